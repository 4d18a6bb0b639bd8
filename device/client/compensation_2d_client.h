#pragma once
// An XY stage's 2D compensation table kept on the instrument (docs/accuracy.md, "2D
// compensation table"): upload a motion::metrology::CompensationTable2D, enable or
// disable it, keep it for power-up, read its state. Reached as
// Instrument::compensation2d(), nullptr on a backend without it; the BenchPilot
// backend's implementation is device/backends/benchpilot/protocol_compensation_2d_client.h.
//
// Positions are the X and Y axes' home coordinates. Enabling or disabling does not
// move the axes; the positions they report shift by the correction.
#include "device/client/instrument.h"
#include "motion/metrology/grid/compensation_table_2d.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

namespace dev {

struct Compensation2dState {
    bool installed = false;  ///< the instrument holds a table
    bool enabled = false;    ///< the operator enabled it
    bool applied = false;    ///< enabled and X and Y homed: targets are compensated now
    bool saved = false;      ///< the table and its enabled state are the power-up ones
    int columns = 0;
    int rows = 0;
};

class Compensation2dClient : public QObject {
    Q_OBJECT
public:
    explicit Compensation2dClient(QObject* parent = nullptr) : QObject(parent) {}

    /// Whether the instrument can keep a 2D table at all.
    virtual bool available() const = 0;

    using Callback = Instrument::Callback;
    using StateDone = std::function<void(const std::optional<RequestError>&, const Compensation2dState&)>;
    using Progress = std::function<void(int sent, int total)>;

    /// Uploads `table`, checked first as the device would (motion::metrology::validate);
    /// the device installs it disabled once the last part has arrived.
    virtual void upload(const motion::metrology::CompensationTable2D& table, Callback done, Progress progress = {}) = 0;
    /// Enables or disables the table; `keepForPowerUp` also saves it and this state.
    virtual void setEnabled(bool enabled, bool keepForPowerUp, StateDone done) = 0;
    /// What the instrument holds, changing nothing.
    virtual void state(StateDone done) = 0;
};

} // namespace dev
