#include "device/client/instrument_types.h"

namespace dev {

const char* linkStateTerm(LinkState s)
{
    switch (s) {
    case LinkState::Disconnected: return "link.state.disconnected";
    case LinkState::Connecting: return "link.state.connecting";
    case LinkState::Identified: return "link.state.identified";
    case LinkState::Ready: return "link.state.ready";
    case LinkState::Lost: return "link.state.lost";
    }
    return "link.state.disconnected";
}

motion::msg::Arg eventDetail(const DeviceEvent& e, const char* name)
{
    if (e.worded || !e.detail.empty())
        return motion::msg::nested(name, e.detail);
    return motion::msg::verbatim(name, e.text.toStdString());
}

const char* linkStateKey(LinkState s)
{
    // The term's last word: "link.state.ready" → "ready".
    return linkStateTerm(s) + sizeof("link.state.") - 1;
}

QString AxisDescriptor::unitName() const
{
    return unit == dev::proto::AxisUnit::Microlitre ? QStringLiteral("µL") : QStringLiteral("mm");
}

int DeviceIdentity::axisIndex(QChar letter) const
{
    for (int i = 0; i < axes.size(); ++i)
        if (axes[i].letter.toUpper() == letter.toUpper())
            return i;
    return -1;
}

QString DeviceIdentity::kindName() const
{
    return kind == dev::proto::DeviceKind::Stage ? QStringLiteral("stage") : QStringLiteral("analyzer");
}

bool InstrumentStatus::anyMoving() const
{
    for (const auto& a : axes)
        if (a.moving)
            return true;
    return false;
}

} // namespace dev
