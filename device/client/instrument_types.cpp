#include "device/client/instrument_types.h"

#include <QCoreApplication>

namespace dev {

QString linkStateName(LinkState s)
{
    switch (s) {
    case LinkState::Disconnected: return QCoreApplication::translate("dev", "disconnected");
    case LinkState::Connecting: return QCoreApplication::translate("dev", "connecting");
    case LinkState::Identified: return QCoreApplication::translate("dev", "identified");
    case LinkState::Ready: return QCoreApplication::translate("dev", "ready");
    case LinkState::Lost: return QCoreApplication::translate("dev", "link lost");
    }
    return {};
}

QString AxisDescriptor::unitName() const
{
    return unit == proto::AxisUnit::Microlitre ? QStringLiteral("µL") : QStringLiteral("mm");
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
    return kind == proto::DeviceKind::Stage ? QCoreApplication::translate("dev", "stage")
                                            : QCoreApplication::translate("dev", "analyzer");
}

bool InstrumentStatus::anyMoving() const
{
    for (const auto& a : axes)
        if (a.moving)
            return true;
    return false;
}

} // namespace dev
