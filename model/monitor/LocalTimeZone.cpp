#include "model/monitor/LocalTimeZone.h"

#include <QByteArray>
#include <QtGlobal>
#include <ctime>

namespace opentop {

void LocalTimeZone::readOnce()
{
    if (qEnvironmentVariableIsSet("TZ"))
        return;
    qputenv("TZ", QByteArrayLiteral(":/etc/localtime"));
    tzset();
}

} // namespace opentop
