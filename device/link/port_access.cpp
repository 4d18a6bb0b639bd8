#include "device/link/port_access.h"

#include <cerrno>
#include <grp.h>
#include <sys/stat.h>
#include <unistd.h>

namespace dev {

namespace {
QString modeText(mode_t m)
{
    QString s = S_ISCHR(m) ? QStringLiteral("c") : S_ISLNK(m) ? QStringLiteral("l") : S_ISDIR(m) ? QStringLiteral("d") : QStringLiteral("-");
    const char* letters = "rwxrwxrwx";
    for (int bit = 0; bit < 9; ++bit)
        s += (m & (0400 >> bit)) ? QLatin1Char(letters[bit]) : QLatin1Char('-');
    return s;
}
} // namespace

PortAccess portAccess(const QString& path)
{
    PortAccess a;
    const QByteArray p = path.toLocal8Bit();
    struct stat st {};
    if (::stat(p.constData(), &st) != 0)
        return a;  // gone: not a permission question
    a.mode = modeText(st.st_mode);
    a.denied = ::access(p.constData(), R_OK | W_OK) != 0 && errno == EACCES;
    if ((st.st_mode & (S_IRGRP | S_IWGRP)) == (S_IRGRP | S_IWGRP)) {
        if (const struct group* g = ::getgrgid(st.st_gid))
            a.group = QString::fromLocal8Bit(g->gr_name);
        else
            a.group = QString::number(st.st_gid);
    }
    return a;
}

motion::msg::Message permissionProblem(const QString& port, const PortAccess& access, const QString& detail)
{
    if (!access.denied)
        return motion::msg::make("link.port_busy", {motion::msg::verbatim("port", port.toStdString()), motion::msg::verbatim("detail", detail.toStdString())});
    if (!access.group.isEmpty())
        return motion::msg::make("link.port_group", {motion::msg::verbatim("port", port.toStdString()), motion::msg::verbatim("group", access.group.toStdString())});
    return motion::msg::make("link.port_denied", {motion::msg::verbatim("port", port.toStdString()), motion::msg::verbatim("mode", access.mode.toStdString())});
}

} // namespace dev
