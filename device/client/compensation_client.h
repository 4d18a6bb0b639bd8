#pragma once
// An instrument's own axis error compensation (docs/accuracy.md), in axis units: upload an
// axis's compensation (an error polynomial or a table of up to 256 points, plus a
// backlash: motion::metrology::CompensationModel), read it back, enable or disable it
// and keep it for power-up. Reached as Instrument::compensation(), nullptr on a
// backend without it (Capability::Compensation says why); the BenchPilot backend's
// implementation is device/backends/benchpilot/protocol_compensation_client.h.
//
// Positions are the axis's home coordinates (what it reads after homing, before any
// set-zero): measure and compensate on a homed axis. Enabling or disabling does not
// move the axis; the position it reports shifts by the correction.
#include "device/client/instrument.h"
#include "motion/metrology/compensation/compensation_model.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

namespace dev {

struct AxisCompensation {
    int axis = -1;
    std::optional<motion::metrology::CompensationModel> model;  ///< none uploaded
    bool enabled = false;   ///< the operator enabled it
    bool applied = false;   ///< enabled and the axis is homed: targets are being compensated now
    bool saved = false;     ///< the device powers up with this compensation and this enabled state
};

class CompensationClient : public QObject {
    Q_OBJECT
public:
    explicit CompensationClient(Instrument* instrument, QObject* parent = nullptr) : QObject(parent), m_instrument(instrument) {}
    Instrument* instrument() const { return m_instrument; }

    /// Axes that can carry a compensation (the linear ones).
    virtual QVector<int> compensableAxes() const = 0;

    using Callback = Instrument::Callback;
    using ReadDone = std::function<void(const std::optional<RequestError>&, const AxisCompensation&)>;
    using Progress = std::function<void(int sent, int total)>;

    /// Uploads `model` (its `axis` letter is ignored: `axis` says where it goes). It is
    /// checked first as the device would (motion::metrology::validate) and refused with
    /// the reason; the device installs it disabled once the last part has arrived.
    virtual void upload(int axis, const motion::metrology::CompensationModel& model, Callback done, Progress progress = {}) = 0;
    /// What the device holds for the axis, read back in full.
    virtual void read(int axis, ReadDone done) = 0;
    /// Enables or disables the axis's compensation; `keepForPowerUp` also saves it and
    /// this state to the device's flash.
    virtual void setEnabled(int axis, bool enabled, bool keepForPowerUp, Callback done = {}) = 0;

signals:
    /// The device changed an axis's compensation (installed, enabled, disabled, saved); text says how.
    void changed(int axis, const QString& text);

private:
    QPointer<Instrument> m_instrument;
};

} // namespace dev
