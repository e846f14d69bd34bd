#include "model/ModelLog.h"

Q_LOGGING_CATEGORY(lcModel, "opentop.model", QtInfoMsg)
