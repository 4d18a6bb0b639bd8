#pragma once
// The BenchPilot backend's path queue: PATH_BEGIN / PATH_APPEND / PATH_STATUS,
// PATH_HOLD / RESUME / CLEAR and the path events (docs/protocol.md, "Path queue"), all
// through BenchPilotClient::request. Reached as BenchPilotClient::paths().
#include "device/client/path_client.h"

#include <QPointer>

namespace dev {

class BenchPilotClient;
struct DeviceEvent;

class ProtocolPathClient : public PathClient {
    Q_OBJECT
public:
    explicit ProtocolPathClient(BenchPilotClient* client, QObject* parent = nullptr);

    bool available() const override;
    int maxSegmentsPerAppend() const override { return dev::proto::kMaxPathSegmentsPerAppend; }
    motion::path::PathLimits limits() const override;
    void refreshLimits(Callback done = {}) override;
    void begin(quint32 firstIndex, Reply done) override;
    void append(quint32 firstIndex, const std::vector<motion::path::Segment>& segments, bool start, bool last,
                Reply done) override;
    void queryStatus(Reply done) override;
    void hold(Callback done = {}) override;
    void resume(Callback done = {}) override;
    void clear(Callback done = {}) override;

private:
    void onEvent(const DeviceEvent& e);
    std::function<void(const std::optional<RequestError>&, const dev::proto::Bytes&)> statusReply(Reply done);
    static PathQueueState fromWire(const dev::proto::PathStatusReply& s);

    QPointer<BenchPilotClient> m_client;
    PathQueueState m_last;
    bool m_haveLimits = false;
};

} // namespace dev
