#include "cli/CliContext.h"

#include "connection/BackendFactory.h"
#include "connection/ConnectionOptions.h"
#include "model/bus/BusMemory.h"
#include "model/bus/BusSpec.h"
#include "model/io/DisplayText.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceIdentifier.h"
#include "model/session/DeviceSession.h"
#include "sim/SimBus.h"
#include "transport/ModbusBackend.h"
#include "transport/ModbusClient.h"
#include "transport/TrafficLog.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>
#include <atomic>
#ifdef Q_OS_WIN
#include <windows.h>
#else
#include <csignal>
#endif

namespace opentop {

namespace {

std::atomic<bool> g_interrupted{false};

#ifdef Q_OS_WIN
// The console's Ctrl-C, Ctrl-Break and close, on a thread Windows starts for the event.
BOOL WINAPI onConsoleControl(DWORD event)
{
    switch (event) {
    case CTRL_C_EVENT:
    case CTRL_BREAK_EVENT:
        g_interrupted.store(true);
        return TRUE;
    case CTRL_CLOSE_EVENT:
        // The window closed (as SIGHUP on a dropped ssh session): Windows ends the process
        // when this returns, or after 5 s. Waiting lets the current transaction complete and
        // the command report what was done; the process ends with it before the wait does.
        g_interrupted.store(true);
        Sleep(4000);
        return TRUE;
    default:
        return FALSE;
    }
}
#else
extern "C" void onInterrupt(int)
{
    // Stop between transactions: the current one completes, nothing new starts.
    g_interrupted.store(true);
}
#endif

} // namespace

CliContext::CliContext(const QCommandLineParser& parser, QTextStream& out, QTextStream& err,
                       QObject* parent)
    : GroupReach(parent)
    , m_parser(parser)
    , m_out(out)
    , m_err(err)
    , m_log(std::make_unique<TrafficLog>())
{
    m_log->setDescriber(m_describer.describer());
}

void CliContext::setGroups(const BusGroups& groups)
{
    m_groups = groups;
    m_describer.setGroups(groups);
}

QVector<DeviceSession*> CliContext::reachedBy(int slave) const
{
    QVector<DeviceSession*> sessions;
    for (int child : m_groups.childrenOf(slave))
        if (DeviceSession* s = m_sessions.value(child))
            sessions << s;
    return sessions;
}

CliContext::~CliContext()
{
    qDeleteAll(m_sessions);
    m_sessions.clear();
    m_client.reset(); // bounded shutdown of the bus worker before the log goes
}

void CliContext::installInterruptHandler()
{
#ifdef Q_OS_WIN
    SetConsoleCtrlHandler(onConsoleControl, TRUE);
#else
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    // A dropped ssh session: stop between transactions and report like Ctrl-C, never die in
    // the middle of a restore with nothing said.
    std::signal(SIGHUP, onInterrupt);
#ifdef SIGPIPE
    // Output piped into `head` or a `less` quit early: the pipe closing must not end a restore
    // halfway. Writes to it fail instead (CliApp::finishOutput says so on stderr).
    std::signal(SIGPIPE, SIG_IGN);
#endif
#endif
}

bool CliContext::interrupted() const
{
    return g_interrupted.load();
}

bool CliContext::connectBus()
{
    if (m_client)
        return true;
    QString error;
    const auto settings = ConnectionOptions::fromParser(m_parser, QString(), &error);
    if (!settings) {
        // A wrong or missing connection option is a wrong command line (exit 2), said once.
        if (!m_usageError)
            m_err << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        m_usageError = true;
        return false;
    }
    m_settings = *settings;
    if (m_parser.isSet(QStringLiteral("trace"))) {
        m_log->setSink([this](const TrafficEntry& e) {
            // The sink runs on the bus thread; stderr is line-buffered and lines are short.
            const QByteArray line = e.toLine().toLocal8Bit() + '\n';
            std::fwrite(line.constData(), 1, size_t(line.size()), stderr);
        });
    }
    BackendFactory::Made made = BackendFactory::makeClient(m_settings, m_log.get());
    if (!made.client) {
        m_err << tr("error: %1").arg(DisplayText::escapedLines(made.error)) << Qt::endl;
        return false;
    }
    m_simBus = made.simBus;
    m_client = std::move(made.client);
    const QString openError = m_client->openBlocking();
    if (!openError.isEmpty()) {
        // The transport's text already names the port ("Cannot open /dev/ttyUSB0 19200 8N1: ...").
        m_err << tr("error: %1").arg(DisplayText::escapedLines(openError)) << Qt::endl;
        m_client.reset();
        return false;
    }
    if (m_parser.isSet(QStringLiteral("trace")) && !m_client->lineReport().isEmpty())
        m_err << tr("serial line: %1").arg(m_client->lineReport().text()) << Qt::endl;
    if (m_settings.kind == ConnectionSettings::Kind::Simulated) {
        for (const BusSpecEntry& e :
             BusSpec::parse(m_settings.simSpec, nullptr).value_or(QVector<BusSpecEntry>())) {
            m_knownSlaves << e.slave;
            m_simTypes.insert(e.slave, e.type);
        }
    }
    return true;
}

std::optional<BusDriveList> CliContext::busDrives(QString* error)
{
    const QString option = QStringLiteral("bus-drives");
    const bool given = m_parser.isSet(option);
    const QString text =
        given ? m_parser.value(option) : qEnvironmentVariable("OPENTOP_BUS_DRIVES");
    BusDriveList list;
    if (!text.trimmed().isEmpty()) {
        QString parseError;
        const auto ids = parseIds(text, &parseError);
        if (!ids) {
            if (error)
                *error = tr("%1 \"%2\": %3")
                             .arg(given ? QStringLiteral("--bus-drives")
                                        : QStringLiteral("OPENTOP_BUS_DRIVES"),
                                  text, parseError);
            return std::nullopt;
        }
        list.source = given ? BusDriveList::Source::Option : BusDriveList::Source::Environment;
        list.slaves = *ids;
        return list;
    }
    if (!connectBus())
        return list;
    if (m_settings.kind == ConnectionSettings::Kind::Simulated) {
        list.source = BusDriveList::Source::Simulated;
        list.slaves = m_knownSlaves;
        return list;
    }
    // What the last scan of this connection found, here or in the window.
    const QString key = BusMemory::key(m_settings);
    const QVector<BusMemory::Drive> remembered = BusMemory::load(key);
    if (remembered.isEmpty())
        return list;
    list.source = BusDriveList::Source::Remembered;
    for (const BusMemory::Drive& d : remembered)
        list.slaves << d.slave;
    list.savedAt = BusMemory::savedAt(key);
    list.place = BusMemory::placeText(m_settings);
    return list;
}

QString CliContext::busKey(QString* error) const
{
    if (m_client)
        return BusMemory::key(m_settings);
    const auto settings = ConnectionOptions::fromParser(m_parser, QString(), error);
    return settings ? BusMemory::key(*settings) : QString();
}

QHash<int, QString> CliContext::machineNames()
{
    if (!m_machineNames) {
        QString error;
        const QString key = busKey(&error);
        m_machineNames = key.isEmpty() ? QHash<int, QString>() : BusMemory::names(key);
    }
    return *m_machineNames;
}

QString CliContext::fittingVariant(const QString& type, const QString& family)
{
    QString variant;
    const Profile* p = ProfileRegistry::builtIn().forDeviceType(type, &variant);
    return p && p->family == family && !variant.isEmpty() ? variant : QString();
}

std::optional<QString> CliContext::givenVariant(int slave, const QString& family) const
{
    if (!m_parser.isSet(QStringLiteral("variant")))
        return std::nullopt;
    for (const QString& item : m_parser.value(QStringLiteral("variant")).split(QLatin1Char(','))) {
        const int eq = item.indexOf(QLatin1Char('='));
        if (eq < 0) {
            if (!fittingVariant(item.trimmed(), family).isEmpty())
                return fittingVariant(item.trimmed(), family);
        } else if (item.left(eq).trimmed().toInt() == slave) {
            return fittingVariant(item.mid(eq + 1).trimmed(), family);
        }
    }
    return std::nullopt;
}

QString CliContext::assignedVariant(int slave, const QString& family) const
{
    if (const std::optional<QString> given = givenVariant(slave, family))
        return *given;
    return fittingVariant(m_simTypes.value(slave), family);
}

DeviceInfo CliContext::identify(int slave)
{
    if (m_identified.contains(slave))
        return m_identified.value(slave);
    DeviceInfo info;
    info.slave = slave;
    if (!connectBus())
        return info;
    DeviceIdentifier identifier(m_client.get(), ProfileRegistry::builtIn());
    wait([&](std::function<void()> finish) {
        identifier.identify(slave, [&info, finish](const DeviceInfo& found) {
            info = found;
            finish();
        });
    });
    if (info.state == DeviceInfo::State::Present && info.variant.isEmpty()) {
        info.variant = assignedVariant(slave, info.family);
        const Profile* p = ProfileRegistry::builtIn().family(info.family);
        if (p && p->variant(info.variant))
            info.model = p->variant(info.variant)->model;
    }
    info.machineName = machineNames().value(slave);
    m_identified.insert(slave, info);
    return info;
}

DeviceSession* CliContext::session(int slave, QString* error)
{
    if (DeviceSession* s = m_sessions.value(slave))
        return s;
    const DeviceInfo info = identify(slave);
    if (!m_client) {
        // connectBus() has said why; "machine number N: not checked" would only mislead.
        if (error)
            *error = tr("machine number %1: no connection").arg(slave);
        return nullptr;
    }
    if (info.state != DeviceInfo::State::Present) {
        if (error)
            *error = tr("machine number %1: %2%3")
                         .arg(slave)
                         .arg(DeviceInfo::stateText(info.state),
                              info.detail.isEmpty()
                                  ? QString()
                                  : QStringLiteral(" (") + info.detail + QLatin1Char(')'));
        return nullptr;
    }
    const Profile* profile = ProfileRegistry::builtIn().family(info.family);
    auto* s = new DeviceSession(m_client.get(), *profile, slave, info.variant);
    // What an earlier run wrote and did not store is stored by a restore of this one.
    BusMemory::keep(BusMemory::key(m_settings), s);
    s->setMachineName(machineNames().value(slave)); // how messages and files name it
    s->acceptIdentification(info.identifyRegisters);
    s->setGroupReach(this);
    m_sessions.insert(slave, s);
    return s;
}

bool CliContext::wait(const std::function<void(std::function<void()> finish)>& start)
{
    if (interrupted())
        return false;
    QEventLoop loop;
    bool done = false;
    start([&done, &loop] {
        done = true;
        loop.quit();
    });
    if (done)
        return true;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&loop, this] {
        if (interrupted())
            loop.quit();
    });
    poll.start(50);
    loop.exec();
    if (!done && m_client)
        m_client->cancelAll();
    return done;
}

QString CliContext::variantError(const QString& text)
{
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    QStringList known;
    for (const Profile& p : registry.profiles()) {
        for (const ProfileVariant& v : p.variants)
            known << v.id;
    }
    for (const QString& item : text.split(QLatin1Char(','))) {
        const int eq = item.indexOf(QLatin1Char('='));
        const QString variant = (eq < 0 ? item : item.mid(eq + 1)).trimmed().toLower();
        if (eq >= 0) {
            bool ok = false;
            const int id = item.left(eq).trimmed().toInt(&ok);
            if (!ok || id < 1 || id > 247)
                return tr("--variant %1: \"%2\" is not a machine number 1–247")
                    .arg(item.trimmed(), item.left(eq).trimmed());
        }
        if (!known.contains(variant))
            return tr("--variant %1: \"%2\" is not a drive variant; use one of %3")
                .arg(item.trimmed(), variant, known.join(QStringLiteral(", ")));
    }
    return QString();
}

std::optional<QVector<int>> CliContext::parseIds(const QString& text, QString* error)
{
    QVector<int> ids;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QStringList range = part.split(QLatin1Char('-'));
        bool ok1 = false;
        bool ok2 = range.size() == 1;
        const int first = range.value(0).trimmed().toInt(&ok1);
        const int last = range.size() == 2 ? range.value(1).trimmed().toInt(&ok2) : first;
        if (!ok1 || !ok2 || range.size() > 2 || first < 1 || last > 247 || first > last) {
            if (error)
                *error =
                    tr("\"%1\" is not a machine number 1–247 or a range such as 3-8").arg(part);
            return std::nullopt;
        }
        for (int id = first; id <= last; ++id) {
            if (!ids.contains(id))
                ids << id;
        }
    }
    if (ids.isEmpty()) {
        if (error)
            *error = tr("no machine number given");
        return std::nullopt;
    }
    return ids;
}

} // namespace opentop
