#include "model/io/SystemUser.h"

#ifdef Q_OS_WIN
#include <windows.h>
#else
#include <pwd.h>
#include <unistd.h>
#endif

namespace opentop {

QString SystemUser::loginName()
{
#ifdef Q_OS_WIN
    constexpr DWORD kNameSize = 257; // UNLEN + 1
    wchar_t name[kNameSize] = {};
    DWORD size = kNameSize;
    return GetUserNameW(name, &size) ? QString::fromWCharArray(name) : QString();
#else
    const passwd* user = ::getpwuid(::geteuid());
    return user ? QString::fromLocal8Bit(user->pw_name) : QString();
#endif
}

} // namespace opentop
