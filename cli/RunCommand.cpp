#include "cli/RunCommand.h"

#include "cli/CliContext.h"
#include "cli/GroupCheck.h"
#include "model/io/DisplayText.h"
#include "model/profile/ProfileRegistry.h"
#include "model/run/GroupFollowers.h"
#include "model/run/RunControl.h"
#include "model/session/DeviceSession.h"

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
        err << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitUsage;
    }
    DeviceSession* session = context.session(slave, &error);
    if (!session) {
        err << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitCommunication;
    }
    const RunControl::Plan plan = RunControl::plan(*session, *command);
    if (plan.failure != RunControl::Failure::None) {
        err << tr("error: %1").arg(DisplayText::escapedLines(plan.error)) << Qt::endl;
        return exitCodeOf(plan.failure);
    }
    const bool confirmed = context.parser().isSet(QStringLiteral("yes"));
    if (!confirmed)
        err << tr("Would send to machine number %1: %2\nThis moves or stops a motor: add --yes to "
                  "send it.")
                   .arg(slave)
                   .arg(plan.description)
            << Qt::endl;
    // Drives in the target's communication group execute the command too, without replying;
    // a run command only where the drive takes them over the bus: who follows is said first.
    GroupCheck group(context);
    int refused = group.read(slave);
    const bool motion = plan.meta && plan.meta->safety == QLatin1String("motion");
    if (refused == ExitOk && motion && !group.children().isEmpty()) {
        QVector<GroupFollowers::Drive> followers;
        if (!context.wait([&](std::function<void()> finish) {
                GroupFollowers::readBefore(session->reachedDrives(),
                                           [&followers, finish](const auto& d) {
                                               followers = d;
                                               finish();
                                           });
            }))
            return ExitInterrupted;
        for (const QString& line : GroupFollowers::beforeLines(followers))
            err << tr("note: %1").arg(DisplayText::escapedLines(line)) << Qt::endl;
    }
    if (refused == ExitOk)
        refused = group.confirm(slave, confirmed, ExitUsage);
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
            err << tr("error: %1").arg(DisplayText::escapedLines(outcome.error)) << '\n'
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
    // What each drive of the group does now, read from it (they executed it too, or ignored it).
    if (outcome.sent && !group.children().isEmpty()) {
        QVector<GroupFollowers::Drive> drives;
        if (!context.wait([&](std::function<void()> finish) {
                GroupFollowers::readAfter(session->reachedDrives(),
                                          [&drives, finish](const auto& d) {
                                              drives = d;
                                              finish();
                                          });
            }))
            return ExitInterrupted;
        if (!context.json()) {
            out << tr("Communication group of %1, read after the command:").arg(slave) << '\n';
            for (const QString& line : GroupFollowers::afterLines(drives))
                out << "  " << line << '\n';
        }
        QJsonArray children;
        for (const GroupFollowers::Drive& d : drives) {
            QJsonObject s{{QStringLiteral("slave"), d.slave},
                          {QStringLiteral("priority"), d.priority},
                          {QStringLiteral("alarm"), d.alarm}};
            if (d.running)
                s.insert(QStringLiteral("running"), *d.running);
            if (!d.speed.isEmpty())
                s.insert(QStringLiteral("speed"), d.speed);
            if (!d.why.isEmpty())
                s.insert(QStringLiteral("why"), d.why);
            if (!d.commError.isEmpty())
                s.insert(QStringLiteral("commError"), d.commError);
            children.append(s);
        }
        json.insert(QStringLiteral("group"), children);
    }
    if (context.json())
        out << QJsonDocument(json).toJson(QJsonDocument::Indented);
    return exitCodeOf(outcome.failure);
}

} // namespace opentop
