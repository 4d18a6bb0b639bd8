#pragma once
// JSON-RPC 2.0 as the scripting API speaks it (docs/api.md): the error codes, one
// request line read into a call (or the error that answers it), and the messages
// written back. Plain Qt Core: the fuzz target (tests/fuzz/api/) drives it alone.
#include <QByteArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include <functional>

namespace app::api {

/// The error codes. −32768…−32000 are JSON-RPC's own; the application's are
/// −32001…−32099, documented in docs/api.md with what a client should do.
namespace code {
constexpr int kParseError = -32700;      ///< the line is not JSON
constexpr int kInvalidRequest = -32600;  ///< JSON, but not a JSON-RPC 2.0 request (or a line over 1 MiB)
constexpr int kMethodNotFound = -32601;
constexpr int kInvalidParams = -32602;   ///< names the field and what was wrong
constexpr int kInternalError = -32603;
// Refused by the device or the motion failed (the CLI's exit code 2).
constexpr int kRefused = -32001;         ///< anything else the device refused, or a motion that failed
constexpr int kNotHomed = -32002;
constexpr int kSoftLimit = -32003;
constexpr int kEStopLatched = -32004;
constexpr int kBusy = -32005;            ///< the instrument runs a job someone else started
constexpr int kLinkTrouble = -32010;     ///< the CLI's exit code 3: no instrument, link lost, no answer
constexpr int kNotInControl = -32020;    ///< needs the control lease (control.acquire), or it was taken back
constexpr int kTooManyCalls = -32030;    ///< more calls in flight than a client may have; retry after one ends
constexpr int kCancelled = -32040;       ///< call.cancel or the server shutting down interrupted it
} // namespace code

/// Lines longer than this (without the newline) are refused.
constexpr int kMaxLineBytes = 1024 * 1024;

/// One request line, read.
struct Request {
    enum class Kind {
        Call,          ///< has an id: answer it
        Notification,  ///< no id: never answered (JSON-RPC), even when it fails
        Invalid,       ///< answer `error` with `id` (null when it could not be read)
    };
    Kind kind = Kind::Invalid;
    QJsonValue id;        ///< number or string; null for an invalid request without a readable id
    QString method;
    QJsonObject params;   ///< by-name params; an absent "params" is {}
    int errorCode = 0;
    QString errorMessage;
};

/// Reads one line (without its newline). Never throws, never crashes on any bytes.
Request readRequest(const QByteArray& line);

/// The response lines (compact JSON, ending in '\n').
QByteArray resultLine(const QJsonValue& id, const QJsonValue& result);
QByteArray errorLine(const QJsonValue& id, int code, const QString& message, const QJsonValue& data = {});
QByteArray notificationLine(const QString& method, const QJsonObject& params);

/// Splits a byte stream into lines of at most kMaxLineBytes. A longer line is not
/// kept: its bytes are skipped up to the next newline and `overlong` is called once for
/// it (the caller answers with an error). Memory stays bounded whatever arrives.
class LineSplitter {
public:
    /// Feeds bytes; calls `line` for every complete line, `overlong` for each one too long.
    void feed(const QByteArray& bytes, const std::function<void(const QByteArray&)>& line,
              const std::function<void()>& overlong);
    /// Bytes held for an incomplete line.
    int pending() const { return m_buffer.size(); }

private:
    QByteArray m_buffer;
    bool m_skipping = false;  ///< inside a line already known to be too long
};

} // namespace app::api
