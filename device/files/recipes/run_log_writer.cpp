#include "device/files/recipes/run_log_writer.h"

#include <QDateTime>
#include <QFile>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace dev::files::plates {

RunLogWriter::~RunLogWriter() { close(); }

motion::msg::Message RunLogWriter::problem(const char* id) const
{
    // strerror: the system's words for what the disk said (English on most systems).
    return motion::msg::make(id, {motion::msg::verbatim("file", m_path.toStdString()), motion::msg::verbatim("detail", std::strerror(errno))});
}

bool RunLogWriter::open(const QString& path, int flags, motion::msg::Message* error)
{
    close();
    const QByteArray name = QFile::encodeName(path);
    m_fd = ::open(name.constData(), flags | O_WRONLY | O_APPEND | O_CLOEXEC, 0644);
    if (m_fd < 0) {
        m_error = motion::msg::make("file.log.cannot_open", {motion::msg::verbatim("file", path.toStdString()), motion::msg::verbatim("detail", std::strerror(errno))});
        if (error)
            *error = m_error;
        return false;
    }
    m_path = path;
    return true;
}

bool RunLogWriter::create(const QString& path, motion::msg::Message* error) { return open(path, O_CREAT | O_EXCL, error); }

bool RunLogWriter::append(const QString& path, motion::msg::Message* error) { return open(path, 0, error); }

void RunLogWriter::close()
{
    if (m_fd >= 0)
        ::close(m_fd);
    m_fd = -1;
}

bool RunLogWriter::write(dev::files::json::Value line)
{
    if (m_fd < 0) {
        m_error = motion::msg::make("file.log.not_open");
        return false;
    }
    line.set("time", QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs).toStdString());
    const std::string text = dev::files::json::write(line, false) + "\n";
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(m_fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            m_error = problem("file.log.cannot_write");
            return false;
        }
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(m_fd) != 0) {
        m_error = problem("file.log.cannot_sync");
        return false;
    }
    return true;
}

} // namespace dev::files::plates
