#pragma once

#include "sim/SimDevice.h"

#include <QCoreApplication>
#include <QString>
#include <functional>
#include <memory>

namespace opentop {

class SimBus;

// The simulator's text console: one command per line (help, list, quit and the per-device
// backdoors alarm, warning, load, vr, input, ignore-stop, power-cycle, get, set, defect).
class SimConsole
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SimConsole)
public:
    explicit SimConsole(std::shared_ptr<SimBus> bus);

    SimControlResult execute(const QString& line);
    // What unplug and replug do (the pty server's); without them the commands are refused.
    using PortHook = std::function<SimControlResult()>;
    void setPortHooks(PortHook unplug, PortHook replug);
    bool quitRequested() const { return m_quit; }
    static QString helpText();

private:
    std::shared_ptr<SimBus> m_bus;
    bool m_quit = false;
    PortHook m_unplug;
    PortHook m_replug;
};

} // namespace opentop
