#include "sim/QuitSignals.h"

#include <atomic>
#include <windows.h>

namespace opentop {

namespace {

std::atomic<QuitSignals*> g_target{nullptr};

// Runs on a thread of its own that Windows starts for the event; the loop hears of it queued.
// After a close, logoff or shutdown Windows ends the process soon after this returns.
BOOL WINAPI onConsoleControl(DWORD event)
{
    switch (event) {
    case CTRL_C_EVENT:
    case CTRL_BREAK_EVENT:
    case CTRL_CLOSE_EVENT:
        if (QuitSignals* target = g_target.load())
            QMetaObject::invokeMethod(target, &QuitSignals::received, Qt::QueuedConnection);
        return TRUE;
    default:
        return FALSE;
    }
}

} // namespace

QuitSignals::QuitSignals(QObject* parent)
    : QObject(parent)
{
    g_target.store(this);
    SetConsoleCtrlHandler(onConsoleControl, TRUE);
}

QuitSignals::~QuitSignals()
{
    SetConsoleCtrlHandler(onConsoleControl, FALSE);
    QuitSignals* self = this;
    g_target.compare_exchange_strong(self, nullptr);
}

} // namespace opentop
