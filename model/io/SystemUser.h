#pragma once

#include <QString>

namespace opentop {

// The account the program runs as, as the system names it: the default operator of an
// end-of-line run and the station's login field. getpwuid on POSIX, GetUserNameW on Windows.
class SystemUser
{
public:
    // Empty when the system cannot say.
    static QString loginName();
};

} // namespace opentop
