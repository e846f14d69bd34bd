#include "transport/LibraryVersions.h"

#include <modbus.h>

namespace opentop {

QString LibraryVersions::libmodbus()
{
    return QStringLiteral("%1.%2.%3")
        .arg(libmodbus_version_major)
        .arg(libmodbus_version_minor)
        .arg(libmodbus_version_micro);
}

} // namespace opentop
