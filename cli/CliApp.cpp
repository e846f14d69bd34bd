#include "cli/CliApp.h"

#include "cli/CliCommands.h"
#include "cli/CliContext.h"
#include "cli/ExitCode.h"
#include "connection/ConnectionOptions.h"
#include "model/io/DisplayText.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QSet>
#include <QTextStream>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::CliApp", text);
}

QList<QCommandLineOption> globalOptions()
{
    return {
        {QStringLiteral("json"), tr("Machine-readable JSON on standard output.")},
        {QStringLiteral("trace"), tr("Print every frame sent and received on standard error.")},
        {QStringLiteral("variant"),
         tr("Drive variant where the drive does not report it: VARIANT, or ID=VARIANT,... (e.g. "
            "dbu400, 150=dbu400)."),
         tr("VARIANT")},
        {QStringLiteral("bus-drives"),
         tr("The drives on the bus, e.g. 1,3,5-7 (default: OPENTOP_BUS_DRIVES, else the drives "
            "the last scan of this connection found): before a write or command, their "
            "communication group is read to name every drive it also reaches."),
         tr("LIST")},
        {QStringLiteral("no-group-check"),
         tr("Write or command a drive that can be a communication group parent although the "
            "drives on the bus are not known (no --bus-drives and no scan of this connection): "
            "drives in its group execute it too, unnamed.")},
        {{QStringLiteral("h"), QStringLiteral("help")},
         tr("Show this help, or a command's help after the command.")},
        {QStringLiteral("version"), tr("Show the version.")},
        // Read by main() before this parser exists (Language::requestedIn); listed so that the
        // parser accepts it and the help shows it.
        {QStringLiteral("lang"),
         tr("Language of the human output: en, zh_TW, zh_CN, ko, ja (default: the system's). "
            "--json output is the same in every language."),
         tr("CODE")},
    };
}

} // namespace

CliApp::CliApp()
{
    m_commands = makeCliCommands();
}

CliApp::~CliApp() = default;

CliCommand* CliApp::find(const QString& name) const
{
    for (const auto& c : m_commands) {
        if (c->name() == name)
            return c.get();
    }
    return nullptr;
}

QString CliApp::helpText(const QString& program) const
{
    QString text = tr("Usage: %1 [options] COMMAND [arguments]\n\n"
                      "Commissioning tool for RS-485 Modbus-RTU motor drives.\n\nCommands:\n")
                       .arg(program);
    for (const auto& c : m_commands)
        text += QStringLiteral("  %1  %2\n").arg(c->synopsis().leftJustified(44), c->summary());
    text += tr("\nConnection (every command that talks to drives):\n"
               "  --port PATH | --tcp HOST:PORT | --sim SPEC\n"
               "  --family F  --baud N  --parity N|E|O  --stop-bits N  --timeout MS  --retries N\n"
               "  Defaults follow the family: dbu 19200 8N1, dcpid 9600 8E1; --timeout 200,\n"
               "  --retries 3 (2 more while the line is noisy: a request needed a retry lately).\n"
               "  Serial port only: --rs485 off|auto|kernel|rts (who switches the RS-485\n"
               "  direction; off: the adapter), --rts-polarity high|low, --rts-delay US,\n"
               "  --low-latency on|off (default on). scan says what the driver accepted.\n"
               "Output: --json  --trace  --variant VARIANT  --lang CODE\n"
               "Groups: before a write or command, the communication group of the drives on the\n"
               "bus is read: --bus-drives LIST (or OPENTOP_BUS_DRIVES), else the drives the last\n"
               "scan of this connection found (here or in the window); with neither, a write to a\n"
               "drive that can be a group parent is refused unless --no-group-check\n\n"
               "Exit codes: 0 success, 1 communication failure, 2 usage, 3 invalid value or file\n"
               "(nothing written), 4 verification mismatch or a drive that did not stop,\n"
               "5 eol run FAIL, 6 eol run station error (no verdict on the unit),\n"
               "130 interrupted by Ctrl-C, SIGTERM or SIGHUP (what was done is reported).\n\n"
               "\"%1 help COMMAND\" shows a command's options.\n")
                .arg(program);
    return text;
}

bool CliApp::needsGui(const QStringList& arguments)
{
    // A certificate's PDF lays out text, which needs Qt Gui's font database (offscreen).
    const int eol = int(arguments.indexOf(QStringLiteral("eol")));
    return eol > 0 && arguments.indexOf(QStringLiteral("certificate"), eol) > eol;
}

QString CliApp::profileLanguage(const QStringList& arguments, const QString& language)
{
    for (const QString& a : arguments.mid(1)) {
        if (a == QLatin1String("--"))
            break;
        if (a == QLatin1String("--json") || a.startsWith(QLatin1String("--json=")))
            return QStringLiteral("en");
    }
    return language.isEmpty() ? QStringLiteral("en") : language;
}

int CliApp::finishOutput(int code, QTextStream& out, QTextStream& err,
                         const std::function<bool()>& lost)
{
    out.flush();
    if (out.status() == QTextStream::Ok && !(lost && lost()))
        return code;
    err << tr("note: standard output could not be written (closed early, or the disk is "
              "full): what the command printed there is lost; the work itself ran to its end "
              "and exit status %1 says how it ended")
               .arg(code)
        << Qt::endl;
    return code;
}

int CliApp::run(const QStringList& arguments, QTextStream& out, QTextStream& err)
{
    const QString program = QFileInfo(arguments.value(0, QStringLiteral("opentop-cli"))).fileName();
    QCommandLineParser parser;
    QSet<QString> global;
    QHash<QString, QSet<QString>> commandOptions;
    // Each command's options are its own: a command's --csv may be a flag where another's takes
    // a file. The line is read with the options of the command it names; when it names none
    // (or holds another command's option), with every command's, to say what is wrong.
    auto setUp = [&](QCommandLineParser& p, const CliCommand* only) {
        p.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
        QSet<QString> added;
        auto add = [&](const QCommandLineOption& o) {
            p.addOption(o);
            for (const QString& n : o.names())
                added.insert(n);
        };
        for (const QCommandLineOption& o : globalOptions())
            add(o);
        ConnectionOptions::addTo(p);
        for (const QString& n : ConnectionOptions::names())
            added.insert(n);
        global = added;
        for (const auto& c : m_commands) {
            if (only && c.get() != only)
                continue;
            for (const QCommandLineOption& o : c->options()) {
                for (const QString& n : o.names())
                    commandOptions[c->name()].insert(n);
                if (!added.contains(o.names().first()))
                    add(o);
            }
        }
    };
    bool parsed = false;
    for (const auto& c : m_commands) {
        if (!arguments.contains(c->name()))
            continue;
        QCommandLineParser own;
        setUp(own, c.get());
        if (!own.parse(arguments))
            continue;
        QStringList positional = own.positionalArguments();
        if (positional.value(0) == QLatin1String("help"))
            positional.removeFirst();
        if (positional.value(0) != c->name())
            continue;
        setUp(parser, c.get());
        parser.parse(arguments);
        parsed = true;
        break;
    }
    if (!parsed) {
        setUp(parser, nullptr);
        if (!parser.parse(arguments)) {
            // The parser's message quotes the argument as given.
            err << program << ": " << DisplayText::escaped(parser.errorText()) << '\n'
                << tr("Try \"%1 --help\".").arg(program) << Qt::endl;
            return ExitUsage;
        }
    }
    if (parser.isSet(QStringLiteral("version"))) {
        out << "opentop-cli " << OPENTOP_VERSION << Qt::endl;
        return ExitOk;
    }
    QStringList positional = parser.positionalArguments();
    const bool help =
        parser.isSet(QStringLiteral("help")) || positional.value(0) == QLatin1String("help");
    if (positional.value(0) == QLatin1String("help"))
        positional.removeFirst();
    if (positional.isEmpty()) {
        (help ? out : err) << helpText(program);
        (help ? out : err).flush();
        return help ? ExitOk : ExitUsage;
    }
    CliCommand* command = find(positional.first());
    if (!command) {
        err << tr("%1: unknown command \"%2\"; commands: ")
                   .arg(program, DisplayText::escaped(positional.first()));
        QStringList names;
        for (const auto& c : m_commands)
            names << c->name();
        err << names.join(QStringLiteral(", ")) << Qt::endl;
        return ExitUsage;
    }
    if (help) {
        out << tr("Usage: %1 [options] %2\n%3\n")
                   .arg(program, command->synopsis(), command->summary());
        if (!command->details().isEmpty())
            out << command->details() << '\n';
        for (const QCommandLineOption& o : command->options())
            out << QStringLiteral("  --%1%2  %3\n")
                       .arg(o.names().last(),
                            o.valueName().isEmpty() ? QString() : QLatin1Char(' ') + o.valueName(),
                            o.description());
        out.flush();
        return ExitOk;
    }
    for (const QString& name : parser.optionNames()) {
        if (!global.contains(name) && !commandOptions.value(command->name()).contains(name)) {
            err << tr("%1 %2: --%3 is not an option of this command; see \"%1 help %2\"")
                       .arg(program, command->name(), DisplayText::escaped(name))
                << Qt::endl;
            return ExitUsage;
        }
    }
    // Wrong option values are refused before anything is opened or sent (exit 2).
    QString wrong = ConnectionOptions::valueError(parser);
    if (wrong.isEmpty() && parser.isSet(QStringLiteral("variant")))
        wrong = CliContext::variantError(parser.value(QStringLiteral("variant")));
    if (!wrong.isEmpty()) {
        err << tr("%1: %2").arg(program, DisplayText::escapedLines(wrong)) << '\n'
            << tr("Try \"%1 --help\".").arg(program) << Qt::endl;
        return ExitUsage;
    }
    CliContext context(parser, out, err);
    int code = command->run(context, positional.mid(1));
    out.flush();
    err.flush();
    if (context.usageError())
        code = ExitUsage;
    if (context.interrupted() && code == ExitOk)
        return ExitInterrupted;
    return code;
}

} // namespace opentop
