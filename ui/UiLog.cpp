#include "ui/UiLog.h"

Q_LOGGING_CATEGORY(lcUi, "opentop.ui", QtInfoMsg)
