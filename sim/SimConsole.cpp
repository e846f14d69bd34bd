#include "sim/SimConsole.h"

#include "sim/SimBus.h"

#include <QMutexLocker>
#include <QRegularExpression>
#include <QStringList>

namespace opentop {

namespace {

const char* const kDeviceCommands[] = {"alarm", "warning",     "load",        "vr",
                                       "input", "ignore-stop", "power-cycle", "get",
                                       "set",   "defect",      "motor"};

} // namespace

SimConsole::SimConsole(std::shared_ptr<SimBus> bus)
    : m_bus(std::move(bus))
{
}

void SimConsole::setPortHooks(PortHook unplug, PortHook replug)
{
    m_unplug = std::move(unplug);
    m_replug = std::move(replug);
}

QString SimConsole::helpText()
{
    return tr("commands:\n"
              "  help                      this text\n"
              "  list                      the devices and their state\n"
              "  alarm ID CODE             raise an alarm (DBU)\n"
              "  warning ID CODE           raise a warning, CODE 0 clears it (DBU)\n"
              "  load ID PERCENT           add to the load rate (DBU) or current (DC)\n"
              "  vr ID RPM                 Ext-VR speed, used by SPno1 (DBU)\n"
              "  input ID MASK             input terminals: X0..X3 (DBU), SQ1 SQ2 DE (DC)\n"
              "  ignore-stop ID on|off     acknowledge stop commands but keep running (DBU)\n"
              "  power-cycle ID            turn the device off and on\n"
              "  get ID ADDR [fc]          show a register (fc 3, 4 or 6 for write-only)\n"
              "  set ID ADDR VALUE [fc]    change a register without any check\n"
              "  defect ID DEFECT[,...]    add defects to a drive (see --help), e.g.\n"
              "                            defect 3 max_speed=800 or defect 4 alarm=0x07@2s\n"
              "  defect ID clear           the drive has no defects again\n"
              "  defects                   the drives' defects\n"
              "  motor ID [KEY=VALUE ...]  show or change a DC controller's motor and load,\n"
              "                            e.g. motor 7 load=0.05 inertia=3e-4 (see --motor)\n"
              "  unplug                    close the pty under its client (adapter pulled out)\n"
              "  replug                    a new pty behind the same symlink\n"
              "  quit                      stop the simulator");
}

SimControlResult SimConsole::execute(const QString& line)
{
    static const QRegularExpression spaces(QStringLiteral("\\s+"));
    QStringList words = line.trimmed().split(spaces, Qt::SkipEmptyParts);
    if (words.isEmpty())
        return {true, QString()};
    const QString cmd = words.takeFirst().toLower();
    if (cmd == QLatin1String("help"))
        return {true, helpText()};
    if (cmd == QLatin1String("quit") || cmd == QLatin1String("exit")) {
        m_quit = true;
        return {true, tr("bye")};
    }
    if (cmd == QLatin1String("unplug") || cmd == QLatin1String("replug")) {
        const PortHook& hook = cmd == QLatin1String("unplug") ? m_unplug : m_replug;
        if (!hook)
            return {false, tr("%1 needs the pty server (--pty)").arg(cmd)};
        return hook();
    }
    if (cmd == QLatin1String("list")) {
        QStringList lines;
        QMutexLocker lock(&m_bus->mutex());
        const qint64 now = m_bus->nowMs();
        for (SimDevice* d : m_bus->devices()) {
            d->advance(now);
            lines << QStringLiteral("%1 %2").arg(d->slave()).arg(d->stateText());
            if (d->defects().any())
                lines.last() += tr(", defects: %1").arg(d->defects().spec.toString());
        }
        return {true, lines.join(QLatin1Char('\n'))};
    }
    if (cmd == QLatin1String("defects")) {
        QStringList lines;
        QMutexLocker lock(&m_bus->mutex());
        for (const SimDevice* d : m_bus->devices()) {
            if (d->defects().any())
                lines << QStringLiteral("%1 %2: %3")
                             .arg(d->slave())
                             .arg(d->type(), d->defects().spec.toString());
        }
        return {true, lines.isEmpty() ? tr("no drive has defects") : lines.join(QLatin1Char('\n'))};
    }
    bool known = false;
    for (const char* c : kDeviceCommands)
        known = known || cmd == QLatin1String(c);
    if (!known)
        return {false, tr("unknown command '%1'; type help for the list").arg(cmd)};
    if (words.isEmpty())
        return {
            false,
            tr("usage: %1 ID ...; ID is a machine number on the bus (%2)").arg(cmd, m_bus->spec())};
    bool ok = false;
    const int id = words.takeFirst().toInt(&ok);
    if (!ok)
        return {
            false,
            tr("'%1' is not a machine number; the bus has %2").arg(line.trimmed(), m_bus->spec())};
    words.prepend(cmd);
    return m_bus->control(id, words);
}

} // namespace opentop
