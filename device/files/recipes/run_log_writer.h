#pragma once
// Appends run-log lines (run_log.h) and makes each durable before returning:
// write, then fsync. A recipe run writes a line before it commands what the
// line announces, so whatever the log says happened may have; whatever it does
// not say did not.
#include "device/files/json.h"

#include "motion/message.h"

#include <QString>

namespace dev::files::plates {

class RunLogWriter {
public:
    RunLogWriter() = default;
    ~RunLogWriter();
    RunLogWriter(const RunLogWriter&) = delete;
    RunLogWriter& operator=(const RunLogWriter&) = delete;

    /// A new log: refuses to overwrite an existing file (a log is a record).
    bool create(const QString& path, motion::msg::Message* error);
    /// An existing log, to continue it.
    bool append(const QString& path, motion::msg::Message* error);
    void close();
    bool isOpen() const { return m_fd >= 0; }
    QString path() const { return m_path; }
    /// file.log.cannot_open / cannot_write / cannot_sync / not_open {file, detail}.
    motion::msg::Message lastError() const { return m_error; }

    /// One JSON object as one line; the time ("time") is added here. False (and
    /// lastError()) when the disk refused: a run must stop then.
    bool write(dev::files::json::Value line);

private:
    bool open(const QString& path, int flags, motion::msg::Message* error);
    motion::msg::Message problem(const char* id) const;
    int m_fd = -1;
    QString m_path;
    motion::msg::Message m_error;
};

} // namespace dev::files::plates
