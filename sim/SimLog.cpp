#include "sim/SimLog.h"

Q_LOGGING_CATEGORY(lcSim, "opentop.sim", QtInfoMsg)
