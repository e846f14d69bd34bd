// Hostile text reaches no terminal (issue 28, item 5), through the program as delivered: a
// recipe whose product holds an escape sequence, and units recorded with serials that retitle
// a terminal or read as a spreadsheet formula (rows as a database written by an older version
// holds them, put in through the model's result store), are shown by `eol recipe check`,
// `eol recipe show` and `eol results` with every control character escaped, and exported as CSV
// that a spreadsheet reads as text; the JSON output keeps the exact text, escaped by JSON.
#include "model/eol/RecipeFile.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultStore.h"
#include "tests/e2e/CliProcess.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTimeZone>
#include <gtest/gtest.h>

using namespace opentop;
using namespace opentop::test;

namespace {

// ESC ] 0 ; ... BEL sets an xterm's title; printed raw, a serial renames the operator's window.
const QString kRetitle = QStringLiteral("SN\x1b]0;owned\x07");
const QString kRetitleShown = QStringLiteral("SN\\x1b]0;owned\\x07");

struct Output
{
    int code = -1;
    QByteArray out;
    QByteArray err;
    QString text() const { return QString::fromUtf8(out + err); }
};

// opentop-cli ARGS in English, its output as the terminal would get the bytes.
Output cli(const QStringList& args)
{
    QProcess process;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("LC_ALL"));
    env.remove(QStringLiteral("LANGUAGE"));
    env.remove(QStringLiteral("OPENTOP_EOL_DB"));
    env.insert(QStringLiteral("LANG"), QStringLiteral("C.UTF-8"));
    process.setProcessEnvironment(env);
    process.start(cliProgram(), args);
    Output o;
    if (!process.waitForStarted(5000) || !process.waitForFinished(30000)) {
        process.kill();
        process.waitForFinished(2000);
        return o;
    }
    o.code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    o.out = process.readAllStandardOutput();
    o.err = process.readAllStandardError();
    return o;
}

// No byte a terminal takes as a control: C0 but the line feed, DEL, C1 and the bidi
// overrides (as UTF-8); the first one found, or empty.
QString rawControl(const QByteArray& bytes)
{
    for (int i = 0; i < bytes.size(); ++i) {
        const uchar b = uchar(bytes.at(i));
        if ((b < 0x20 && b != '\n') || b == 0x7f)
            return QStringLiteral("byte 0x%1 at %2").arg(b, 2, 16, QLatin1Char('0')).arg(i);
    }
    for (const QChar c : QString::fromUtf8(bytes)) {
        const char16_t u = c.unicode();
        if ((u >= 0x80 && u <= 0x9f) || (u >= 0x202a && u <= 0x202e) ||
            (u >= 0x2066 && u <= 0x2069))
            return QStringLiteral("U+%1").arg(uint(u), 4, 16, QLatin1Char('0'));
    }
    return QString();
}

class CliHostileTextE2e : public ::testing::Test
{
protected:
    void SetUp() override { ASSERT_TRUE(dir.isValid()); }

    // The example recipe with an escape sequence in its product, a bidi override in its
    // position's name and a screen-clearing sequence in its description; signed.
    QString hostileRecipe()
    {
        QString error;
        std::optional<Recipe> recipe = RecipeFile::load(
            QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json"), &error);
        EXPECT_TRUE(recipe) << error.toStdString();
        if (!recipe)
            return QString();
        recipe->product = QStringLiteral("Pump\x1b]0;owned\x07 200");
        recipe->description = QStringLiteral("clears\x1b[2J the screen");
        recipe->positions[0].name = QStringLiteral("belt\u202etfel");
        const QString path = dir.filePath(QStringLiteral("hostile.json"));
        EXPECT_TRUE(RecipeFile::save(*recipe, path, &error)) << error.toStdString();
        return path;
    }

    // A results database with a unit whose serial retitles the terminal and whose operator's
    // name holds a bidi override, and one whose serial is a spreadsheet formula.
    QString hostileDatabase()
    {
        const QString path = dir.filePath(QStringLiteral("results.db"));
        QString error;
        std::unique_ptr<ResultDatabase> db = ResultDatabase::open(path, &error);
        EXPECT_TRUE(db) << error.toStdString();
        if (!db)
            return path;
        ResultStore store(*db);
        const QDateTime base(QDate(2026, 11, 24), QTime(13, 0), QTimeZone::utc());
        auto add = [&](const QString& serial, const QString& operatorName, UnitStatus status,
                       const QString& reason, int minute) {
            UnitRecord u;
            u.serial = serial;
            u.station = QStringLiteral("station-1");
            u.operatorName = operatorName;
            u.recipeName = QStringLiteral("pump A");
            u.recipeRevision = QStringLiteral("-12.5"); // a number, to stay one in CSV
            u.recipeChecksum = QStringLiteral("sha256:00");
            u.started = base.addSecs(60 * minute);
            u.ended = u.started.addSecs(40);
            u.status = status;
            u.failureReason = reason;
            EXPECT_TRUE(store.beginUnit(u, &error)) << error.toStdString();
            EXPECT_TRUE(store.finishUnit(u, &error)) << error.toStdString();
        };
        add(kRetitle, QStringLiteral("Ann\u202eeM"), UnitStatus::Fail,
            QStringLiteral("speed low\x1b[1A\rPASS"), 0);
        add(QStringLiteral("=cmd|'/C calc'!A0"), QStringLiteral("@SUM(1+1)"), UnitStatus::Pass,
            QString(), 1);
        return path;
    }

    QTemporaryDir dir;
};

} // namespace

TEST_F(CliHostileTextE2e, RecipeCheckShowsTheProductEscaped)
{
    const QString recipe = hostileRecipe();
    const Output r =
        cli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"), recipe});
    EXPECT_EQ(r.code, 0) << qPrintable(r.text());
    EXPECT_EQ(rawControl(r.out + r.err), QString()) << qPrintable(r.text());
    EXPECT_TRUE(QString::fromUtf8(r.out).contains(
        QStringLiteral("valid: Pump\\x1b]0;owned\\x07 200 revision A: ")))
        << qPrintable(r.text());
}

TEST_F(CliHostileTextE2e, RecipeCheckJsonKeepsTheExactProduct)
{
    const QString recipe = hostileRecipe();
    const Output r = cli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("check"),
                          recipe, QStringLiteral("--json")});
    EXPECT_EQ(r.code, 0) << qPrintable(r.text());
    // JSON escapes controls itself (\u001b): no raw byte, and not escaped twice.
    EXPECT_FALSE(r.out.contains('\x1b'));
    EXPECT_FALSE(r.out.contains("\\\\x1b"));
    const QJsonObject o = QJsonDocument::fromJson(r.out).object();
    EXPECT_EQ(o.value(QStringLiteral("product")).toString(),
              QStringLiteral("Pump\x1b]0;owned\x07 200"))
        << r.out.constData();
}

TEST_F(CliHostileTextE2e, RecipeShowShowsEveryTextOfTheFileEscaped)
{
    const QString recipe = hostileRecipe();
    const Output r =
        cli({QStringLiteral("eol"), QStringLiteral("recipe"), QStringLiteral("show"), recipe});
    EXPECT_EQ(r.code, 0) << qPrintable(r.text());
    EXPECT_EQ(rawControl(r.out + r.err), QString()) << qPrintable(r.text());
    const QString out = QString::fromUtf8(r.out);
    EXPECT_TRUE(out.startsWith(QStringLiteral("Pump\\x1b]0;owned\\x07 200, revision A\n")))
        << qPrintable(out);
    EXPECT_TRUE(out.contains(QStringLiteral("clears\\x1b[2J the screen\n"))) << qPrintable(out);
    EXPECT_TRUE(out.contains(QStringLiteral("belt\\u202etfel"))) << qPrintable(out);
}

TEST_F(CliHostileTextE2e, ResultsShowSerialsNamesAndReasonsEscaped)
{
    const QString db = hostileDatabase();
    const Output r =
        cli({QStringLiteral("eol"), QStringLiteral("results"), QStringLiteral("--db"), db});
    EXPECT_EQ(r.code, 0) << qPrintable(r.text());
    EXPECT_EQ(rawControl(r.out + r.err), QString()) << qPrintable(r.text());
    const QString out = QString::fromUtf8(r.out);
    EXPECT_TRUE(out.contains(kRetitleShown)) << qPrintable(out);
    EXPECT_TRUE(out.contains(QStringLiteral("Ann\\u202eeM"))) << qPrintable(out);
    // The carriage return and cursor-up cannot overwrite the verdict with "PASS".
    EXPECT_TRUE(out.contains(QStringLiteral("speed low\\x1b[1A\\rPASS"))) << qPrintable(out);
    // A header, two units, the count: the escaped text makes no line of its own.
    EXPECT_EQ(out.count(QLatin1Char('\n')), 4) << qPrintable(out);
}

TEST_F(CliHostileTextE2e, ResultsCsvReadsAsTextInASpreadsheetAndKeepsNumbers)
{
    const QString db = hostileDatabase();
    const Output r = cli({QStringLiteral("eol"), QStringLiteral("results"), QStringLiteral("--db"),
                          db, QStringLiteral("--csv")});
    EXPECT_EQ(r.code, 0) << qPrintable(r.text());
    const QStringList lines =
        QString::fromUtf8(r.out).split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 3) << r.out.constData();
    // Only the record ends are line breaks.
    EXPECT_EQ(rawControl(QByteArray(r.out).replace("\r\n", "\n")), QString()) << r.out.constData();
    QString formula;
    QString retitle;
    for (const QString& line : lines.mid(1)) {
        // No field of these rows needs quoting: split on commas.
        const QStringList f = line.split(QLatin1Char(','));
        ASSERT_EQ(f.size(), 11) << qPrintable(line);
        EXPECT_EQ(f[7], QStringLiteral("-12.5")) << "a number stays a number";
        if (f[1].contains(QLatin1String("calc"))) {
            formula = line;
            EXPECT_EQ(f[1], QStringLiteral("'=cmd|'/C calc'!A0"));
            EXPECT_EQ(f[3], QStringLiteral("'@SUM(1+1)"));
        } else {
            retitle = line;
            EXPECT_EQ(f[1], kRetitleShown);
            EXPECT_EQ(f[3], QStringLiteral("Ann\\u202eeM"));
            EXPECT_EQ(f[10], QStringLiteral("speed low\\x1b[1A\\rPASS"));
        }
    }
    EXPECT_FALSE(formula.isEmpty()) << r.out.constData();
    EXPECT_FALSE(retitle.isEmpty()) << r.out.constData();
}
