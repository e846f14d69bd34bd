// PortLockFile on Windows: there are no UUCP lock files, since a COM port opens exclusively
// (PortLock_win.cpp). Only what PortLock's shared code refers to is here.
#include "transport/PortLockFile.h"

namespace opentop {

PortLockFile::~PortLockFile() = default;

QStringList PortLockFile::defaultDirectories()
{
    return {};
}

} // namespace opentop
