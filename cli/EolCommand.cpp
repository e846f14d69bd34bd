#include "cli/EolCommand.h"

#include "cli/CliContext.h"
#include "cli/ExitCode.h"
#include "model/io/DisplayText.h"

#include <QCoreApplication>
#include <QSet>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolCommand", text);
}

} // namespace

EolCommand::EolCommand() = default;
EolCommand::~EolCommand() = default;

void EolCommand::add(std::unique_ptr<EolSubcommand> subcommand)
{
    m_subcommands.push_back(std::move(subcommand));
}

QString EolCommand::synopsis() const
{
    return QStringLiteral("eol run|recipe|results|certificate ...");
}

QString EolCommand::summary() const
{
    return tr("End-of-line station: recipes, the results database, unit certificates");
}

QString EolCommand::details() const
{
    QString text = tr("Subcommands:\n");
    for (const auto& s : m_subcommands)
        text += QStringLiteral("  eol %1\n      %2\n").arg(s->synopsis(), s->summary());
    text += tr("Results database: --db URL, else OPENTOP_EOL_DB, else the SQLite file\n"
               "$XDG_DATA_HOME/opentop/results.db (~/.local/share/opentop/results.db).\n"
               "\"opentop-cli help eol\" lists every option; each subcommand takes only its own.");
    return text;
}

QList<QCommandLineOption> EolCommand::options() const
{
    QList<QCommandLineOption> list;
    QSet<QString> seen;
    for (const auto& s : m_subcommands) {
        for (const QCommandLineOption& o : s->options()) {
            if (seen.contains(o.names().first()))
                continue;
            seen.insert(o.names().first());
            list << o;
        }
    }
    return list;
}

EolSubcommand* EolCommand::find(const QStringList& args) const
{
    EolSubcommand* best = nullptr;
    int bestWords = 0;
    for (const auto& s : m_subcommands) {
        const QStringList words = s->name().split(QLatin1Char(' '));
        if (words.size() > bestWords && args.mid(0, int(words.size())) == words) {
            best = s.get();
            bestWords = int(words.size());
        }
    }
    return best;
}

QString EolCommand::names() const
{
    QStringList list;
    for (const auto& s : m_subcommands)
        list << s->name();
    return list.join(QStringLiteral(", "));
}

int EolCommand::run(CliContext& context, const QStringList& args)
{
    EolSubcommand* sub = find(args);
    if (!sub) {
        if (args.isEmpty())
            context.err() << tr("error: name a subcommand: eol %1").arg(names()) << Qt::endl;
        else
            context.err() << tr("error: unknown subcommand \"eol %1\"; subcommands: %2")
                                 .arg(DisplayText::escaped(args.mid(0, 2).join(QLatin1Char(' '))),
                                      names())
                          << Qt::endl;
        context.err() << tr("See \"opentop-cli help eol\".") << Qt::endl;
        return ExitUsage;
    }
    // The options of eol's other subcommands are not this one's.
    QSet<QString> own;
    for (const QCommandLineOption& o : sub->options()) {
        for (const QString& n : o.names())
            own.insert(n);
    }
    QSet<QString> others;
    for (const QCommandLineOption& o : options()) {
        for (const QString& n : o.names())
            others.insert(n);
    }
    for (const QString& name : context.parser().optionNames()) {
        if (others.contains(name) && !own.contains(name)) {
            context.err() << tr("error: eol %1: --%2 is not an option of this subcommand; "
                                "usage: eol %3")
                                 .arg(sub->name(), name, sub->synopsis())
                          << Qt::endl;
            return ExitUsage;
        }
    }
    return sub->run(context, args.mid(int(sub->name().split(QLatin1Char(' ')).size())));
}

} // namespace opentop
