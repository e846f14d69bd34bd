#include "cli/EolSupport.h"

#include "cli/CliContext.h"
#include "cli/ExitCode.h"
#include "model/eol/RecipeFile.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultUrl.h"
#include "model/files/BackupFile.h"
#include "model/io/DisplayText.h"
#include "model/profile/Profile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

namespace opentop {

std::optional<EolSupport::LoadedRecipe>
EolSupport::recipeArgument(CliContext& context, const QStringList& args, const QString& usage,
                           bool allowUnsigned, int* exitCode)
{
    if (args.size() != 1) {
        context.err() << tr("error: name one recipe file; usage: eol %1").arg(usage) << Qt::endl;
        *exitCode = ExitUsage;
        return std::nullopt;
    }
    return loadRecipe(context, args.first(), allowUnsigned, exitCode);
}

std::optional<EolSupport::LoadedRecipe>
EolSupport::loadRecipe(CliContext& context, const QString& path, bool allowUnsigned, int* exitCode)
{
    const QFileInfo info(path);
    QString problem;
    if (!info.exists())
        problem = tr("no such file");
    else if (info.isDir())
        problem = tr("is a directory; name a recipe file");
    else if (!info.isFile())
        problem = tr("is not a regular file (a device, FIFO or socket); name a recipe file");
    else if (info.size() > RecipeFile::kMaxFileBytes)
        problem = tr("is larger than %1 MB, the most a recipe file may hold")
                      .arg(RecipeFile::kMaxFileBytes / (1024 * 1024));
    QFile file(path);
    if (problem.isEmpty() && !file.open(QIODevice::ReadOnly))
        problem = tr("cannot be read: %1").arg(file.errorString());
    if (!problem.isEmpty()) {
        context.err() << tr("error: %1: %2").arg(DisplayText::escaped(path), problem) << Qt::endl;
        *exitCode = ExitUsage;
        return std::nullopt;
    }
    const QByteArray data = file.read(RecipeFile::kMaxFileBytes + 1);
    LoadedRecipe loaded;
    QString error;
    if (std::optional<Recipe> recipe = RecipeFile::fromJson(data, &error, &loaded.checksum)) {
        loaded.recipe = *recipe;
        return loaded;
    }
    // Is the checksum the only fault? Read it again as if it were signed.
    const QJsonObject root = QJsonDocument::fromJson(data).object();
    if (root.value(QStringLiteral("format")).toString() == RecipeFile::formatName()) {
        QJsonObject resigned = root;
        resigned.remove(QStringLiteral("checksum"));
        resigned.insert(QStringLiteral("checksum"), BackupFile::checksumOf(resigned));
        QString resignedError;
        std::optional<Recipe> recipe =
            RecipeFile::fromJson(QJsonDocument(resigned).toJson(QJsonDocument::Compact),
                                 &resignedError, &loaded.checksum);
        if (recipe) {
            if (allowUnsigned) {
                loaded.recipe = *recipe;
                loaded.signedOk = false;
                return loaded;
            }
            context.err() << tr("error: %1").arg(unsignedText(path)) << Qt::endl;
            *exitCode = ExitInvalid;
            return std::nullopt;
        }
        // Changed by hand and broken: what is broken helps more than the checksum.
        error = resignedError;
    }
    // The parser's message may quote the file's text.
    context.err() << tr("error: %1 refused: %2")
                         .arg(DisplayText::escaped(path), DisplayText::escapedLines(error))
                  << Qt::endl;
    *exitCode = ExitInvalid;
    return std::nullopt;
}

QString EolSupport::unsignedText(const QString& path)
{
    return tr("%1 was changed after OpenTOP wrote it (its checksum does not match), so no station "
              "runs it. Check it with \"opentop-cli eol recipe check %1\" and, when it is right, "
              "sign it with \"opentop-cli eol recipe sign %1\"")
        .arg(DisplayText::escaped(path));
}

QJsonArray EolSupport::problemsJson(const QVector<RecipeProblem>& problems)
{
    QJsonArray array;
    for (const RecipeProblem& p : problems)
        array << QJsonObject{{QStringLiteral("path"), p.path},
                             {QStringLiteral("message"), p.message}};
    return array;
}

void EolSupport::printProblems(CliContext& context, const QVector<RecipeProblem>& problems)
{
    for (const RecipeProblem& p : problems)
        context.out() << tr("%1: %2").arg(DisplayText::escaped(p.path),
                                          DisplayText::escapedLines(p.message))
                      << '\n';
    context.out().flush();
}

int EolSupport::settingCount(const Recipe& recipe)
{
    int n = 0;
    for (const RecipePosition& p : recipe.positions)
        n += int(p.settings.size());
    return n;
}

int EolSupport::stepCount(const Recipe& recipe)
{
    int n = 0;
    for (const RecipePosition& p : recipe.positions)
        n += int(p.steps.size());
    return n;
}

QString EolSupport::countsText(const Recipe& recipe)
{
    int unitValues = 0;
    for (const RecipePosition& p : recipe.positions)
        unitValues += int(p.unitValues.size());
    QStringList parts{tr("%n position(s)", nullptr, int(recipe.positions.size())),
                      tr("%n setting(s)", nullptr, settingCount(recipe))};
    if (unitValues > 0)
        parts << tr("%n per-unit value(s)", nullptr, unitValues);
    parts << tr("%n step(s)", nullptr, stepCount(recipe));
    return parts.join(QStringLiteral(", "));
}

QCommandLineOption EolSupport::outputOption()
{
    return {{QStringLiteral("o"), QStringLiteral("output")},
            tr("The file to write (recipe create; results --csv; certificate)."),
            tr("FILE")};
}

QString EolSupport::defaultDatabase()
{
    return ResultUrl::defaultLocation();
}

std::unique_ptr<ResultDatabase> EolSupport::openDatabase(CliContext& context, int* exitCode,
                                                         bool create)
{
    const QString option = QStringLiteral("db");
    QString text = context.parser().value(option);
    QString from = QStringLiteral("--db");
    if (!context.parser().isSet(option)) {
        text = qEnvironmentVariable("OPENTOP_EOL_DB");
        from = QStringLiteral("OPENTOP_EOL_DB");
        if (text.trimmed().isEmpty()) {
            text = defaultDatabase();
            from.clear();
        }
    }
    QString error;
    const std::optional<ResultUrl> url = ResultUrl::parse(text, &error);
    if (!url) {
        context.err() << tr("error: %1: %2")
                             .arg(DisplayText::escaped(from.isEmpty() ? text : from),
                                  DisplayText::escapedLines(error))
                      << Qt::endl;
        *exitCode = ExitUsage;
        return nullptr;
    }
    if (create && url->engine == ResultUrl::Engine::Sqlite)
        QDir().mkpath(QFileInfo(url->path).absolutePath());
    else if (url->engine == ResultUrl::Engine::Sqlite && !QFileInfo::exists(url->path)) {
        // Reading never makes a database: a wrong path would otherwise show an empty one.
        context.err() << tr("error: no results database at %1 (nothing recorded there yet); "
                            "name one with --db URL")
                             .arg(DisplayText::escaped(url->path))
                      << Qt::endl;
        // A database that cannot be opened, like a junk file or a server that is not there
        // (docs/eol-results.md): exit 1.
        *exitCode = ExitCommunication;
        return nullptr;
    }
    std::unique_ptr<ResultDatabase> db = ResultDatabase::open(*url, &error);
    if (!db) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        *exitCode = ExitCommunication;
    }
    return db;
}

QString EolSupport::number(double value)
{
    return QString::number(value, 'g', 12);
}

QString EolSupport::withUnit(const QString& value, const QString& unit)
{
    return unit.isEmpty() ? value : value + QLatin1Char(' ') + unit;
}

QString EolSupport::label(const Profile* profile, const QString& parameter)
{
    const ParameterMeta* meta = profile ? profile->parameter(parameter) : nullptr;
    return meta && !meta->label.isEmpty() ? meta->label : parameter;
}

} // namespace opentop
