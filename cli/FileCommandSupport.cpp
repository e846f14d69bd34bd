#include "cli/FileCommandSupport.h"

#include "cli/CliContext.h"
#include "cli/ExitCode.h"
#include "model/io/DisplayText.h"
#include "model/profile/ProfileRegistry.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonDocument>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::FileCommandSupport", text);
}

} // namespace

std::optional<BackupFile> FileCommandSupport::load(CliContext& context, const QString& path,
                                                   int* exitCode)
{
    const QFileInfo info(path);
    QString problem;
    if (!info.exists())
        problem = tr("no such file");
    else if (info.isDir())
        problem = tr("is a directory; name a backup file");
    else if (!info.isFile())
        problem = tr("is not a regular file (a device, FIFO or socket); name a backup file");
    if (!problem.isEmpty()) {
        context.err() << tr("error: %1: %2").arg(DisplayText::escaped(path), problem) << Qt::endl;
        *exitCode = ExitUsage;
        return std::nullopt;
    }
    QString error;
    std::optional<BackupFile> file = BackupFile::load(path, ProfileRegistry::builtIn(), &error);
    if (!file) {
        // The parser's message may quote the file's text.
        context.err() << tr("error: %1 refused: %2")
                             .arg(DisplayText::escaped(path), DisplayText::escapedLines(error))
                      << Qt::endl;
        *exitCode = ExitInvalid;
    }
    return file;
}

void FileCommandSupport::printJson(CliContext& context, const QJsonObject& object)
{
    context.out() << QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Indented));
    context.out().flush();
}

QJsonArray FileCommandSupport::registersJson(const QVector<quint16>& registers)
{
    QJsonArray array;
    for (quint16 r : registers)
        array << int(r);
    return array;
}

QJsonObject FileCommandSupport::planJson(const RestorePlan& plan)
{
    QJsonArray items;
    for (const RestorePlan::Item& item : plan.items) {
        QJsonObject o{{QStringLiteral("parameter"), item.parameter},
                      {QStringLiteral("action"), RestorePlan::actionText(item.action)},
                      {QStringLiteral("status"), RestorePlan::statusKey(item.status)}};
        if (item.action != RestorePlan::Item::Action::Store) {
            o.insert(QStringLiteral("file"), item.fileText);
            o.insert(QStringLiteral("fileRegisters"), registersJson(item.fileRegisters));
            o.insert(QStringLiteral("device"), item.deviceText);
            o.insert(QStringLiteral("deviceRegisters"), registersJson(item.deviceRegisters));
        }
        if (!item.error.isEmpty())
            o.insert(QStringLiteral("error"), item.error);
        if (item.mismatch)
            o.insert(QStringLiteral("mismatch"), true);
        items << o;
    }
    using Status = RestorePlan::Item::Status;
    int stored = 0;
    for (const RestorePlan::Item& item : plan.items)
        stored +=
            item.action == RestorePlan::Item::Action::Store && item.status == Status::Verified;
    return QJsonObject{
        {QStringLiteral("slave"), plan.slave},
        {QStringLiteral("drive"), plan.title},
        {QStringLiteral("outcome"), RestorePlan::outcomeKey(plan.outcome)},
        {QStringLiteral("reason"), plan.reason},
        {QStringLiteral("deviceRead"), plan.deviceRead},
        {QStringLiteral("problems"), QJsonArray::fromStringList(plan.problems)},
        {QStringLiteral("notes"), QJsonArray::fromStringList(plan.notes)},
        {QStringLiteral("toWrite"), plan.count(RestorePlan::Item::Action::Write)},
        {QStringLiteral("unchanged"), plan.count(Status::Unchanged)},
        {QStringLiteral("verified"), plan.count(Status::Verified) - stored},
        {QStringLiteral("stored"), stored},
        {QStringLiteral("failed"), plan.count(Status::Failed)},
        {QStringLiteral("notAttempted"), plan.count(Status::NotAttempted)},
        {QStringLiteral("notConfirmed"), plan.count(Status::NotConfirmed)},
        {QStringLiteral("items"), items},
    };
}

QString FileCommandSupport::idList(const QVector<int>& ids)
{
    QStringList list;
    for (int id : ids)
        list << QString::number(id);
    return list.join(QStringLiteral(", "));
}

} // namespace opentop
