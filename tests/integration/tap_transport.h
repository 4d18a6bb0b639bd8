#pragma once
// A transport that passes everything through to another one and lets a test
// act at the moment the client writes a frame of a given type, e.g. to switch
// the loopback's fault injection on for exactly one request's bytes.
#include "device/link/transport.h"
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages.h"

#include <functional>
#include <vector>

namespace itest {

/// Frame types found in a chunk of wire bytes (whole frames, as the client writes them).
inline std::vector<dev::proto::Frame> framesIn(const QByteArray& bytes)
{
    dev::proto::FrameDecoder d;
    std::vector<dev::proto::Frame> out;
    d.feed(reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size()), out);
    return out;
}

inline bool containsFrame(const QByteArray& bytes, dev::proto::MsgType type)
{
    for (const auto& f : framesIn(bytes))
        if (f.type == static_cast<std::uint8_t>(type))
            return true;
    return false;
}

class TapTransport final : public dev::Transport {
public:
    explicit TapTransport(dev::Transport* inner, QObject* parent = nullptr) : dev::Transport(parent), m_inner(inner)
    {
        connect(inner, &dev::Transport::opened, this, &dev::Transport::opened);
        connect(inner, &dev::Transport::failed, this, &dev::Transport::failed);
        connect(inner, &dev::Transport::lost, this, &dev::Transport::lost);
        connect(inner, &dev::Transport::bytesReceived, this, &TapTransport::received);
    }

    void open() override { m_inner->open(); }
    void close() override { m_inner->close(); }
    bool isOpen() const override { return m_inner->isOpen(); }
    QString describe() const override { return m_inner->describe(); }
    void write(const QByteArray& bytes) override
    {
        if (beforeWrite)
            beforeWrite(bytes);
        m_inner->write(bytes);
        if (afterWrite)
            afterWrite(bytes);
    }

    /// Called with each write's bytes just before / just after they go to the inner transport.
    std::function<void(const QByteArray&)> beforeWrite, afterWrite;
    /// When set, each whole frame from the device is offered to it first and is lost
    /// on the line when it answers true (a frame cut by a read boundary waits for its end).
    std::function<bool(const dev::proto::Frame&)> dropReceived;

private:
    void received(const QByteArray& bytes)
    {
        if (!dropReceived) {
            emit bytesReceived(bytes);
            return;
        }
        std::vector<dev::proto::Frame> frames;
        m_decoder.feed(reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size()), frames);
        std::vector<std::uint8_t> out;
        for (const auto& f : frames)
            if (!dropReceived(f))
                dev::proto::encodeFrame(f, out);
        if (!out.empty())
            emit bytesReceived(QByteArray(reinterpret_cast<const char*>(out.data()), static_cast<int>(out.size())));
    }

    dev::Transport* m_inner;
    dev::proto::FrameDecoder m_decoder;
};

} // namespace itest
