#include "device/client/instrument.h"

namespace dev {

Instrument::Instrument(QObject* parent) : QObject(parent)
{
    qRegisterMetaType<dev::LinkState>();
    qRegisterMetaType<dev::InstrumentStatus>();
    qRegisterMetaType<dev::DeviceEvent>();
    qRegisterMetaType<dev::RequestError>();
}

Instrument::~Instrument() = default;

std::string instrumentTerm(proto::DeviceKind kind)
{
    return kind == proto::DeviceKind::Stage ? "instrument.stage" : "instrument.analyzer";
}

msg::Message Instrument::whyNot(Capability c) const
{
    if (!isReady()) {
        // Before its first identification a backend does not know what it drives yet.
        if (identity().axes.isEmpty())
            return msg::make(kNotConnectedId);
        return msg::make(kNotConnectedId, {msg::term("instrument", instrumentTerm(identity().kind))});
    }
    if (capabilities().testFlag(c))
        return {};
    return missingReason(c);
}

msg::Message Instrument::missingReason(Capability c) const
{
    const DeviceIdentity& id = identity();
    return msg::make(missingId(c), {msg::term("instrument", instrumentTerm(id.kind)),
                                    msg::verbatim("family", id.family.toStdString())});
}

void Instrument::unlock(Callback done)
{
    refuse(done, RequestError::Kind::Invalid, msg::make("request.no_alarm_lock"));
}

void Instrument::refuse(const Callback& done, RequestError::Kind kind, const msg::Message& message)
{
    RequestError e;
    e.kind = kind;
    e.message = message;
    emit requestFailed(e);
    if (done)
        done(e);
}

} // namespace dev
