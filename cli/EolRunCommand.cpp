#include "cli/EolRunCommand.h"

#include "cli/CliContext.h"
#include "cli/CliIdentity.h"
#include "cli/EolRunIdentity.h"
#include "cli/EolRunOutput.h"
#include "cli/EolSupport.h"
#include "cli/ExitCode.h"
#include "model/eol/EolRun.h"
#include "model/eol/Recipe.h"
#include "model/eol/RecipeChecker.h"
#include "model/eol/RecipeFile.h"
#include "model/eol/ResultWriter.h"
#include "model/eol/RetestPolicy.h"
#include "model/eol/SerialRule.h"
#include "model/eol/StationSafeState.h"
#include "model/eol/UnitValuesCsv.h"
#include "model/io/DisplayText.h"
#include "model/io/SystemUser.h"
#include "model/profile/ProfileRegistry.h"
#include "model/station/UnitStartGate.h"
#include "transport/ModbusClient.h"

#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QHostInfo>
#include <QTimer>
#include <memory>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolRunCommand", text);
}

const QString kSerial = QStringLiteral("serial");
const QString kOperator = QStringLiteral("operator");
const QString kStation = QStringLiteral("station");
const QString kDb = QStringLiteral("db");
const QString kUnits = QStringLiteral("units");
const QString kValue = QStringLiteral("value");
const QString kRetest = QStringLiteral("retest");

} // namespace

QString EolRunCommand::synopsis() const
{
    return QStringLiteral(
        "run RECIPE --serial S [--user NAME | --operator O] [--station NAME] [--db URL] "
        "[--units CSV] [--value ID:NAME=VALUE]... [--variant VARIANT|ID=VARIANT,...] [--retest]");
}

QString EolRunCommand::summary() const
{
    return tr("Set up and test one unit at the end of the line; record the result");
}

QList<QCommandLineOption> EolRunCommand::options() const
{
    return {
        {kSerial, tr("The unit's serial number (as its barcode reads)."), tr("S")},
        {kOperator, tr("Who tests it, on a station without users (default: the login name)."),
         tr("NAME")},
        CliIdentity::userOption(),
        {kStation, tr("This station's name (default: the host name)."), tr("NAME")},
        {kDb, tr("Results database: an SQLite file or postgresql://user@host/db."), tr("URL")},
        {kUnits, tr("CSV file with the per-unit values, by serial number."), tr("CSV")},
        {kValue, tr("A per-unit value typed by the operator, e.g. 1:spno3.speed=1500."),
         tr("ID:NAME=VALUE")},
        {kRetest,
         tr("A technician allows a retest the recipe's rules hold back (a serial that passed "
            "already, or its attempts used up).")},
    };
}

std::optional<QHash<int, QHash<QString, double>>> EolRunCommand::unitValues(CliContext& context,
                                                                            const Recipe& recipe,
                                                                            const QString& serial,
                                                                            QString* error)
{
    QHash<int, QHash<QString, double>> values;
    const QCommandLineParser& parser = context.parser();
    if (parser.isSet(kUnits)) {
        const std::optional<UnitValuesCsv> csv = UnitValuesCsv::load(parser.value(kUnits), error);
        if (!csv)
            return std::nullopt;
        const auto found = csv->valuesFor(recipe, ProfileRegistry::builtIn(), serial, error);
        if (!found)
            return std::nullopt;
        for (const UnitValuesCsv::Value& v : *found)
            values[v.machineNumber][v.parameter] = v.value;
    }
    const RecipeChecker checker(ProfileRegistry::builtIn());
    for (const QString& item : parser.values(kValue)) {
        // ID:NAME=VALUE
        const int colon = item.indexOf(QLatin1Char(':'));
        const int equals = item.indexOf(QLatin1Char('='), colon + 1);
        bool idOk = false;
        bool valueOk = false;
        const int id = item.left(colon).toInt(&idOk);
        const QString name = item.mid(colon + 1, equals - colon - 1).trimmed();
        const double value = item.mid(equals + 1).toDouble(&valueOk);
        if (colon < 1 || equals < 0 || !idOk || name.isEmpty() || !valueOk) {
            *error =
                tr("--value %1: write it as MACHINE:NAME=VALUE, e.g. 1:spno3.speed=1500").arg(item);
            return std::nullopt;
        }
        const QString why = checker.checkUnitValue(recipe, id, name, value);
        if (!why.isEmpty()) {
            *error = tr("--value %1: %2").arg(item, why);
            return std::nullopt;
        }
        values[id][name] = value;
    }
    return values;
}

std::optional<QHash<int, QString>>
EolRunCommand::assertedVariants(CliContext& context, const Recipe& recipe, QString* error)
{
    // --variant states what the drives of this unit are: taken as confirmed by the operator
    // when a drive cannot prove its own, refused when it proves another; never outside the
    // recipe.
    QHash<int, QString> asserted;
    const QString given = context.parser().value(QStringLiteral("variant"));
    for (int i = 0; i < recipe.positions.size(); ++i) {
        const RecipePosition& p = recipe.positions[i];
        const std::optional<QString> variant = context.givenVariant(p.machineNumber, p.family);
        if (!variant)
            continue;
        const QString where = Recipe::positionText(i, p.machineNumber);
        if (variant->isEmpty() || (!p.variants.isEmpty() && !p.variants.contains(*variant))) {
            *error = tr("--variant %1: %2 allows %3; nothing was sent")
                         .arg(given, where,
                              p.variants.isEmpty() ? tr("any %1 variant").arg(p.family)
                                                   : p.variants.join(QStringLiteral(", ")));
            return std::nullopt;
        }
        asserted.insert(p.machineNumber, *variant);
    }
    for (const QString& item : given.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const int eq = item.indexOf(QLatin1Char('='));
        if (eq >= 0 && !recipe.position(item.left(eq).trimmed().toInt())) {
            *error = tr("--variant %1: the recipe has no position at machine number %2; nothing "
                        "was sent")
                         .arg(given, item.left(eq).trimmed());
            return std::nullopt;
        }
    }
    return asserted;
}

int EolRunCommand::run(CliContext& context, const QStringList& args)
{
    QTextStream& err = context.err();
    const QCommandLineParser& parser = context.parser();
    if (args.size() != 1 || !parser.isSet(kSerial) || parser.value(kSerial).trimmed().isEmpty()) {
        err << tr("usage: opentop-cli eol %1").arg(synopsis()) << Qt::endl;
        return ExitUsage;
    }
    // Exactly as given: SerialRule refuses "SN1 " rather than testing it as "SN1".
    const QString serial = parser.value(kSerial);
    QString error;
    int code = ExitOk;
    const std::optional<EolSupport::LoadedRecipe> loaded =
        EolSupport::loadRecipe(context, args.first(), false, &code);
    if (!loaded)
        return code;
    const Recipe* recipe = &loaded->recipe;
    const QString checksum = loaded->checksum;
    const QVector<RecipeProblem> problems =
        RecipeChecker(ProfileRegistry::builtIn()).check(*recipe);
    if (!problems.isEmpty()) {
        err << tr("%1: the recipe is not valid; nothing was sent:")
                   .arg(DisplayText::escaped(args.first()))
            << '\n';
        EolSupport::printProblems(context, problems);
        err.flush();
        return ExitInvalid;
    }
    // Before the database is opened or the bus touched: a refused serial is recorded nowhere.
    const QString badSerial = SerialRule::problem(serial, *recipe);
    if (!badSerial.isEmpty()) {
        err << tr("--serial: %1; nothing was sent").arg(badSerial) << Qt::endl;
        return ExitInvalid;
    }
    const auto values = unitValues(context, *recipe, serial, &error);
    if (!values) {
        err << DisplayText::escapedLines(error) << Qt::endl;
        return ExitInvalid;
    }
    const auto asserted = assertedVariants(context, *recipe, &error);
    if (!asserted) {
        err << DisplayText::escapedLines(error) << Qt::endl;
        return ExitUsage;
    }

    // As `eol results` reads it; the default file and its folder are made when missing.
    QString url = parser.value(kDb);
    if (url.isEmpty())
        url = qEnvironmentVariable("OPENTOP_EOL_DB");
    if (url.isEmpty()) {
        url = EolSupport::defaultDatabase();
        QDir().mkpath(QFileInfo(url).absolutePath());
    }
    const QString station =
        parser.isSet(kStation) ? parser.value(kStation) : QHostInfo::localHostName();
    // The station's writer, as the operator screen's; what this station left running when it
    // was killed is never a pass: marked interrupted as it opens.
    ResultWriter writer;
    const ResultWriter::Opened opened = writer.openAndWait(url, station);
    if (!opened.ok) {
        err << tr("results database: %1; nothing was sent")
                   .arg(DisplayText::escapedLines(opened.error))
            << Qt::endl;
        return ExitCommunication;
    }
    for (const StationLease::Leftover& left : opened.interrupted)
        err << tr("note: unit %1 (begun %2) was left unfinished by a station process that is "
                  "gone; it is now recorded as interrupted. Check that its motor is stopped.")
                   .arg(DisplayText::escaped(left.serial), left.started)
            << Qt::endl;
    if (opened.waiting > 0)
        err << tr("note: %1 result(s) kept on this station could not be sent to the results "
                  "database yet")
                   .arg(opened.waiting)
            << Qt::endl;

    // On a managed station (the database has users) only a user who may test units, with a
    // recipe whose checksum is approved; checked before anything is sent.
    const std::optional<EolRunIdentity> identity =
        EolRunIdentity::check(context, writer, station, *recipe, checksum, &code);
    if (!identity)
        return code;

    // The operator screen's gate: the recipe's retest rules on the serial's recorded verdicts
    // before anything is sent (a technician allows a held retest with --retest), then the bus
    // and the recipe's positions made safe (a station killed mid-test may have left a motor
    // turning in communication priority), then the unit begun. This only says what it decides.
    UnitStartGate gate(ProfileRegistry::builtIn());
    UnitStartGate::Unit unit;
    unit.recipe = *recipe;
    unit.technicianAllows = parser.isSet(kRetest);
    EolRun::Options& options = unit.options;
    options.serial = serial;
    options.station = station;
    options.operatorName = identity->user.isEmpty() ? parser.value(kOperator) : identity->user;
    options.approvalId = identity->approvalId;
    options.approver = identity->approver;
    if (options.operatorName.isEmpty())
        options.operatorName = SystemUser::loginName();
    options.recipeChecksum = checksum;
    options.unitValues = *values;
    options.assertedVariants = *asserted;
    options.writer = &writer;
    options.traffic = context.trafficLog();
    std::optional<bool> connected;
    unit.client = [&]() -> ModbusClient* {
        if (!connected)
            connected = context.connectBus();
        return *connected ? context.client() : nullptr;
    };
    unit.retestPassed = [&](const RetestPolicy::Decision& d) {
        if (d.kind == RetestPolicy::Decision::Kind::NeedsTechnician)
            err << tr("note: %1; tested again as --retest allows")
                       .arg(DisplayText::escapedLines(d.reason))
                << Qt::endl;
        else if (!d.reason.isEmpty())
            err << tr("note: %1").arg(DisplayText::escapedLines(d.reason)) << Qt::endl;
    };
    QObject::connect(&gate, &UnitStartGate::safetyChanged, &gate, [&] {
        if (gate.isMakingSafe())
            return;
        for (const PositionSafety& p : gate.safety()) {
            if (p.worthSaying())
                err << tr("station: %1").arg(DisplayText::escapedLines(p.summary())) << Qt::endl;
        }
    });

    std::unique_ptr<EolRun> eol;
    bool lost = false;
    UnitRecord record;
    QEventLoop loop;
    QTimer interrupt;
    bool interrupted = false;
    unit.made = [&](EolRun* run, ModbusClient* client) {
        eol.reset(run);
        EolRunOutput::follow(context, run, client, &lost);
        // Ctrl-C (or SIGTERM from a line controller) cancels: motors stopped, recorded as
        // aborted.
        QObject::connect(&interrupt, &QTimer::timeout, &loop, [&] {
            if (context.interrupted() && !interrupted) {
                interrupted = true;
                eol->cancel(tr("interrupted at the station"));
            }
        });
        interrupt.start(50);
    };
    unit.finished = [&](const UnitRecord& r) {
        record = r;
        loop.quit();
    };
    UnitStartGate::Outcome outcome;
    gate.start(unit, [&](const UnitStartGate::Outcome& o) {
        outcome = o;
        if (o.kind != UnitStartGate::Outcome::Kind::Begun)
            loop.quit();
    });
    loop.exec();
    switch (outcome.kind) {
    case UnitStartGate::Outcome::Kind::RetestRefused:
    case UnitStartGate::Outcome::Kind::NeedsTechnician:
        err << tr("error: %1; nothing was sent").arg(DisplayText::escapedLines(outcome.message))
            << Qt::endl;
        if (outcome.kind == UnitStartGate::Outcome::Kind::NeedsTechnician)
            err << tr("a technician allows it with --retest") << Qt::endl;
        return ExitInvalid;
    case UnitStartGate::Outcome::Kind::NotConnected:
    case UnitStartGate::Outcome::Kind::Cancelled: // never here: nothing cancels it
        return context.usageError() ? ExitUsage : ExitCommunication;
    case UnitStartGate::Outcome::Kind::Unsafe: // the operator screen's rule
        err << tr("a drive of the station is not confirmed stopped; nothing was tested")
            << Qt::endl;
        return ExitMismatch;
    case UnitStartGate::Outcome::Kind::Begun:
        break;
    }

    EolRunOutput::verdict(context, *eol, record, *recipe, writer.spoolPath());
    if (!eol->unconfirmedStops().isEmpty())
        return ExitMismatch;
    if (!eol->storeError().isEmpty())
        return ExitCommunication;
    switch (record.status) {
    case UnitStatus::Pass:
        return ExitOk;
    case UnitStatus::Fail:
        return ExitFail;
    case UnitStatus::Error:
        return lost ? ExitCommunication : ExitStation;
    default:
        break;
    }
    if (lost)
        return ExitCommunication;
    return interrupted ? ExitInterrupted : ExitCommunication;
}

} // namespace opentop
