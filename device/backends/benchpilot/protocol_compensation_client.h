#pragma once
// The BenchPilot backend's axis error compensation: COMP_UPLOAD in parts of up to 80
// table points, COMP_GET until the whole table is read back, COMP_ENABLE
// (docs/protocol.md, "Compensation"), all through BenchPilotClient::request. Reached as
// BenchPilotClient::compensation().
#include "device/client/compensation_client.h"

#include <QPointer>

#include <memory>

namespace dev {

class BenchPilotClient;

class ProtocolCompensationClient : public CompensationClient {
    Q_OBJECT
public:
    explicit ProtocolCompensationClient(BenchPilotClient* client, QObject* parent = nullptr);

    QVector<int> compensableAxes() const override;
    void upload(int axis, const motion::metrology::CompensationModel& model, Callback done, Progress progress = {}) override;
    void read(int axis, ReadDone done) override;
    void setEnabled(int axis, bool enabled, bool keepForPowerUp, Callback done = {}) override;

private:
    struct Upload;
    void sendPart(std::shared_ptr<Upload> u);
    void readPart(std::shared_ptr<AxisCompensation> into, int first, ReadDone done);
    bool checkAxis(int axis, const Callback& done);

    QPointer<BenchPilotClient> m_client;
};

} // namespace dev
