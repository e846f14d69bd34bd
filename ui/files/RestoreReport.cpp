#include "ui/files/RestoreReport.h"

#include "model/bus/DriveName.h"
#include "model/io/DisplayText.h"
#include "model/io/OutputFile.h"

#include <QDateTime>

namespace opentop {

using Item = RestorePlan::Item;

QString RestoreReport::summary(const RestorePlan& plan)
{
    int stored = 0;
    for (const Item& item : plan.items)
        stored += item.action == Item::Action::Store && item.status == Item::Status::Verified;
    QString text = tr("%1 written and verified, %2 unchanged, %3 failed, %4 not attempted")
                       .arg(plan.count(Item::Status::Verified) - stored)
                       .arg(plan.count(Item::Status::Unchanged))
                       .arg(plan.count(Item::Status::Failed))
                       .arg(plan.count(Item::Status::NotAttempted));
    if (plan.count(Item::Status::NotConfirmed) > 0)
        text += tr(", %1 not confirmed").arg(plan.count(Item::Status::NotConfirmed));
    if (plan.count(Item::Action::Store) > 0)
        text += tr("; %1 of %2 store commands written")
                    .arg(stored)
                    .arg(plan.count(Item::Action::Store));
    return text;
}

QString RestoreReport::text(const QString& file, const QVector<RestorePlan>& plans, bool written)
{
    QStringList lines;
    lines << tr("OpenTOP restore report") << tr("File: %1").arg(file)
          << tr("Date: %1 (UTC)")
                 .arg(QDateTime::currentDateTimeUtc().toString(
                     QStringLiteral("yyyy-MM-dd hh:mm:ss")))
          << (written ? tr("Written to the drives") : tr("Preview only: nothing written"));
    for (const RestorePlan& plan : plans) {
        lines << QString()
              << tr("Machine number %1 from %2: %3")
                     .arg(DriveName::listed(plan.slave, plan.machineName))
                     .arg(plan.title, RestorePlan::outcomeText(plan.outcome));
        if (!plan.reason.isEmpty())
            lines << QStringLiteral("  ") + plan.reason;
        for (const QString& problem : plan.problems)
            lines << QStringLiteral("  ") + problem;
        for (const Item& item : plan.items) {
            const QString result =
                written ? RestorePlan::statusText(item) : RestorePlan::actionText(item.action);
            if (item.action == Item::Action::Store)
                lines << tr("  %1: %2").arg(item.parameter, result);
            else
                lines << tr("  %1: file %2, drive %3: %4")
                             .arg(item.parameter, item.fileText, item.deviceText, result);
        }
        if (written && !plan.refused())
            lines << QStringLiteral("  ") + summary(plan);
        for (const QString& note : plan.notes)
            lines << tr("  Note: %1").arg(note);
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

QString RestoreReport::csv(const QVector<RestorePlan>& plans)
{
    // Values, names and reasons come from the file and the drives: made safe for a
    // spreadsheet (DisplayText::csvCell), then quoted.
    auto quote = [](const QString& cell) {
        QString s = DisplayText::csvCell(cell);
        s.replace(QLatin1Char('"'), QStringLiteral("\"\""));
        return QLatin1Char('"') + s + QLatin1Char('"');
    };
    // The machine's name last: the columns before it stay where readers of older reports find
    // them.
    QStringList lines{QStringLiteral("slave,drive,outcome,parameter,action,status,file,device,"
                                     "mismatch,error,name")};
    for (const RestorePlan& plan : plans) {
        const QString head = QStringLiteral("%1,%2,%3")
                                 .arg(plan.slave)
                                 .arg(quote(plan.title), RestorePlan::outcomeKey(plan.outcome));
        const QString name = QLatin1Char(',') + quote(plan.machineName);
        if (plan.items.isEmpty())
            lines << head + QStringLiteral(",,,,,,,") + quote(plan.reason) + name;
        for (const Item& item : plan.items)
            lines << QStringLiteral("%1,%2,%3,%4,%5,%6,%7,%8")
                             .arg(head, item.parameter, RestorePlan::actionText(item.action),
                                  RestorePlan::statusKey(item.status), quote(item.fileText),
                                  quote(item.deviceText),
                                  item.mismatch ? QStringLiteral("yes") : QString(),
                                  quote(item.error)) +
                         name;
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

bool RestoreReport::save(const QString& path, const QString& file,
                         const QVector<RestorePlan>& plans, bool written, QString* error)
{
    const bool asCsv = path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive);
    return OutputFile::write(path, (asCsv ? csv(plans) : text(file, plans, written)).toUtf8(),
                             error);
}

} // namespace opentop
