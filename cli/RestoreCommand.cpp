#include "RestoreCommand.h"

#include "CliContext.h"
#include "ExitCode.h"
#include "FileCommandSupport.h"
#include "GroupCheck.h"
#include "TextTable.h"
#include "files/Restorer.h"
#include "session/DeviceSession.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QJsonArray>
#include <QTimer>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::RestoreCommand", text);
}

QString trn(const char* text, int n)
{
    return QCoreApplication::translate("opentop::RestoreCommand", text, nullptr, n);
}

using Item = RestorePlan::Item;

} // namespace

QString RestoreCommand::summary() const
{
    return tr("Show what a backup file would change on its drives; with --yes write it, verified");
}

QList<QCommandLineOption> RestoreCommand::options() const
{
    return {{QStringLiteral("ids"), tr("Restore only these drives of the file, e.g. 1,5-7."),
             tr("LIST")},
            {QStringLiteral("dry-run"), tr("Read the drives and show the plan; write nothing.")},
            {QStringLiteral("yes"), tr("Write the plan (without it restore only shows it).")}};
}

RestorePlan RestoreCommand::restore(CliContext& context, DeviceSession* session,
                                    const BackupDevice& device, bool dryRun)
{
    Restorer restorer(session);
    RestorePlan result;
    bool finished = false;
    QEventLoop loop;
    // Ctrl-C cancels between transactions; the restorer then reports what it did.
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&restorer, &context] {
        if (context.interrupted())
            restorer.cancel();
    });
    poll.start(50);
    Restorer::Options options;
    options.dryRun = dryRun;
    restorer.start(device, options, [&](const RestorePlan& plan) {
        result = plan;
        finished = true;
        loop.quit();
    });
    if (!finished)
        loop.exec();
    return result;
}

void RestoreCommand::printPlan(CliContext& context, const RestorePlan& plan, bool report)
{
    QTextStream& out = context.out();
    const int differ = plan.count(Item::Action::Write);
    const int settings = int(plan.items.size()) - plan.count(Item::Action::Store);
    if (!plan.deviceRead) {
        // Nothing was compared: "0 of 69 settings differ" would claim the opposite.
        out << tr("%1: the drive's settings were not read; nothing compared, nothing written")
                   .arg(plan.title)
            << '\n';
        if (!plan.reason.isEmpty())
            out << plan.reason << '\n';
        for (const QString& note : plan.notes)
            out << tr("note: %1").arg(note) << '\n';
        out.flush();
        return;
    }
    out << trn("%1: %n of %2 settings differ", differ).arg(plan.title).arg(settings) << '\n';
    TextTable table({tr("parameter"), tr("file value"), tr("device value"),
                     report ? tr("result") : tr("action")});
    for (const Item& item : plan.items) {
        if (item.status == Item::Status::Unchanged)
            continue;
        table.addRow(
            {item.parameter, item.fileText, item.deviceText,
             report ? RestorePlan::statusText(item) : RestorePlan::actionText(item.action)});
    }
    if (table.rowCount() > 0)
        table.print(out);
    if (report) {
        int stored = 0;
        for (const Item& item : plan.items)
            stored += item.action == Item::Action::Store && item.status == Item::Status::Verified;
        out << tr("%1 written and verified, %2 unchanged, %3 failed, %4 not attempted")
                   .arg(plan.count(Item::Status::Verified) - stored)
                   .arg(plan.count(Item::Status::Unchanged))
                   .arg(plan.count(Item::Status::Failed))
                   .arg(plan.count(Item::Status::NotAttempted));
        if (plan.count(Item::Status::NotConfirmed) > 0)
            out << tr(", %1 not confirmed").arg(plan.count(Item::Status::NotConfirmed));
        if (plan.count(Item::Action::Store) > 0)
            out << tr("; %1 of %2 store commands written")
                       .arg(stored)
                       .arg(plan.count(Item::Action::Store));
        out << '\n';
    } else {
        out << trn("%n setting(s) already equal", plan.count(Item::Action::Keep)) << '\n';
    }
    if (!plan.reason.isEmpty())
        out << plan.reason << '\n';
    for (const QString& note : plan.notes)
        out << tr("note: %1").arg(note) << '\n';
    out.flush();
}

int RestoreCommand::exitCodeOf(const RestorePlan& plan)
{
    switch (plan.outcome) {
    case RestorePlan::Outcome::Planned:
    case RestorePlan::Outcome::Done:
        return ExitOk;
    case RestorePlan::Outcome::Refused:
        return ExitInvalid;
    case RestorePlan::Outcome::Communication:
        return ExitCommunication;
    case RestorePlan::Outcome::Mismatch:
        return ExitMismatch;
    case RestorePlan::Outcome::Interrupted:
        return ExitInterrupted;
    }
    return ExitCommunication;
}

int RestoreCommand::run(CliContext& context, const QStringList& args)
{
    if (args.size() != 1) {
        context.err() << tr("error: name one backup file: restore FILE [--ids LIST] [--yes]")
                      << Qt::endl;
        return ExitUsage;
    }
    int code = ExitOk;
    const std::optional<BackupFile> file = FileCommandSupport::load(context, args.first(), &code);
    if (!file)
        return code;
    QVector<int> ids = file->slaves();
    if (context.parser().isSet(QStringLiteral("ids"))) {
        QString error;
        const auto chosen =
            CliContext::parseIds(context.parser().value(QStringLiteral("ids")), &error);
        if (!chosen) {
            context.err() << tr("error: --ids: %1").arg(error) << Qt::endl;
            return ExitUsage;
        }
        for (int id : *chosen) {
            if (!file->device(id)) {
                context.err() << tr("error: %1 holds no drive with machine number %2; it holds %3")
                                     .arg(args.first())
                                     .arg(id)
                                     .arg(FileCommandSupport::idList(file->slaves()))
                              << Qt::endl;
                return ExitUsage;
            }
        }
        ids = *chosen;
    }
    const bool yes = context.parser().isSet(QStringLiteral("yes"));
    const bool dryRun = context.parser().isSet(QStringLiteral("dry-run")) || !yes;
    if (!context.connectBus())
        return ExitCommunication;

    // Every drive is checked before any is written: a refused file writes nothing at all.
    QVector<DeviceSession*> sessions;
    QJsonArray drives;
    bool refused = false;
    for (int id : ids) {
        QString error;
        DeviceSession* session = context.session(id, &error);
        if (!session) {
            context.err() << tr("error: %1; nothing written").arg(error) << Qt::endl;
            return ExitCommunication;
        }
        const RestorePlan check =
            RestorePlan::check(session->profile(), session->variant(), *file->device(id));
        if (check.refused()) {
            refused = true;
            drives << FileCommandSupport::planJson(check);
            context.err() << tr("error: %1: %2").arg(check.title, check.reason) << Qt::endl;
            for (const QString& problem : check.problems)
                context.err() << "  " << problem << Qt::endl;
        }
        // Every write to a group parent is executed by its children too: say so (--yes is
        // what makes a restore write at all).
        GroupCheck group(context);
        if (const int bad = group.before(id, true, ExitInvalid); bad != ExitOk)
            return bad;
        sessions << session;
    }
    if (refused) {
        if (context.json())
            FileCommandSupport::printJson(context,
                                          {{QStringLiteral("command"), QStringLiteral("restore")},
                                           {QStringLiteral("written"), false},
                                           {QStringLiteral("drives"), drives}});
        return ExitInvalid;
    }

    code = ExitOk;
    for (int i = 0; i < ids.size(); ++i) {
        const BackupDevice& device = *file->device(ids.at(i));
        if (code == ExitCommunication || code == ExitInterrupted) {
            // The bus failed or the user stopped: later drives are left alone, and said so.
            RestorePlan skipped;
            skipped.slave = device.slave;
            skipped.title = device.title();
            skipped.outcome = RestorePlan::Outcome::Interrupted;
            skipped.reason = tr("not attempted");
            drives << FileCommandSupport::planJson(skipped);
            if (!context.json())
                context.out() << tr("%1: not attempted").arg(device.title()) << Qt::endl;
            continue;
        }
        const RestorePlan plan = restore(context, sessions.at(i), device, dryRun);
        drives << FileCommandSupport::planJson(plan);
        if (!context.json())
            printPlan(context, plan, !dryRun && !plan.refused());
        // The most serious outcome of any drive decides.
        static const QVector<int> severity{ExitOk, ExitInvalid, ExitMismatch, ExitCommunication,
                                           ExitInterrupted};
        const int driveCode = exitCodeOf(plan);
        if (severity.indexOf(driveCode) > severity.indexOf(code))
            code = driveCode;
    }
    if (context.json()) {
        FileCommandSupport::printJson(context,
                                      {{QStringLiteral("command"), QStringLiteral("restore")},
                                       {QStringLiteral("dryRun"), dryRun},
                                       {QStringLiteral("written"), !dryRun},
                                       {QStringLiteral("drives"), drives}});
    } else if (dryRun) {
        context.out() << (context.parser().isSet(QStringLiteral("dry-run"))
                              ? tr("dry run: nothing written")
                              : tr("nothing written; add --yes to write"))
                      << Qt::endl;
    }
    return code;
}

} // namespace opentop
