#pragma once
// The simulated controller's axis error compensation (docs/protocol.md,
// "Compensation"): per axis an error polynomial or a table of up to 256 points plus
// a backlash, uploaded in parts, read back, enabled and disabled, and kept for
// power-up when asked (the "flash", NonVolatile below).
//
// An enabled compensation is applied while the axis is homed (its positions are
// home coordinates): every position the trajectory generator asks for is moved by
// the correction for the side it is approached from before the motor or the loop
// sees it (SimAxis::setCompensation), which is how seed 002's controller takes the
// fitted error off each position command, solved exactly instead of in one step.
// Enabling or disabling does not move the axis.
//
// It lives in the machine, not in the host's session: a reconnect (a new HELLO)
// keeps it; a power cycle (a new SimMachine) starts from what was saved.
#include "device/protocol/messages_compensation.h"
#include "motion/metrology/compensation/compensation_model.h"

#include <optional>
#include <vector>

namespace dev::sim {

class SimMachine;

/// What survives a power cycle: per axis the compensation saved and whether it was
/// enabled. Hand it to the next SimMachine (or Firmware) to power up with it.
struct NonVolatile {
    struct Axis {
        std::optional<motion::metrology::CompensationModel> model;
        bool enabled = false;
    };
    std::vector<Axis> axes;
};

class SimCompensation {
public:
    SimCompensation(SimMachine& machine, const NonVolatile& powerUp);

    using Result = std::optional<dev::proto::ErrorReply>;
    Result upload(const dev::proto::CompUploadRequest& r, dev::proto::CompUploadReply& out);
    Result get(const dev::proto::CompGetRequest& r, dev::proto::CompGetReply& out) const;
    Result enable(const dev::proto::CompEnableRequest& r);

    /// Once per tick: attaches an enabled compensation to an axis that is homed and at
    /// rest, detaches one that is disabled or whose homing was lost.
    void reconcile();

    const NonVolatile& flash() const { return m_flash; }
    const std::optional<motion::metrology::CompensationModel>& model(int axis) const;
    bool enabled(int axis) const;
    bool applied(int axis) const;

private:
    struct Staging {
        bool active = false;
        dev::proto::CompKind kind = dev::proto::CompKind::None;
        std::int32_t backlash = 0;
        std::uint16_t total = 0;
        std::vector<dev::proto::CompPoint> points;
    };
    struct Axis {
        std::optional<motion::metrology::CompensationModel> model;
        bool enabled = false;
        bool applied = false;
        bool saved = false;      ///< model and enabled are what the flash holds
        Staging staging;
    };

    Result install(int axis, motion::metrology::CompensationModel model);
    dev::proto::ErrorReply error(dev::proto::ErrorCode code, int axis, std::int32_t value, const std::string& text) const;

    SimMachine& m_m;
    std::vector<Axis> m_axes;
    NonVolatile m_flash;
};

} // namespace dev::sim
