#pragma once
// Common interface of every motion profile (seed S-curve, trapezoid, exponential staircase,
// jerk-limited). The simulator, the GUI plots and the CLI all sample a move through it, so a new
// profile kind needs no change in any of them.

namespace motion {

/// One sampled instant of a move. Every field's sign follows the move's direction: a move of
/// -10 mm has s running from 0 to -10 and v <= 0 throughout.
struct ProfileSample {
    double t = 0, s = 0, v = 0, a = 0, j = 0;  ///< s (mm), v (mm/s), a (mm/s²), j (mm/s³) at time t (s); sign follows the move's direction
};

/// A rest-to-rest move along one coordinate, starting at s = 0 and t = 0.
/// Implementations are small value types (no heap) so that planners can return them by value
/// and the simulator can keep one per axis in its realtime loop.
class Profile {
public:
    virtual ~Profile() = default;
    virtual double duration() const = 0;            ///< s
    virtual double distance() const = 0;            ///< mm, signed
    virtual ProfileSample at(double tS) const = 0;  ///< clamps t to [0, duration]: before start s=0, after end s=distance, v=a=j=0

protected:
    Profile() = default;
    Profile(const Profile&) = default;
    Profile& operator=(const Profile&) = default;
    Profile(Profile&&) = default;
    Profile& operator=(Profile&&) = default;
};

}  // namespace motion
