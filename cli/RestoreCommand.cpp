#include "cli/RestoreCommand.h"

#include "cli/CliContext.h"
#include "cli/ExitCode.h"
#include "cli/FileCommandSupport.h"
#include "cli/GroupCheck.h"
#include "cli/TextTable.h"
#include "model/files/BusRestore.h"
#include "model/io/DisplayText.h"
#include "model/session/DeviceSession.h"

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
            out << DisplayText::escapedLines(plan.reason) << '\n';
        for (const QString& note : plan.notes)
            out << tr("note: %1").arg(DisplayText::escapedLines(note)) << '\n';
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
        out << DisplayText::escapedLines(plan.reason) << '\n';
    for (const QString& note : plan.notes)
        out << tr("note: %1").arg(DisplayText::escapedLines(note)) << '\n';
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
            context.err() << tr("error: --ids: %1").arg(DisplayText::escapedLines(error))
                          << Qt::endl;
            return ExitUsage;
        }
        for (int id : *chosen) {
            if (!file->device(id)) {
                context.err() << tr("error: %1 holds no drive with machine number %2; it holds %3")
                                     .arg(DisplayText::escaped(args.first()))
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

    // Every write to a group parent is executed by its children too: say so (--yes is what
    // makes a restore write at all).
    QVector<BusRestore::Job> jobs;
    for (int id : ids) {
        QString error;
        if (!context.session(id, &error)) {
            context.err() << tr("error: %1; nothing written").arg(DisplayText::escapedLines(error))
                          << Qt::endl;
            return ExitCommunication;
        }
        GroupCheck group(context);
        if (const int bad = group.before(id, true, ExitInvalid); bad != ExitOk)
            return bad;
        jobs.append({id, *file->device(id)});
    }
    BusRestore restore([&context](int id) {
        QString ignored;
        return context.session(id, &ignored);
    });
    // Every drive is checked before any is written: a refused file writes nothing at all.
    QJsonArray drives;
    const QVector<RestorePlan> refusals = restore.check(jobs);
    if (!refusals.isEmpty()) {
        for (const RestorePlan& check : refusals) {
            drives << FileCommandSupport::planJson(check);
            context.err() << tr("error: %1: %2")
                                 .arg(DisplayText::escaped(check.title),
                                      DisplayText::escapedLines(check.reason))
                          << Qt::endl;
            for (const QString& problem : check.problems)
                context.err() << "  " << DisplayText::escapedLines(problem) << Qt::endl;
        }
        if (context.json())
            FileCommandSupport::printJson(context,
                                          {{QStringLiteral("command"), QStringLiteral("restore")},
                                           {QStringLiteral("written"), false},
                                           {QStringLiteral("drives"), drives}});
        return ExitInvalid;
    }

    QObject::connect(&restore, &BusRestore::driveFinished, &restore,
                     [&context, &drives, dryRun](const RestorePlan& plan) {
                         drives << FileCommandSupport::planJson(plan);
                         if (context.json())
                             return;
                         if (!plan.attempted)
                             context.out() << tr("%1: not attempted").arg(plan.title) << Qt::endl;
                         else
                             printPlan(context, plan, !dryRun && !plan.refused());
                     });
    QVector<RestorePlan> plans;
    QEventLoop loop;
    // Ctrl-C cancels between transactions; the restore then reports what it did.
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&restore, &context] {
        if (context.interrupted())
            restore.cancel();
    });
    poll.start(50);
    restore.start(jobs, dryRun, [&plans, &loop](const QVector<RestorePlan>& p) {
        plans = p;
        loop.quit();
    });
    loop.exec();
    RestorePlan worst;
    worst.outcome = BusRestore::worst(plans);
    code = exitCodeOf(worst);
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
