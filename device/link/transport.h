#pragma once
#include "motion/message.h"

#include <QByteArray>

#include <QObject>
#include <QString>

namespace dev {

/// A byte pipe to an instrument. Opening is asynchronous: `opened()` or
/// `failed()` follows `open()`; open() on an open transport just says `opened()`
/// again. A transport that goes away under load (cable pulled, simulator gone)
/// emits `lost()` once and is closed afterwards.
class Transport : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~Transport() override = default;

    virtual void open() = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    virtual void write(const QByteArray& bytes) = 0;
    /// What a person would call this link: "/dev/ttyUSB0 @ 115200 baud", "simulated stage".
    virtual QString describe() const = 0;

signals:
    void opened();
    void failed(const motion::msg::Message& reason);  ///< link.* (docs/wording.md)
    void lost(const motion::msg::Message& reason);
    void bytesReceived(const QByteArray& bytes);
    /// The far end opened the line: on a device's end, a host opened the port (a board wired to
    /// reset on DTR restarts then). Emitted before any byte the host sends after opening; only
    /// by transports that can tell (the loopback pair, benchpilot-sim's pty).
    void peerOpened();
};

} // namespace dev
