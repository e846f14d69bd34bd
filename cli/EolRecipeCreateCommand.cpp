#include "cli/EolRecipeCreateCommand.h"

#include "cli/CliContext.h"
#include "cli/EolSupport.h"
#include "cli/ExitCode.h"
#include "cli/FileCommandSupport.h"
#include "model/eol/GoldenMeasure.h"
#include "model/eol/RecipeBuilder.h"
#include "model/eol/RecipeFile.h"
#include "model/eol/RecipeFromDrives.h"
#include "model/io/DisplayText.h"
#include "model/io/OutputFile.h"
#include "model/profile/Profile.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceInfo.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QTimer>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolRecipeCreateCommand", text);
}

} // namespace

QString EolRecipeCreateCommand::summary() const
{
    return tr("Make a recipe from a golden unit: a backup file or drives on the bus");
}

QList<QCommandLineOption> EolRecipeCreateCommand::options() const
{
    return {
        {QStringLiteral("from-backup"), tr("recipe create: the golden unit's backup file."),
         tr("FILE")},
        {QStringLiteral("drives"),
         tr("recipe create: the golden unit's drives on the bus, e.g. 1,2 (with the connection "
            "options)."),
         tr("LIST")},
        {QStringLiteral("product"), tr("recipe create: the product's name."), tr("NAME")},
        {QStringLiteral("revision"), tr("recipe create: the recipe's revision."), tr("REV")},
        EolSupport::outputOption(),
        {QStringLiteral("force"), tr("recipe create: replace an existing recipe file.")},
        {QStringLiteral("measure"),
         tr("recipe create --drives: run the golden unit through the recipe's steps once (its "
            "motors turn) and take the hold limits from what it measured.")},
        {QStringLiteral("margin"),
         tr("recipe create --measure: the margin around a measured value, in % of it (default "
            "25; at least 5 % of the parameter's full scale)."),
         tr("PERCENT")},
        {QStringLiteral("yes"), tr("recipe create --measure: run the motors.")},
    };
}

std::optional<Recipe> EolRecipeCreateCommand::readGolden(CliContext& context,
                                                         const QVector<int>& ids,
                                                         const QString& product,
                                                         const QString& revision, int* exitCode)
{
    QVector<RecipeFromDrives::Golden> golden;
    for (int id : ids) {
        QString error;
        DeviceSession* session = context.session(id, &error);
        if (!session) {
            context.err() << tr("error: %1; nothing written").arg(DisplayText::escapedLines(error))
                          << Qt::endl;
            *exitCode = ExitCommunication;
            return std::nullopt;
        }
        golden.append({id,
                       RecipeFromDrives::reportedVariant(session->profile(), context.identify(id)),
                       context.givenVariant(id, session->profile().family).value_or(QString())});
    }
    RecipeFromDrives make(
        context.client(), ProfileRegistry::builtIn(),
        [&context](int id, QString* error) { return context.session(id, error); });
    QObject::connect(&make, &RecipeFromDrives::driveRead, &make,
                     [&context](const DriveBatchReader::Drive& d) {
                         if (d.ok() && !context.json())
                             context.out() << tr("%1: %2 settings read")
                                                  .arg(DisplayText::escaped(d.read.device.title()))
                                                  .arg(d.read.parameters)
                                           << Qt::endl;
                     });
    RecipeFromDrives::Result result;
    const bool completed = context.wait([&](std::function<void()> finish) {
        make.start(golden, product, revision, qEnvironmentVariable("USER"),
                   [&result, finish](const RecipeFromDrives::Result& r) {
                       result = r;
                       finish();
                   });
    });
    if (!completed) {
        make.cancel();
        context.err() << tr("interrupted while reading the golden unit: nothing written")
                      << Qt::endl;
        *exitCode = ExitInterrupted;
        return std::nullopt;
    }
    for (const QString& line : result.variants)
        context.err() << tr("note: %1").arg(DisplayText::escapedLines(line)) << Qt::endl;
    if (!result.recipe) {
        for (const QString& problem : result.problems)
            context.err() << tr("error: %1").arg(DisplayText::escapedLines(problem)) << Qt::endl;
        for (int id : result.unknownVariants)
            context.err() << tr("give its variant with --variant %1=VARIANT").arg(id) << Qt::endl;
        context.err() << tr("nothing written") << Qt::endl;
        *exitCode = result.failure == RecipeFromDrives::Failure::Communication ? ExitCommunication
                    : result.failure == RecipeFromDrives::Failure::Cancelled   ? ExitInterrupted
                                                                               : ExitInvalid;
        return std::nullopt;
    }
    return result.recipe;
}

bool EolRecipeCreateCommand::measure(CliContext& context, Recipe* recipe, double margin,
                                     int* exitCode, QJsonArray* limits)
{
    QTextStream& err = context.err();
    const QStringList motion = GoldenMeasure::motionText(*recipe);
    if (!context.parser().isSet(QStringLiteral("yes"))) {
        err << tr("Would run the golden unit through the recipe's steps:") << Qt::endl;
        for (const QString& line : motion)
            err << QStringLiteral("  ") << DisplayText::escapedLines(line) << Qt::endl;
        err << tr("This turns motors: add --yes to run them. Nothing was run; nothing written.")
            << Qt::endl;
        *exitCode = ExitUsage;
        return false;
    }
    err << tr("measuring the golden unit (Ctrl-C stops every motor):") << Qt::endl;
    for (const QString& line : motion)
        err << QStringLiteral("  ") << DisplayText::escapedLines(line) << Qt::endl;
    GoldenLimits::Margin m;
    m.relative = margin / 100.0;
    GoldenMeasure run(context.client(), ProfileRegistry::builtIn(), *recipe, m);
    QObject::connect(
        &run, &GoldenMeasure::phaseChanged, &run,
        [&err](int machineNumber, EolDriveRun::Phase, const QString& text) {
            err << tr("drive %1: %2").arg(machineNumber).arg(DisplayText::escapedLines(text))
                << Qt::endl;
        });
    QObject::connect(context.client(), &ModbusClient::connectionLost, &run,
                     [&run](const QString& why) { run.connectionLost(why); });
    GoldenMeasure::Outcome outcome;
    QEventLoop loop;
    QTimer interrupt;
    bool interrupted = false;
    QObject::connect(&interrupt, &QTimer::timeout, &loop, [&] {
        if (context.interrupted() && !interrupted) {
            interrupted = true;
            run.cancel(tr("interrupted"));
        }
    });
    interrupt.start(50);
    bool finished = false;
    run.start(EolStepRunner::Timing(), [&](const GoldenMeasure::Outcome& o) {
        outcome = o;
        finished = true;
        loop.quit();
    });
    if (!finished)
        loop.exec();
    for (const QString& d : outcome.unconfirmedStops)
        err << tr("WARNING: %1 is not confirmed stopped").arg(DisplayText::escaped(d)) << Qt::endl;
    if (!outcome.ok) {
        err << tr("error: %1; nothing written").arg(DisplayText::escapedLines(outcome.error))
            << Qt::endl;
        *exitCode = interrupted                                 ? ExitInterrupted
                    : outcome.record.status == UnitStatus::Fail ? ExitFail
                                                                : ExitCommunication;
        return false;
    }
    if (!context.json())
        context.out() << tr("limits from the golden unit:") << Qt::endl;
    auto bound = [](const std::optional<double>& v) { return v ? QJsonValue(*v) : QJsonValue(); };
    for (const GoldenLimits::Change& c : outcome.limits.changes) {
        if (!context.json())
            context.out() << tr("  drive %1, step %2: %3")
                                 .arg(c.machineNumber)
                                 .arg(c.step + 1)
                                 .arg(DisplayText::escaped(GoldenLimits::changeText(c)))
                          << Qt::endl;
        limits->append(QJsonObject{{QStringLiteral("machineNumber"), c.machineNumber},
                                   {QStringLiteral("step"), c.step + 1},
                                   {QStringLiteral("quantity"), c.quantity},
                                   {QStringLiteral("measured"), c.measured},
                                   {QStringLiteral("unit"), c.unit},
                                   {QStringLiteral("lower"), bound(c.after.lower)},
                                   {QStringLiteral("upper"), bound(c.after.upper)},
                                   {QStringLiteral("defaultLower"), bound(c.before.lower)},
                                   {QStringLiteral("defaultUpper"), bound(c.before.upper)}});
    }
    *recipe = outcome.limits.recipe;
    return true;
}

int EolRecipeCreateCommand::run(CliContext& context, const QStringList& args)
{
    const QCommandLineParser& parser = context.parser();
    auto usage = [&](const QString& problem) {
        context.err()
            << tr("error: %1; usage: eol %2").arg(DisplayText::escapedLines(problem), synopsis())
            << Qt::endl;
        return ExitUsage;
    };
    if (!args.isEmpty())
        return usage(tr("unexpected argument \"%1\"").arg(args.first()));
    const bool fromBackup = parser.isSet(QStringLiteral("from-backup"));
    const bool fromDrives = parser.isSet(QStringLiteral("drives"));
    if (fromBackup == fromDrives)
        return usage(tr("give either --from-backup FILE or --drives LIST"));
    const bool measuring = parser.isSet(QStringLiteral("measure"));
    if (measuring && !fromDrives)
        return usage(tr("--measure needs the golden unit on the bus: give --drives LIST"));
    double margin = 25;
    if (parser.isSet(QStringLiteral("margin"))) {
        bool ok = false;
        margin = parser.value(QStringLiteral("margin")).toDouble(&ok);
        if (!measuring)
            return usage(tr("--margin is for --measure"));
        if (!ok || margin < 1 || margin > 100)
            return usage(tr("--margin %1: give a percentage from 1 to 100")
                             .arg(parser.value(QStringLiteral("margin"))));
    }
    const QString product = parser.value(QStringLiteral("product")).trimmed();
    const QString revision = parser.value(QStringLiteral("revision")).trimmed();
    if (product.isEmpty())
        return usage(tr("give the product's name with --product NAME"));
    if (revision.isEmpty())
        return usage(tr("give the recipe's revision with --revision REV"));
    const QString path = parser.value(QStringLiteral("o"));
    if (path.isEmpty())
        return usage(tr("give the recipe file to write with -o RECIPE"));
    if (QFileInfo::exists(path) && !QFileInfo(path).isDir() &&
        !parser.isSet(QStringLiteral("force"))) {
        context.err()
            << tr("error: %1 exists; give --force to replace it").arg(DisplayText::escaped(path))
            << Qt::endl;
        return ExitUsage;
    }
    if (const QString problem = OutputFile::problem(path); !problem.isEmpty()) {
        context.err() << tr("error: %1; nothing read").arg(DisplayText::escapedLines(problem))
                      << Qt::endl;
        return ExitUsage;
    }

    const RecipeBuilder builder(ProfileRegistry::builtIn());
    QString error;
    std::optional<Recipe> recipe;
    int code = ExitOk;
    QJsonArray measured; // the limits --measure derived
    if (fromBackup) {
        const std::optional<BackupFile> file =
            FileCommandSupport::load(context, parser.value(QStringLiteral("from-backup")), &code);
        if (!file)
            return code;
        recipe = builder.fromBackup(*file, product, revision, &error);
    } else {
        const auto ids = CliContext::parseIds(parser.value(QStringLiteral("drives")), &error);
        if (!ids)
            return usage(tr("--drives %1: %2").arg(parser.value(QStringLiteral("drives")), error));
        if (!context.connectBus())
            return ExitCommunication;
        recipe = readGolden(context, *ids, product, revision, &code);
        if (!recipe)
            return code;
        if (recipe && measuring && !measure(context, &*recipe, margin, &code, &measured))
            return code;
    }
    if (!recipe) {
        context.err() << tr("error: %1; nothing written").arg(DisplayText::escapedLines(error))
                      << Qt::endl;
        return ExitInvalid;
    }

    const QVector<RecipeProblem> problems =
        RecipeChecker(ProfileRegistry::builtIn()).check(*recipe);
    if (!RecipeFile::save(*recipe, path, &error)) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitUsage;
    }
    if (context.json()) {
        FileCommandSupport::printJson(
            context, {{QStringLiteral("command"), QStringLiteral("eol recipe create")},
                      {QStringLiteral("file"), path},
                      {QStringLiteral("written"), true},
                      {QStringLiteral("product"), recipe->product},
                      {QStringLiteral("revision"), recipe->revision},
                      {QStringLiteral("checksum"), RecipeFile::checksumOf(*recipe)},
                      {QStringLiteral("positions"), int(recipe->positions.size())},
                      {QStringLiteral("settings"), EolSupport::settingCount(*recipe)},
                      {QStringLiteral("steps"), EolSupport::stepCount(*recipe)},
                      {QStringLiteral("valid"), problems.isEmpty()},
                      {QStringLiteral("measuredLimits"), measured},
                      {QStringLiteral("problems"), EolSupport::problemsJson(problems)}});
    } else {
        context.out() << tr("wrote %1: %2 revision %3, %4")
                             .arg(DisplayText::escaped(path), DisplayText::escaped(recipe->product),
                                  DisplayText::escaped(recipe->revision),
                                  EolSupport::countsText(*recipe))
                      << Qt::endl;
        EolSupport::printProblems(context, problems);
    }
    if (!problems.isEmpty()) {
        context.err() << tr("error: the recipe does not pass \"eol recipe check\": fix it, then "
                            "sign it with \"opentop-cli eol recipe sign %1\"")
                             .arg(DisplayText::escaped(path))
                      << Qt::endl;
        return ExitInvalid;
    }
    return ExitOk;
}

} // namespace opentop
