#pragma once
// The BenchPilot backend's 2D compensation table: COMP2D_UPLOAD in parts of up to 96
// nodes, COMP2D_ENABLE to enable, disable, keep or only report (docs/protocol.md,
// "2D compensation"), all through BenchPilotClient::request. Reached as
// BenchPilotClient::compensation2d().
#include "device/client/compensation_2d_client.h"

#include <QPointer>

#include <memory>

namespace dev {

class BenchPilotClient;

class ProtocolCompensation2dClient : public Compensation2dClient {
    Q_OBJECT
public:
    explicit ProtocolCompensation2dClient(BenchPilotClient* client, QObject* parent = nullptr);

    bool available() const override;
    void upload(const motion::metrology::CompensationTable2D& table, Callback done, Progress progress = {}) override;
    void setEnabled(bool enabled, bool keepForPowerUp, StateDone done) override;
    void state(StateDone done) override;

private:
    struct Upload;
    void sendPart(std::shared_ptr<Upload> u);
    void sendEnable(std::uint8_t flags, const char* what, StateDone done);
    bool check(const std::function<void(const std::optional<RequestError>&)>& refuse) const;

    QPointer<BenchPilotClient> m_client;
};

} // namespace dev
