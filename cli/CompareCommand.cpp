#include "cli/CompareCommand.h"

#include "cli/CliContext.h"
#include "cli/ExitCode.h"
#include "cli/FileCommandSupport.h"
#include "cli/TextTable.h"
#include "model/bus/DriveName.h"
#include "model/files/Comparer.h"
#include "model/files/DriveBatchReader.h"
#include "model/io/DisplayText.h"
#include "model/profile/ProfileRegistry.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QRegularExpression>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::CompareCommand", text);
}

QString trn(const char* text, int n)
{
    return QCoreApplication::translate("opentop::CompareCommand", text, nullptr, n);
}

} // namespace

QString CompareCommand::summary() const
{
    return tr("Show the settings that differ; A, B: a machine number, FILE or FILE:ID (exit 0 "
              "whether or not they differ)");
}

QList<QCommandLineOption> CompareCommand::options() const
{
    return {{QStringLiteral("defaults"),
             tr("Compare A with the profile's factory defaults; settings the manual gives no "
                "default for are listed, never counted as differences.")}};
}

std::optional<CompareCommand::Side> CompareCommand::readDrive(CliContext& context, int slave,
                                                              int* code)
{
    *code = ExitCommunication;
    if (!context.connectBus())
        return std::nullopt;
    DriveBatchReader reader(
        [&context](int id, QString* error) { return context.session(id, error); });
    QVector<DriveBatchReader::Drive> drives;
    const bool completed = context.wait([&reader, &drives, slave](std::function<void()> finish) {
        reader.start({slave}, {}, [&drives, finish](const QVector<DriveBatchReader::Drive>& d) {
            drives = d;
            finish();
        });
    });
    if (!completed) {
        *code = ExitInterrupted;
        context.err() << tr("interrupted") << Qt::endl;
        return std::nullopt;
    }
    const DriveBatchReader::Drive drive = drives.value(0);
    if (!drive.error.isEmpty() || !drive.read.failures.isEmpty()) {
        for (const QString& problem : drive.problems())
            context.err() << tr("error: %1").arg(DisplayText::escapedLines(problem)) << Qt::endl;
        return std::nullopt;
    }
    const BackupReader::Result& result = drive.read;
    return Side{tr("drive %1").arg(DriveName::listed(slave, context.machineNames().value(slave))),
                result.device};
}

std::optional<CompareCommand::Side> CompareCommand::resolve(CliContext& context,
                                                            const QString& text, int* code)
{
    static const QRegularExpression number(QStringLiteral("^\\d+$"));
    static const QRegularExpression fileAndId(QStringLiteral("^(.+):(\\d+)$"));
    if (number.match(text).hasMatch() && !QFileInfo(text).isFile()) {
        QString error;
        const auto ids = CliContext::parseIds(text, &error);
        if (!ids) {
            context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
            *code = ExitUsage;
            return std::nullopt;
        }
        return readDrive(context, ids->first(), code);
    }
    QString path = text;
    int slave = 0;
    const QRegularExpressionMatch m = fileAndId.match(text);
    if (!QFileInfo(text).isFile() && m.hasMatch()) {
        path = m.captured(1);
        slave = m.captured(2).toInt();
    }
    const std::optional<BackupFile> file = FileCommandSupport::load(context, path, code);
    if (!file)
        return std::nullopt;
    if (slave == 0 && file->devices.size() == 1)
        slave = file->devices.first().slave;
    if (!file->device(slave)) {
        context.err() << (slave == 0 ? tr("error: %1 holds several drives (%2): name one as "
                                          "%1:ID")
                                           .arg(DisplayText::escaped(path),
                                                FileCommandSupport::idList(file->slaves()))
                                     : tr("error: %1 holds no drive with machine number %2; it "
                                          "holds %3")
                                           .arg(DisplayText::escaped(path))
                                           .arg(slave)
                                           .arg(FileCommandSupport::idList(file->slaves())))
                      << Qt::endl;
        *code = ExitUsage;
        return std::nullopt;
    }
    return Side{QStringLiteral("%1:%2").arg(path).arg(slave), *file->device(slave)};
}

int CompareCommand::run(CliContext& context, const QStringList& args)
{
    const bool defaults = context.parser().isSet(QStringLiteral("defaults"));
    if (args.size() != (defaults ? 1 : 2)) {
        context.err() << tr("error: compare A B, or compare A --defaults (A, B: a machine "
                            "number, FILE or FILE:ID)")
                      << Qt::endl;
        return ExitUsage;
    }
    int code = ExitOk;
    const std::optional<Side> a = resolve(context, args.at(0), &code);
    if (!a)
        return code;
    std::optional<Side> b;
    if (!defaults) {
        b = resolve(context, args.at(1), &code);
        if (!b)
            return code;
    }
    const Profile* profile = ProfileRegistry::builtIn().family(a->device.family);
    const Comparer::Result result = defaults ? Comparer::compareWithDefaults(*profile, a->device)
                                             : Comparer::compare(*profile, a->device, b->device);
    const QString bLabel = defaults ? tr("factory defaults") : b->label;
    if (!result.refusal.isEmpty()) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(result.refusal)) << Qt::endl;
        return ExitInvalid;
    }
    if (context.json()) {
        QJsonArray differences;
        for (const Comparer::Difference& d : result.differences)
            differences << QJsonObject{
                {QStringLiteral("parameter"), d.parameter},
                {QStringLiteral("label"), d.label},
                {QStringLiteral("a"), d.a},
                {QStringLiteral("b"), d.b},
                {QStringLiteral("aRegisters"), FileCommandSupport::registersJson(d.aRegisters)},
                {QStringLiteral("bRegisters"), FileCommandSupport::registersJson(d.bRegisters)}};
        FileCommandSupport::printJson(
            context, {{QStringLiteral("command"), QStringLiteral("compare")},
                      {QStringLiteral("a"), a->label},
                      {QStringLiteral("b"), bLabel},
                      {QStringLiteral("compared"), result.compared},
                      {QStringLiteral("count"), int(result.differences.size())},
                      {QStringLiteral("differences"), differences},
                      {QStringLiteral("noDefault"), QJsonArray::fromStringList(result.noDefault)},
                      {QStringLiteral("notes"), QJsonArray::fromStringList(result.notes)}});
        return ExitOk;
    }
    QTextStream& out = context.out();
    // Labels name files; models come from them: shown escaped (DisplayText).
    out << tr("A: %1 (%2)")
               .arg(DisplayText::escaped(a->label), DisplayText::escaped(a->device.model))
        << '\n'
        << tr("B: %1").arg(DisplayText::escaped(bLabel))
        << (defaults ? QString()
                     : QStringLiteral(" (%1)").arg(DisplayText::escaped(b->device.model)))
        << '\n';
    if (!result.differences.isEmpty()) {
        TextTable table({tr("parameter"), tr("A"), tr("B")});
        for (const Comparer::Difference& d : result.differences)
            table.addRow({d.parameter, d.a.isEmpty() ? tr("(not held)") : d.a,
                          d.b.isEmpty() ? tr("(not held)") : d.b});
        table.print(out);
        out << trn("%n difference(s)", int(result.differences.size()))
            << tr(" in %1 settings compared").arg(result.compared) << '\n';
    } else {
        out << tr("no differences (%1 settings compared)").arg(result.compared) << '\n';
    }
    if (!result.noDefault.isEmpty())
        out << trn("%n setting(s) with no factory default documented: ",
                   int(result.noDefault.size()))
            << DisplayText::escaped(result.noDefault.join(QStringLiteral(", "))) << '\n';
    for (const QString& note : result.notes)
        out << tr("note: %1").arg(DisplayText::escapedLines(note)) << '\n';
    out.flush();
    return ExitOk;
}

} // namespace opentop
