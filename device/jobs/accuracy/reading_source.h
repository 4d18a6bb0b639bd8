#pragma once
// Where an accuracy run's readings come from, behind one interface:
//
//  - the instrument's own readback (encoder on the analyzer, grating on the stage),
//  - an external gauge on a serial port of its own (gauge_source.h),
//  - a laser interferometer whose own capture is imported after the run
//    (interferometer_source.h: the run notes each stop's time; the readings arrive
//    with the import),
//  - a person typing what a dial indicator shows (manual_source.h),
//  - the microscope's camera reading a glass line scale (device/camera/scale_reading_source.h).
//
// The runner moves the axis, waits for it to settle, and then asks the source for
// the reading at that stop. A source answers every take() exactly once, unless
// cancel() was called first.
#include "motion/message.h"
#include "motion/metrology/readings.h"

#include <QObject>
#include <QString>

#include <functional>
#include <vector>

namespace dev {
struct DeviceEvent;
}

namespace dev::jobs {

enum class ReadingKind { Readback, Gauge, Interferometer, Manual, Camera };
/// "readback", "gauge", "interferometer", "manual", "camera": the result file's "reference".
const char* readingKindName(ReadingKind k);
/// The term that names the kind for a person: accuracy.source_kind.* (ui::words::term).
const char* readingKindTerm(ReadingKind k);

/// One stop of a run, as a source needs to know it.
struct StopContext {
    int index = 0;                       ///< 0-based, in the run's order
    int total = 0;                       ///< stops in the run
    int cycle = 1;
    motion::metrology::Direction direction = motion::metrology::Direction::Up;
    std::vector<int> axes;               ///< instrument axes read here: one, or X and Y for a linked test
    std::vector<QChar> letters;          ///< their letters
    std::vector<double> targetsMm;       ///< one per axis
    quint64 deviceTimeUs = 0;            ///< device clock when the axis had settled
    double runTimeS = 0;                 ///< seconds since the run (or its resumption) began, on the device clock
};

struct TakeResult {
    std::vector<double> valuesMm;        ///< one per axis; empty when deferred or failed
    bool deferred = false;               ///< the reading comes later (an interferometer's import)
    motion::msg::Message problem;                ///< the reading failed: which port, what was sent
};

class ReadingSource : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~ReadingSource() override = default;

    virtual ReadingKind kind() const = 0;
    /// For a person and the report (accuracy.source.*): "gauge on /dev/ttyUSB1",
    /// "the stage's grating (readback)".
    virtual motion::msg::Message describe() const = 0;
    /// How many axes one reading can cover (a gauge reads one).
    virtual int maxAxes() const { return 1; }

    using OpenDone = std::function<void(const motion::msg::Message& problem)>;  ///< empty: ready
    /// Makes the source ready before the first stop (opens a port).
    virtual void open(OpenDone done) { done({}); }
    virtual void close() {}

    using TakeDone = std::function<void(const TakeResult&)>;
    /// The reading at a stop the axes have settled at.
    virtual void take(const StopContext& stop, TakeDone done) = 0;
    /// Drops a take in progress; its done is never called.
    virtual void cancel() {}
};

} // namespace dev::jobs

Q_DECLARE_METATYPE(dev::jobs::StopContext)
