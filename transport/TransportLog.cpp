#include "transport/TransportLog.h"

namespace opentop {

Q_LOGGING_CATEGORY(lcTransport, "opentop.transport", QtInfoMsg)

} // namespace opentop
