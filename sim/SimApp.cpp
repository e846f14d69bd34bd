#include "sim/SimApp.h"

#include "sim/DcPidSimDevice.h"

#include "sim/ConsoleInput.h"
#include "sim/PtySimServer.h"
#include "sim/QuitSignals.h"
#include "sim/SimBus.h"
#include "sim/SimConsole.h"
#include "sim/SimLog.h"
#include "sim/TcpSimServer.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <cstdio>

namespace opentop {

namespace {

void printOut(const QString& text)
{
    std::fputs(text.toLocal8Bit().constData(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

void printErr(const QString& text)
{
    std::fputs(text.toLocal8Bit().constData(), stderr);
    std::fputc('\n', stderr);
    std::fflush(stderr);
}

} // namespace

SimApp::SimApp(QObject* parent)
    : QObject(parent)
{
}

SimApp::~SimApp()
{
    shutdown();
}

int SimApp::start(const QStringList& arguments)
{
    QString error;
    const std::optional<SimOptions> options = SimOptions::parse(arguments.mid(1), &error);
    if (!options) {
        printErr(QStringLiteral("opentop-sim: ") + error);
        return 2;
    }
    m_options = *options;
    if (m_options.help) {
        printOut(SimOptions::usage());
        return 0;
    }
    if (m_options.version) {
        printOut(QStringLiteral("opentop-sim " OPENTOP_VERSION));
        return 0;
    }
    QLoggingCategory::setFilterRules(
        m_options.quiet ? QStringLiteral("opentop.*.debug=false\nopentop.*.info=false")
                        : QStringLiteral("opentop.*.debug=false"));
    m_bus = SimBus::fromSpec(m_options.devices, &error);
    if (!m_bus) {
        printErr(QStringLiteral("opentop-sim: --devices: ") + error);
        return 2;
    }
    m_bus->setLine(m_options.baud, m_options.parity);
    const LineFormat busLine{m_options.baud, m_options.parity, 8, 1};
    for (SimDevice* d : m_bus->devices()) {
        const LineFormat own = d->lineFormat();
        if (own.isSet() && m_bus->hasOwnLine(d->slave()))
            printErr(tr("opentop-sim: %1@%2 talks %3 (its own line settings): it answers only "
                        "frames sent in that format")
                         .arg(d->type())
                         .arg(d->slave())
                         .arg(own.text()));
        else if (own.isSet() && !own.hears(busLine))
            printErr(tr("opentop-sim: warning: %1@%2 cannot use %3 %4 and will not answer")
                         .arg(d->type())
                         .arg(d->slave())
                         .arg(m_options.baud)
                         .arg(QLatin1Char(m_options.parity)));
    }
    m_bus->setFaults(FaultInjector(m_options.faults, m_options.seed));
    for (SimDevice* d : m_bus->devices()) {
        if (auto* dc = dynamic_cast<DcPidSimDevice*>(d))
            dc->setMotorModel(m_options.motor);
    }
    for (const auto& [slave, spec] : m_options.defects) {
        SimDevice* d = m_bus->device(slave);
        if (!d) {
            printErr(tr("opentop-sim: --defect %1:%2: no drive with machine number %1 on the "
                        "bus %3")
                         .arg(slave)
                         .arg(spec.toString(), m_bus->spec()));
            return 2;
        }
        if (!d->addDefects(spec, &error)) {
            printErr(tr("opentop-sim: --defect %1 (%2@%1): %3").arg(slave).arg(d->type(), error));
            return 2;
        }
    }

    m_signals = new QuitSignals(this);
    connect(m_signals, &QuitSignals::received, this, &SimApp::onSignal);

    const WireTiming timing(m_options.baud, m_options.parity, m_options.turnaroundMs);
    if (m_options.pty) {
        m_pty = new PtySimServer(m_bus, timing, m_options.wireTiming, this);
        m_pty->setHalfDuplex(m_options.halfDuplex);
        if (!m_pty->open(m_options.ptyLink, &error)) {
            printErr(QStringLiteral("opentop-sim: ") + error);
            // a link another simulator serves is a usage error, as bad arguments are
            return m_pty->linkHolderPid() > 0 ? 2 : 1;
        }
        printOut(QStringLiteral("pty: ") + m_pty->slavePath());
    }
    if (m_options.tcp) {
        m_tcp = new TcpSimServer(m_bus, timing, m_options.wireTiming, this);
        if (!m_tcp->listen(QHostAddress(m_options.tcpHost), m_options.tcpPort, &error)) {
            printErr(QStringLiteral("opentop-sim: ") + error);
            return 1;
        }
        printOut(QStringLiteral("tcp: %1:%2").arg(m_options.tcpHost).arg(m_tcp->port()));
    }

    m_console = std::make_unique<SimConsole>(m_bus);
    if (m_pty) {
        PtySimServer* pty = m_pty;
        m_console->setPortHooks(
            [pty] {
                if (!pty->isOpen())
                    return SimControlResult{false, tr("the port is unplugged already")};
                pty->unplug();
                return SimControlResult{true, tr("unplugged")};
            },
            [pty] {
                QString why;
                if (!pty->replug(&why))
                    return SimControlResult{false, why};
                return SimControlResult{true, QStringLiteral("pty: ") + pty->slavePath()};
            });
    }
    m_stdin = new ConsoleInput(this);
    connect(m_stdin, &ConsoleInput::received, this, &SimApp::onStdin);
    connect(qApp, &QCoreApplication::aboutToQuit, this, &SimApp::shutdown);
    printOut(QStringLiteral("ready"));
    return -1;
}

void SimApp::onStdin(const QByteArray& bytes, bool eof)
{
    m_stdinBuffer.append(bytes);
    if (eof && !m_stdinBuffer.isEmpty() && !m_stdinBuffer.endsWith('\n'))
        m_stdinBuffer.append('\n'); // a last command without a newline
    int newline;
    while ((newline = m_stdinBuffer.indexOf('\n')) >= 0) {
        const QString line = QString::fromLocal8Bit(m_stdinBuffer.left(newline));
        m_stdinBuffer.remove(0, newline + 1);
        const SimControlResult result = m_console->execute(line);
        if (!result.text.isEmpty())
            printOut(result.ok ? result.text : tr("error: %1").arg(result.text));
        if (m_console->quitRequested()) {
            QCoreApplication::quit();
            return;
        }
    }
    // At its end (no console, e.g. /dev/null) the simulator keeps serving until a signal.
}

void SimApp::onSignal()
{
    qCInfo(lcSim) << "signal received, stopping";
    QCoreApplication::quit();
}

void SimApp::shutdown()
{
    if (m_pty)
        m_pty->close();
    if (m_tcp)
        m_tcp->close();
    if (m_stdin)
        m_stdin->stop();
}

} // namespace opentop
