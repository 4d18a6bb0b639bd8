#include "device/jobs/accuracy/reading_source.h"

#include "device/client/instrument_types.h"

namespace dev::jobs {

const char* readingKindName(ReadingKind k)
{
    switch (k) {
    case ReadingKind::Readback: return "readback";
    case ReadingKind::Gauge: return "gauge";
    case ReadingKind::Interferometer: return "interferometer";
    case ReadingKind::Manual: return "manual";
    case ReadingKind::Camera: return "camera";
    }
    return "readback";
}

const char* readingKindTerm(ReadingKind k)
{
    switch (k) {
    case ReadingKind::Readback: return "accuracy.source_kind.readback";
    case ReadingKind::Gauge: return "accuracy.source_kind.gauge";
    case ReadingKind::Interferometer: return "accuracy.source_kind.interferometer";
    case ReadingKind::Manual: return "accuracy.source_kind.manual";
    case ReadingKind::Camera: return "accuracy.source_kind.camera";
    }
    return "accuracy.source_kind.readback";
}

} // namespace dev::jobs
