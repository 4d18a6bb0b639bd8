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

std::string instrumentTerm(dev::proto::DeviceKind kind)
{
    return kind == dev::proto::DeviceKind::Stage ? "instrument.stage" : "instrument.analyzer";
}

motion::msg::Message Instrument::whyNot(Capability c) const
{
    if (!isReady()) {
        // Before its first identification a backend does not know what it drives yet.
        if (identity().axes.isEmpty())
            return motion::msg::make(kNotConnectedId);
        return motion::msg::make(kNotConnectedId, {motion::msg::term("instrument", instrumentTerm(identity().kind))});
    }
    if (capabilities().testFlag(c))
        return {};
    return missingReason(c);
}

motion::msg::Message Instrument::missingReason(Capability c) const
{
    const DeviceIdentity& id = identity();
    return motion::msg::make(missingId(c), {motion::msg::term("instrument", instrumentTerm(id.kind)),
                                    motion::msg::verbatim("family", id.family.toStdString())});
}

void Instrument::unlock(Callback done)
{
    refuse(done, RequestError::Kind::Invalid, motion::msg::make("request.no_alarm_lock"));
}

void Instrument::archMove(const ArchMove&, Callback done)
{
    // A decorator that passes the capability on but not the request lands here with the
    // capability present, where whyNot() has nothing to say: the refusal still names it.
    motion::msg::Message why = whyNot(Capability::ArchedMove);
    if (why.empty())
        why = Instrument::missingReason(Capability::ArchedMove);
    refuse(done, RequestError::Kind::Invalid, why);
}

void Instrument::refuse(const Callback& done, RequestError::Kind kind, const motion::msg::Message& message)
{
    RequestError e;
    e.kind = kind;
    e.message = message;
    emit requestFailed(e);
    if (done)
        done(e);
}

} // namespace dev
