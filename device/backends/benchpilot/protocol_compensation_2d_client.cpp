#include "device/backends/benchpilot/protocol_compensation_2d_client.h"

#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/protocol/messages_compensation_2d.h"

#include <cmath>

namespace dev {

using motion::metrology::CompensationTable2D;

namespace {

RequestError invalid2d(const motion::msg::Message& why)
{
    RequestError e;
    e.kind = RequestError::Kind::Invalid;
    e.message = why;
    return e;
}

std::int32_t nmOfMm(double mm) { return static_cast<std::int32_t>(std::llround(mm * 1e6)); }
std::int32_t nmOfUm(double um) { return static_cast<std::int32_t>(std::llround(um * 1e3)); }

Compensation2dState stateOf(const dev::proto::Comp2dEnableReply& r)
{
    Compensation2dState s;
    s.installed = r.state & dev::proto::Comp2dInstalled;
    s.enabled = r.state & dev::proto::Comp2dEnabled;
    s.applied = r.state & dev::proto::Comp2dApplied;
    s.saved = r.state & dev::proto::Comp2dSaved;
    s.columns = r.columns;
    s.rows = r.rows;
    return s;
}

} // namespace

/// An upload in progress: the parts still to send.
struct ProtocolCompensation2dClient::Upload {
    dev::proto::Comp2dUploadRequest header;
    std::vector<dev::proto::Comp2dNode> nodes;
    std::size_t next = 0;
    Callback done;
    Progress progress;
};

ProtocolCompensation2dClient::ProtocolCompensation2dClient(BenchPilotClient* client, QObject* parent)
    : Compensation2dClient(parent), m_client(client)
{
}

bool ProtocolCompensation2dClient::available() const
{
    return m_client && m_client->hasProtocolCapability(dev::proto::CapCompensation2d);
}

bool ProtocolCompensation2dClient::check(const std::function<void(const std::optional<RequestError>&)>& refuse) const
{
    if (available())
        return true;
    if (refuse)
        refuse(invalid2d(motion::msg::make("compensation2d.not_supported")));
    return false;
}

void ProtocolCompensation2dClient::upload(const CompensationTable2D& table, Callback done, Progress progress)
{
    if (!check(done))
        return;
    for (const auto& p : motion::metrology::validate(table))
        if (p.isError()) {
            if (done)
                done(invalid2d(motion::msg::make("compensation.model_invalid", {motion::msg::verbatim("field", p.path), motion::msg::nested("detail", p.message)})));
            return;
        }
    auto u = std::make_shared<Upload>();
    u->done = std::move(done);
    u->progress = std::move(progress);
    dev::proto::Comp2dUploadRequest& h = u->header;
    h.columns = static_cast<std::uint8_t>(table.columns);
    h.rows = static_cast<std::uint8_t>(table.rows);
    h.originX = nmOfMm(table.originXMm);
    h.originY = nmOfMm(table.originYMm);
    h.pitchX = nmOfMm(table.pitchXMm);
    h.pitchY = nmOfMm(table.pitchYMm);
    for (std::size_t k = 0; k < table.correctionXUm.size(); ++k)
        u->nodes.push_back({nmOfUm(table.correctionXUm[k]), nmOfUm(table.correctionYUm[k])});
    sendPart(u);
}

void ProtocolCompensation2dClient::sendPart(std::shared_ptr<Upload> u)
{
    dev::proto::Comp2dUploadRequest r = u->header;
    r.first = static_cast<std::uint16_t>(u->next);
    const std::size_t count = std::min<std::size_t>(dev::proto::kMaxComp2dNodesPerFrame, u->nodes.size() - u->next);
    r.nodes.assign(u->nodes.begin() + static_cast<std::ptrdiff_t>(u->next),
                   u->nodes.begin() + static_cast<std::ptrdiff_t>(u->next + count));
    const QPointer<ProtocolCompensation2dClient> self(this);
    m_client->request(
        dev::proto::kComp2dUpload, dev::proto::encode(r),
        [self, u](const std::optional<RequestError>& e, const dev::proto::Bytes& payload) {
            if (!self)
                return;
            if (e) {
                if (u->done)
                    u->done(e);
                return;
            }
            const auto reply = dev::proto::decodeComp2dUploadReply(payload);
            if (!reply) {
                if (u->done)
                    u->done(invalid2d(motion::msg::make("compensation2d.upload_unreadable")));
                return;
            }
            u->next = reply->received;
            if (u->progress)
                u->progress(reply->received, static_cast<int>(u->nodes.size()));
            if (reply->installed) {
                if (u->done)
                    u->done(std::nullopt);
                return;
            }
            if (u->next >= u->nodes.size()) {
                if (u->done)
                    u->done(invalid2d(motion::msg::make("compensation.not_installed")));
                return;
            }
            self->sendPart(u);
        },
        "compensation2d.request.upload");
}

void ProtocolCompensation2dClient::sendEnable(std::uint8_t flags, const char* what, StateDone done)
{
    m_client->request(
        dev::proto::kComp2dEnable, dev::proto::encode(dev::proto::Comp2dEnableRequest{flags}),
        [done](const std::optional<RequestError>& e, const dev::proto::Bytes& payload) {
            if (!done)
                return;
            if (e)
                return done(e, {});
            const auto r = dev::proto::decodeComp2dEnableReply(payload);
            if (!r)
                return done(invalid2d(motion::msg::make("compensation2d.state_unreadable")), {});
            done(std::nullopt, stateOf(*r));
        },
        what);
}

void ProtocolCompensation2dClient::setEnabled(bool enabled, bool keepForPowerUp, StateDone done)
{
    if (!check([&done](const std::optional<RequestError>& e) {
            if (done)
                done(e, {});
        }))
        return;
    const auto flags = static_cast<std::uint8_t>((enabled ? dev::proto::Comp2dEnableOn : 0) | (keepForPowerUp ? dev::proto::Comp2dEnableSave : 0));
    sendEnable(flags, enabled ? "compensation2d.request.enable" : "compensation2d.request.disable", std::move(done));
}

void ProtocolCompensation2dClient::state(StateDone done)
{
    if (!check([&done](const std::optional<RequestError>& e) {
            if (done)
                done(e, {});
        }))
        return;
    sendEnable(dev::proto::Comp2dEnableQuery, "compensation2d.request.state", std::move(done));
}

} // namespace dev
