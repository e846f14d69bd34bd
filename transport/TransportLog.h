#pragma once

#include <QLoggingCategory>

namespace opentop {

// Diagnostics of the transport layer; enable with QT_LOGGING_RULES="opentop.transport.debug=true".
Q_DECLARE_LOGGING_CATEGORY(lcTransport)

} // namespace opentop
