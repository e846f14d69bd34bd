#include "RunCommand.h"

#include "CliContext.h"
#include "GroupCheck.h"
#include "profile/ProfileRegistry.h"
#include "run/RunControl.h"
#include "session/DeviceSession.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::RunCommand", text);
}

// Drives update their status within a few cycles of a command.
constexpr int kSettleMs = 200;

int exitCodeOf(RunControl::Failure failure)
{
    switch (failure) {
    case RunControl::Failure::None:
        return ExitOk;
    case RunControl::Failure::Unsupported:
        return ExitUsage;
    case RunControl::Failure::InvalidValue:
    case RunControl::Failure::Priority:
        return ExitInvalid; // nothing was sent
    case RunControl::Failure::Communication:
        return ExitCommunication;
    case RunControl::Failure::Mismatch:
        return ExitMismatch;
    }
    return ExitCommunication;
}

} // namespace

QString RunCommand::summary() const
{
    return tr("Test run: start, stop, direction, running data, hold/free, speed (needs --yes)");
}

QList<QCommandLineOption> RunCommand::options() const
{
    return {{QStringLiteral("yes"), tr("Send the command (it moves or stops a motor).")}};
}

int RunCommand::run(CliContext& context, const QStringList& args)
{
    QTextStream& out = context.out();
    QTextStream& err = context.err();
    QString error;
    const auto ids = args.isEmpty() ? std::nullopt : CliContext::parseIds(args.first(), &error);
    if (!ids || ids->size() != 1 || args.size() < 2) {
        err << tr("error: usage: %1 (one machine number; a negative speed after --)")
                   .arg(synopsis())
            << Qt::endl;
        return ExitUsage;
    }
    const int slave = ids->first();
    const std::optional<RunControl::Command> command = RunControl::parse(args.mid(1), &error);
    if (!command) {
        err << tr("error: %1").arg(error) << Qt::endl;
        return ExitUsage;
    }
    DeviceSession* session = context.session(slave, &error);
    if (!session) {
        err << tr("error: %1").arg(error) << Qt::endl;
        return ExitCommunication;
    }
    const RunControl::Plan plan = RunControl::plan(*session, *command);
    if (plan.failure != RunControl::Failure::None) {
        err << tr("error: %1").arg(plan.error) << Qt::endl;
        return exitCodeOf(plan.failure);
    }
    const bool confirmed = context.parser().isSet(QStringLiteral("yes"));
    if (!confirmed)
        err << tr("Would send to machine number %1: %2\nThis moves or stops a motor: add --yes to "
                  "send it.")
                   .arg(slave)
                   .arg(plan.description)
            << Qt::endl;
    // Drives in the target's communication group execute the command too, without replying.
    GroupCheck group(context);
    const int refused = group.before(slave, confirmed, ExitUsage);
    if (!confirmed || refused != ExitOk)
        return confirmed ? refused : ExitUsage;

    RunControl control(context.client(), ProfileRegistry::builtIn());
    RunControl::Outcome outcome;
    if (!context.wait([&](std::function<void()> finish) {
            control.execute(session, *command, [&outcome, finish](const RunControl::Outcome& o) {
                outcome = o;
                finish();
            });
        }))
        return ExitInterrupted;
    QJsonObject json{{QStringLiteral("slave"), slave},
                     {QStringLiteral("family"), session->profile().family},
                     {QStringLiteral("command"), args.mid(1).join(QLatin1Char(' '))},
                     {QStringLiteral("write"), plan.description},
                     {QStringLiteral("sent"), outcome.sent},
                     {QStringLiteral("ok"), outcome.ok}};
    if (!outcome.error.isEmpty())
        json.insert(QStringLiteral("error"), outcome.error);
    if (!outcome.explanation.isEmpty())
        json.insert(QStringLiteral("explanation"), outcome.explanation);
    if (!context.json()) {
        if (outcome.ok && group.children().isEmpty())
            out << tr("Sent to machine number %1: %2").arg(slave).arg(plan.description) << '\n';
        else if (outcome.ok)
            out << tr("Sent to machine number %1, executed also by %2 (communication group): %3")
                       .arg(slave)
                       .arg(BusGroups::listText(group.children()))
                       .arg(plan.description)
                << '\n';
        else
            err << tr("error: %1").arg(outcome.error) << '\n'
                << (outcome.explanation.isEmpty() ? QString()
                                                  : outcome.explanation + QLatin1Char('\n'));
    }
    // What a drive does now, read from it (children included: they executed the command too).
    auto readState = [&](DeviceSession* target, const QString& title, int settleMs,
                         QJsonObject* result) {
        RunControl::State state;
        if (!context.wait([&](std::function<void()> finish) {
                control.readState(
                    target,
                    [&state, finish](const RunControl::State& s) {
                        state = s;
                        finish();
                    },
                    settleMs);
            }))
            return false;
        QJsonObject items;
        int width = 0;
        for (const auto& item : state.items)
            width = std::max(width, int(item.first.size()));
        if (!context.json())
            out << title << '\n';
        for (const auto& item : state.items) {
            items.insert(item.first, item.second);
            if (!context.json())
                out << "  " << item.first.leftJustified(width) << "  " << item.second << '\n';
        }
        if (!state.error.isEmpty() && !context.json())
            out << "  " << tr("(not read: %1)").arg(state.error) << '\n';
        *result = QJsonObject{{QStringLiteral("values"), items}};
        if (state.running)
            result->insert(QStringLiteral("running"), *state.running);
        return true;
    };
    if (outcome.sent && (outcome.ok || outcome.failure != RunControl::Failure::Communication ||
                         !outcome.deviceError.isEmpty())) {
        QJsonObject s;
        if (!readState(session, tr("State of machine number %1:").arg(slave), kSettleMs, &s))
            return ExitInterrupted;
        json.insert(QStringLiteral("state"), s);
    }
    if (outcome.sent && !group.children().isEmpty()) {
        QJsonArray children;
        for (int child : group.children()) {
            DeviceSession* childSession = context.session(child, &error);
            QJsonObject s{{QStringLiteral("slave"), child}};
            if (!childSession) {
                if (!context.json())
                    out << tr("State of machine number %1 (communication group of %2): not read: "
                              "%3")
                               .arg(child)
                               .arg(slave)
                               .arg(error)
                        << '\n';
                s.insert(QStringLiteral("error"), error);
            } else if (!readState(childSession,
                                  tr("State of machine number %1 (communication group of %2):")
                                      .arg(child)
                                      .arg(slave),
                                  0, &s)) {
                return ExitInterrupted;
            }
            s.insert(QStringLiteral("slave"), child);
            children.append(s);
        }
        json.insert(QStringLiteral("group"), children);
    }
    if (context.json())
        out << QJsonDocument(json).toJson(QJsonDocument::Indented);
    return exitCodeOf(outcome.failure);
}

} // namespace opentop
