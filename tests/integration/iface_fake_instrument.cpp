#include "iface_fake_instrument.h"

#include "motion/jerk_limited.h"

#include <QPointer>
#include <QTimer>

#include <cmath>

namespace itest {

dev::Capabilities FakeInstrument::defaultCapabilities()
{
    using C = dev::Capability;
    return C::Homing | C::SetZero | C::MeasuredPosition | C::SoftLimits | C::VelocityJog | C::TriggerOutput | C::MachineLimits;
}

FakeInstrument::FakeInstrument(double accelMmS2, double jerkMmS3, dev::Capabilities capabilities, QObject* parent)
    : dev::Instrument(parent), m_caps(capabilities)
{
    m_identity.kind = dev::proto::DeviceKind::Stage;
    m_identity.family = QStringLiteral("Fake 0.1");
    m_identity.model = QStringLiteral("in-memory stage");
    m_identity.firmware = QStringLiteral("none");
    m_identity.motionProfile = jerkMmS3 > 0 ? dev::proto::MotionProfile::JerkLimited : dev::proto::MotionProfile::Trapezoid;
    for (const char letter : {'X', 'Y'}) {
        dev::AxisDescriptor a;
        a.letter = QLatin1Char(letter);
        a.travelMax = 100;
        a.maxSpeed = 20;
        a.resolution = 0.0005;
        a.maxAccel = accelMmS2;
        a.maxJerk = jerkMmS3;
        a.defaultSpeed = 10;
        m_identity.axes.push_back(a);
    }
}

void FakeInstrument::later(std::function<void()> f)
{
    const QPointer<FakeInstrument> self(this);
    QTimer::singleShot(0, this, [self, f = std::move(f)] {
        if (self)
            f();
    });
}

void FakeInstrument::connectLink()
{
    m_state = dev::LinkState::Connecting;
    emit stateChanged(m_state);
    m_status.axes.resize(m_identity.axes.size());
    m_limits = QVector<dev::SoftLimits>(m_identity.axes.size(), dev::SoftLimits{0, 100});
    m_state = dev::LinkState::Identified;
    emit stateChanged(m_state);
    emit identified(m_identity);
    emit limitsChanged();
    m_state = dev::LinkState::Ready;
    emit stateChanged(m_state);
    emit statusChanged(m_status);
}

void FakeInstrument::disconnectLink()
{
    m_state = dev::LinkState::Disconnected;
    emit stateChanged(m_state);
}

motion::msg::Message FakeInstrument::missingReason(dev::Capability c) const
{
    motion::msg::Message m = Instrument::missingReason(c);
    m.args.push_back(motion::msg::term("because", "capability.because.fake"));
    return m;
}

void FakeInstrument::arrive(const std::vector<int>& axes, double seconds, dev::proto::EventKind kind)
{
    later([this, axes, seconds, kind] {
        m_status.deviceTimeUs += static_cast<quint64>(std::llround(seconds * 1e6)) + 1000;
        for (int a : axes) {
            m_status.axes[a].moving = false;
            dev::DeviceEvent e;
            e.kind = kind;
            e.axis = a;
            e.position = m_status.axes[a].measured;
            e.deviceTimeUs = m_status.deviceTimeUs;
            emit eventReceived(e);
        }
        emit statusChanged(m_status);
    });
}

void FakeInstrument::home(quint8 axisMask, Callback done)
{
    if (!isReady())
        return refuse(done, dev::RequestError::Kind::LinkDown, motion::msg::make("request.instrument_not_connected"));
    std::vector<int> axes;
    for (int a = 0; a < m_status.axes.size(); ++a)
        if (axisMask == 0 || (axisMask & (1u << a))) {
            m_status.axes[a] = dev::AxisReadout{};
            m_status.axes[a].homed = true;
            axes.push_back(a);
        }
    later([done] {
        if (done)
            done(std::nullopt);
    });
    arrive(axes, 0.5, dev::proto::EventKind::HomeDone);
}

void FakeInstrument::move(const QVector<QPair<int, double>>& targets, bool relative, double speed, Callback done)
{
    if (!isReady())
        return refuse(done, dev::RequestError::Kind::LinkDown, motion::msg::make("request.instrument_not_connected"));
    moves.push_back(targets);
    std::vector<int> axes;
    double lengthMm = 0;
    for (const auto& [axis, value] : targets) {
        if (axis < 0 || axis >= m_status.axes.size())
            return refuse(done, dev::RequestError::Kind::Invalid, motion::msg::make("request.move_no_such_axis", {motion::msg::integer("index", axis, motion::msg::Unit::None)}));
        auto& r = m_status.axes[axis];
        const double to = relative ? r.commanded + value : value;
        lengthMm = std::hypot(lengthMm, to - r.commanded);
        r.commanded = r.measured = to;
        r.moving = true;
        axes.push_back(axis);
    }
    const dev::AxisDescriptor& a = m_identity.axes[0];
    const double v = speed > 0 ? std::min(speed, a.maxSpeed) : a.defaultSpeed;
    const auto profile = motion::JerkLimitedProfile::plan(lengthMm, {v, a.maxAccel, a.maxJerk > 0 ? a.maxJerk : 1e9});
    later([done] {
        if (done)
            done(std::nullopt);
    });
    arrive(axes, profile ? profile->duration() : 0.0, dev::proto::EventKind::MotionDone);
}

void FakeInstrument::jogStep(int axis, double delta, double speed, Callback done) { move({{axis, delta}}, true, speed, std::move(done)); }

void FakeInstrument::setJogVelocities(const std::map<int, double>& velocities, Callback done)
{
    jogs.push_back(velocities);
    later([done] {
        if (done)
            done(std::nullopt);
    });
}

void FakeInstrument::stop(quint8, Callback done)
{
    later([done] {
        if (done)
            done(std::nullopt);
    });
}

void FakeInstrument::estop(Callback done)
{
    m_status.estop = true;
    emit statusChanged(m_status);
    later([done] {
        if (done)
            done(std::nullopt);
    });
}

void FakeInstrument::reset(Callback done)
{
    m_status.estop = false;
    emit statusChanged(m_status);
    later([done] {
        if (done)
            done(std::nullopt);
    });
}

void FakeInstrument::setZero(quint8, Callback done)
{
    later([done] {
        if (done)
            done(std::nullopt);
    });
}

void FakeInstrument::setSoftLimits(int axis, double min, double max, Callback done)
{
    if (axis >= 0 && axis < m_limits.size())
        m_limits[axis] = {min, max};
    emit limitsChanged();
    later([done] {
        if (done)
            done(std::nullopt);
    });
}

void FakeInstrument::readStatus(StatusCallback done)
{
    later([this, done] {
        m_status.deviceTimeUs += 1000;
        emit statusChanged(m_status);
        if (done)
            done(std::nullopt, m_status);
    });
}

void FakeInstrument::dwell(double seconds, Callback done)
{
    QTimer::singleShot(static_cast<int>(std::lround(seconds * 1000)), this, [done] {
        if (done)
            done(std::nullopt);
    });
}

void FakeInstrument::pulseTrigger(double widthS, Callback done)
{
    if (!m_caps.testFlag(dev::Capability::TriggerOutput))
        return refuse(done, dev::RequestError::Kind::Invalid, motion::msg::make("request.no_trigger_output"));
    triggerWidthsS.push_back(widthS);
    later([done] {
        if (done)
            done(std::nullopt);
    });
}

void FakeInstrument::subscribe(const QVector<dev::proto::ChannelRef>&, int, SubscribeCallback done)
{
    later([done] {
        if (done)
            done(std::nullopt, {});
    });
}

} // namespace itest
