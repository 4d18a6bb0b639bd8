// A serial port that will not open for lack of permission says what to do on Debian (join
// the port's group, log out and in) rather than "busy or you lack permission"; a port the
// user may open but cannot (another program holds it) says that instead.
//
// The tests run as root, for whom file modes deny nothing, so the pty is checked by a
// child process that has become an ordinary user (nobody) first; as an ordinary user the
// test takes the mode away from its own pty instead. QSerialPort itself is not driven
// into PermissionError here (root opens anything): what it reports is classified by
// dev::permissionProblem, which these tests cover for each case.
#include "device/link/port_access.h"

#include <grp.h>
#include <pwd.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace {

struct Pty {
    int master = -1;
    QString slave;
    Pty()
    {
        master = ::posix_openpt(O_RDWR | O_NOCTTY);
        if (master >= 0 && ::grantpt(master) == 0 && ::unlockpt(master) == 0)
            slave = QString::fromLocal8Bit(::ptsname(master));
    }
    ~Pty()
    {
        if (master >= 0)
            ::close(master);
    }
};

/// portAccess(path) as seen by uid/gid `who` (a child process), as "denied|group".
std::string accessAs(const QString& path, uid_t uid, gid_t gid)
{
    int fds[2];
    if (::pipe(fds) != 0)
        return "pipe failed";
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        std::string out = "cannot become the user";
        if (::setgroups(0, nullptr) == 0 && ::setgid(gid) == 0 && ::setuid(uid) == 0) {
            const dev::PortAccess a = dev::portAccess(path);
            out = std::string(a.denied ? "denied" : "allowed") + "|" + a.group.toStdString();
        }
        [[maybe_unused]] const auto n = ::write(fds[1], out.data(), out.size());
        ::_exit(0);
    }
    ::close(fds[1]);
    std::string got;
    char buf[256];
    ssize_t n;
    while ((n = ::read(fds[0], buf, sizeof buf)) > 0)
        got.append(buf, static_cast<size_t>(n));
    ::close(fds[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return got;
}

std::string argOf(const motion::msg::Message& m, const char* name) { return m.text(name); }

TEST(PortAccess, APtyWhoseModeShutsTheUserOutGivesTheGroupToJoin)
{
    Pty pty;
    ASSERT_FALSE(pty.slave.isEmpty());
    const QByteArray path = pty.slave.toLocal8Bit();
    if (::geteuid() == 0) {
        // As a serial port is on Debian: root:dialout, rw for the group only.
        const struct group* dialout = ::getgrnam("dialout");
        const gid_t portGroup = dialout ? dialout->gr_gid : 20;
        ASSERT_EQ(::chown(path.constData(), 0, portGroup), 0);
        ASSERT_EQ(::chmod(path.constData(), 0660), 0);
        const struct passwd* nobody = ::getpwnam("nobody");
        const uid_t uid = nobody ? nobody->pw_uid : 65534;
        const gid_t gid = nobody ? nobody->pw_gid : 65534;
        const std::string group = dialout ? "dialout" : "20";
        EXPECT_EQ(accessAs(pty.slave, uid, gid), "denied|" + group);
        // A member of the group may open it.
        EXPECT_EQ(accessAs(pty.slave, uid, portGroup), "allowed|" + group);
        // Root is never denied: a PermissionError then means another program holds it.
        EXPECT_FALSE(dev::portAccess(pty.slave).denied);
    } else {
        // An ordinary user's own pty, its mode taken away.
        ASSERT_EQ(::chmod(path.constData(), 0), 0);
        const dev::PortAccess a = dev::portAccess(pty.slave);
        EXPECT_TRUE(a.denied);
        EXPECT_TRUE(a.group.isEmpty());
        EXPECT_EQ(dev::permissionProblem(pty.slave, a, QStringLiteral("Permission denied")).id, "link.port_denied");
    }
}

TEST(PortAccess, QSerialPortsPermissionErrorIsWordedByWhatTheFileSystemSays)
{
    dev::PortAccess groupOnly;
    groupOnly.denied = true;
    groupOnly.group = QStringLiteral("dialout");
    groupOnly.mode = QStringLiteral("crw-rw----");
    const motion::msg::Message join = dev::permissionProblem(QStringLiteral("/dev/ttyUSB0"), groupOnly, QStringLiteral("Permission denied"));
    EXPECT_EQ(join.id, "link.port_group");
    EXPECT_EQ(argOf(join, "port"), "/dev/ttyUSB0");
    EXPECT_EQ(argOf(join, "group"), "dialout");

    dev::PortAccess noGroup = groupOnly;
    noGroup.group.clear();
    noGroup.mode = QStringLiteral("crw-------");
    const motion::msg::Message denied = dev::permissionProblem(QStringLiteral("/dev/ttyUSB0"), noGroup, QStringLiteral("Permission denied"));
    EXPECT_EQ(denied.id, "link.port_denied");
    EXPECT_EQ(argOf(denied, "mode"), "crw-------");

    const motion::msg::Message busy = dev::permissionProblem(QStringLiteral("/dev/ttyUSB0"), dev::PortAccess{}, QStringLiteral("locked"));
    EXPECT_EQ(busy.id, "link.port_busy");
    EXPECT_EQ(argOf(busy, "detail"), "locked");
}

TEST(PortAccess, APortThatIsNotThereIsNoPermissionQuestion)
{
    const dev::PortAccess a = dev::portAccess(QStringLiteral("/dev/ttyBP-not-there"));
    EXPECT_FALSE(a.denied);
}

} // namespace
