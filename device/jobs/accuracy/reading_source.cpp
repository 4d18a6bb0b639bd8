#include "device/jobs/accuracy/reading_source.h"

namespace jobs {

const char* readingKindName(ReadingKind k)
{
    switch (k) {
    case ReadingKind::Readback: return "readback";
    case ReadingKind::Gauge: return "gauge";
    case ReadingKind::Interferometer: return "interferometer";
    case ReadingKind::Manual: return "manual";
    }
    return "readback";
}

} // namespace jobs
