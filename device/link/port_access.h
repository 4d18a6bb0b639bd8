#pragma once
// Why a serial port would not open for lack of permission, and what to tell the user.
// QSerialPort reports a port it cannot open and one another program has locked with
// the same PermissionError; the file's owner, group and mode tell the two apart, and
// on Debian the usual answer is the port's group (dialout), which the user joins once.
#include "motion/message.h"

#include <QString>

namespace dev {

struct PortAccess {
    bool denied = false;   ///< this user (real uid and this session's groups) may not read and write it
    QString group;         ///< the port's group when its members may read and write it, else empty
    QString mode;          ///< the permission bits as ls shows them ("crw-rw----"), for the message
};

/// Asks the file system as the running user (access(2), stat(2)); root is never denied.
PortAccess portAccess(const QString& path);

/// The message for a port that would not open with QSerialPort's PermissionError:
/// link.port_group (join the group), link.port_denied (no group would help), or
/// link.port_busy when the user may open it (then another program holds it).
motion::msg::Message permissionProblem(const QString& port, const PortAccess& access, const QString& detail);

} // namespace dev
