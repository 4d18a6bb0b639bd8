#include "device/backends/benchpilot/protocol_compensation_client.h"

#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/protocol/messages_compensation.h"

#include <cmath>

namespace dev {

using motion::metrology::CompensationModel;

namespace {

RequestError compensationInvalid(const motion::msg::Message& why)
{
    RequestError e;
    e.kind = RequestError::Kind::Invalid;
    e.message = why;
    return e;
}

std::int32_t compNm(double mm) { return static_cast<std::int32_t>(std::llround(mm * 1e6)); }
std::int32_t nmFromUm(double um) { return static_cast<std::int32_t>(std::llround(um * 1e3)); }

} // namespace

/// An upload in progress: the parts still to send.
struct ProtocolCompensationClient::Upload {
    int axis = 0;
    dev::proto::CompUploadRequest header;
    std::vector<dev::proto::CompPoint> points;
    std::size_t next = 0;
    Callback done;
    Progress progress;
};

ProtocolCompensationClient::ProtocolCompensationClient(BenchPilotClient* client, QObject* parent)
    : CompensationClient(client, parent), m_client(client)
{
    connect(client, &BenchPilotClient::eventReceived, this, [this](const DeviceEvent& e) {
        if (e.kind == dev::proto::kEvCompChanged)
            emit changed(e.axis, e.text);
    });
}

QVector<int> ProtocolCompensationClient::compensableAxes() const
{
    QVector<int> out;
    if (!m_client || !m_client->hasProtocolCapability(dev::proto::CapCompensation))
        return out;
    const auto& axes = m_client->identity().axes;
    for (int i = 0; i < axes.size(); ++i)
        if (axes[i].unit == dev::proto::AxisUnit::Millimetre)
            out.push_back(i);
    return out;
}

bool ProtocolCompensationClient::checkAxis(int axis, const Callback& done)
{
    if (m_client && compensableAxes().contains(axis))
        return true;
    if (done)
        done(compensationInvalid(m_client && m_client->hasProtocolCapability(dev::proto::CapCompensation)
                                     ? motion::msg::make("compensation.axis_not_compensable", {motion::msg::integer("axis", axis, motion::msg::Unit::None)})
                                     : motion::msg::make("compensation.not_supported")));
    return false;
}

void ProtocolCompensationClient::upload(int axis, const CompensationModel& model, Callback done, Progress progress)
{
    if (!checkAxis(axis, done))
        return;
    CompensationModel m = model;
    m.axis = QString(m_client->identity().axes[axis].letter).toStdString();
    for (const auto& p : motion::metrology::validate(m))
        if (p.isError()) {
            if (done)
                done(compensationInvalid(motion::msg::make("compensation.model_invalid", {motion::msg::verbatim("field", p.path), motion::msg::nested("detail", p.message)})));
            return;
        }
    auto u = std::make_shared<Upload>();
    u->axis = axis;
    u->done = std::move(done);
    u->progress = std::move(progress);
    dev::proto::CompUploadRequest& h = u->header;
    h.axis = static_cast<std::uint8_t>(axis);
    h.backlash = m.perDirection ? 0 : nmFromUm(m.backlashUm);
    if (m.kind == CompensationModel::Kind::Polynomial) {
        h.kind = dev::proto::CompKind::Polynomial;
        h.coefficients = m.polynomial.coefficientsUm;
        h.total = static_cast<std::uint16_t>(h.coefficients.size());
        h.validFrom = compNm(m.validFromMm);
        h.validTo = compNm(m.validToMm);
    } else {
        h.kind = m.perDirection ? dev::proto::CompKind::TablePerDirection : dev::proto::CompKind::Table;
        for (const auto& p : m.table)
            u->points.push_back({compNm(p.nominalMm), nmFromUm(p.correctionUpUm), nmFromUm(m.perDirection ? p.correctionDownUm : p.correctionUpUm)});
        h.total = static_cast<std::uint16_t>(u->points.size());
    }
    sendPart(u);
}

void ProtocolCompensationClient::sendPart(std::shared_ptr<Upload> u)
{
    dev::proto::CompUploadRequest r = u->header;
    r.first = static_cast<std::uint16_t>(u->next);
    if (r.kind != dev::proto::CompKind::Polynomial) {
        const std::size_t count = std::min<std::size_t>(dev::proto::kMaxCompPointsPerFrame, u->points.size() - u->next);
        r.points.assign(u->points.begin() + static_cast<std::ptrdiff_t>(u->next),
                        u->points.begin() + static_cast<std::ptrdiff_t>(u->next + count));
    }
    const QPointer<ProtocolCompensationClient> self(this);
    m_client->request(
        dev::proto::kCompUpload, dev::proto::encode(r),
        [self, u](const std::optional<RequestError>& e, const dev::proto::Bytes& payload) {
            if (!self)
                return;
            if (e) {
                if (u->done)
                    u->done(e);
                return;
            }
            const auto reply = dev::proto::decodeCompUploadReply(payload);
            if (!reply) {
                if (u->done)
                    u->done(compensationInvalid(motion::msg::make("compensation.upload_unreadable")));
                return;
            }
            u->next = reply->received;
            if (u->progress)
                u->progress(reply->received, u->header.total);
            if (reply->installed) {
                if (u->done)
                    u->done(std::nullopt);
                return;
            }
            if (u->header.kind == dev::proto::CompKind::Polynomial || u->next >= u->points.size()) {
                if (u->done)
                    u->done(compensationInvalid(motion::msg::make("compensation.not_installed")));
                return;
            }
            self->sendPart(u);
        },
        "compensation.request.upload");
}

void ProtocolCompensationClient::read(int axis, ReadDone done)
{
    if (!checkAxis(axis, [&done, axis](const std::optional<RequestError>& e) {
            AxisCompensation c;
            c.axis = axis;
            done(e, c);
        }))
        return;
    auto into = std::make_shared<AxisCompensation>();
    into->axis = axis;
    readPart(into, 0, std::move(done));
}

void ProtocolCompensationClient::readPart(std::shared_ptr<AxisCompensation> into, int first, ReadDone done)
{
    const int axis = into->axis;
    const dev::proto::CompGetRequest q{static_cast<std::uint8_t>(axis), static_cast<std::uint16_t>(first), dev::proto::kMaxCompPointsPerFrame};
    const QPointer<ProtocolCompensationClient> self(this);
    m_client->request(
        dev::proto::kCompGet, dev::proto::encode(q),
        [self, into, first, done](const std::optional<RequestError>& e, const dev::proto::Bytes& payload) {
            if (!self)
                return;
            if (e)
                return done(e, *into);
            const auto r = dev::proto::decodeCompGetReply(payload);
            if (!r || r->axis != into->axis)
                return done(compensationInvalid(motion::msg::make("compensation.read_unreadable")), *into);
            into->enabled = r->flags & dev::proto::CompEnabled;
            into->applied = r->flags & dev::proto::CompApplied;
            into->saved = r->flags & dev::proto::CompSaved;
            if (r->kind == dev::proto::CompKind::None) {
                into->model.reset();
                return done(std::nullopt, *into);
            }
            if (first == 0) {
                CompensationModel m;
                m.axis = QString(self->m_client->identity().axes[into->axis].letter).toStdString();
                m.backlashUm = r->backlash / 1e3;
                if (r->kind == dev::proto::CompKind::Polynomial) {
                    m.kind = CompensationModel::Kind::Polynomial;
                    m.polynomial.coefficientsUm = r->coefficients;
                    m.validFromMm = r->validFrom / 1e6;
                    m.validToMm = r->validTo / 1e6;
                } else {
                    m.kind = CompensationModel::Kind::Table;
                    m.perDirection = r->kind == dev::proto::CompKind::TablePerDirection;
                }
                into->model = m;
            }
            if (r->kind == dev::proto::CompKind::Polynomial)
                return done(std::nullopt, *into);
            for (const auto& p : r->points)
                into->model->table.push_back({p.nominal / 1e6, p.correctionUp / 1e3, p.correctionDown / 1e3});
            const int next = first + static_cast<int>(r->points.size());
            if (next >= r->total || r->points.empty())
                return done(std::nullopt, *into);
            self->readPart(into, next, done);
        },
        "compensation.request.read");
}

void ProtocolCompensationClient::setEnabled(int axis, bool enabled, bool keepForPowerUp, Callback done)
{
    if (!checkAxis(axis, done))
        return;
    dev::proto::CompEnableRequest r;
    r.axisMask = static_cast<std::uint8_t>(1u << axis);
    r.flags = static_cast<std::uint8_t>((enabled ? dev::proto::CompEnableOn : 0) | (keepForPowerUp ? dev::proto::CompEnableSave : 0));
    m_client->request(
        dev::proto::kCompEnable, dev::proto::encode(r),
        [done](const std::optional<RequestError>& e, const dev::proto::Bytes&) {
            if (done)
                done(e);
        },
        enabled ? "compensation.request.enable" : "compensation.request.disable");
}

} // namespace dev
