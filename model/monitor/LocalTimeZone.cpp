#include "model/monitor/LocalTimeZone.h"

#include <QByteArray>
#include <QtGlobal>
#include <ctime>

namespace opentop {

void LocalTimeZone::readOnce()
{
#ifdef Q_OS_WIN
    return; // glibc's cost, and a TZ the Windows C runtime would read as UTC
#endif
    if (qEnvironmentVariableIsSet("TZ"))
        return;
    qputenv("TZ", QByteArrayLiteral(":/etc/localtime"));
    tzset();
}

} // namespace opentop
