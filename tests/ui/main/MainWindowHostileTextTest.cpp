// Issue 28 item 5 (hostile text): in production mode, text OpenTOP did not write (the recipe's
// product and position names, the station's name, a scanned serial) is shown as it is written,
// never drawn as HTML: QLabel and QMessageBox guess rich text, and a product
// "<font size=40>PASS</font>" would otherwise show the operator a large PASS.
#include "model/eol/RecipeFile.h"
#include "model/station/EolStation.h"
#include "tests/ui/main/MainWindowFixture.h"
#include "ui/eol/ProductionMode.h"
#include "ui/eol/ProductionView.h"

#include <QLabel>
#include <QLineEdit>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextDocument>

using namespace opentop;
using namespace opentop::test;

namespace {

const QString kProduct = QStringLiteral("<font size=40>PASS</font>");
const QString kPosition = QStringLiteral("<i>belt</i>");
const QString kStation = QStringLiteral("<b>Line-1</b>");
const QString kSerial = QStringLiteral("<b>SN-H1</b><img src=x>");

// What a reader sees of a text shown in `format`: as Qt draws it (rich text when told so or, in
// Qt::AutoText, when Qt takes it for rich text), read back as plain text.
QString seen(Qt::TextFormat format, const QString& text)
{
    if (format != Qt::RichText && !(format == Qt::AutoText && Qt::mightBeRichText(text)))
        return text;
    QTextDocument document;
    document.setHtml(text);
    return document.toPlainText();
}

// The labels under `root` that quote `hostile` (as written or HTML-escaped); each is expected to
// read it as written.
int expectEveryLabelReadsAsWritten(QWidget* root, const QString& hostile)
{
    int quoting = 0;
    for (const QLabel* label : root->findChildren<QLabel*>()) {
        const QString text = label->text();
        if (!text.contains(hostile) && !text.contains(hostile.toHtmlEscaped()))
            continue;
        ++quoting;
        EXPECT_TRUE(seen(label->textFormat(), text).contains(hostile))
            << qPrintable(label->objectName()) << " shows " << qPrintable(text) << " as "
            << qPrintable(seen(label->textFormat(), text));
    }
    return quoting;
}

// The example DBU200 recipe for drive 1, a long hold, its product and position named in markup.
QString hostileRecipe(const QTemporaryDir& dir)
{
    QString error;
    std::optional<Recipe> recipe = RecipeFile::load(
        QStringLiteral(OPENTOP_SOURCE_DIR "/docs/examples/recipe-dbu200.json"), &error);
    EXPECT_TRUE(recipe) << qPrintable(error);
    if (!recipe)
        return QString();
    recipe->product = kProduct;
    recipe->serialPattern.clear();
    RecipePosition& p = recipe->positions[0];
    p.name = kPosition;
    p.unitValues.clear();
    for (RecipeStep& s : p.steps)
        if (s.type == RecipeStep::Type::Hold)
            s.duration = 60;
    const QString path = dir.filePath(QStringLiteral("hostile.json"));
    EXPECT_TRUE(RecipeFile::save(*recipe, path, &error)) << qPrintable(error);
    return path;
}

// Answers the next modal message box with `button` once it shows; its text and text format go
// to *text and *format.
void answerNextBox(QMessageBox::StandardButton button, QString* text, Qt::TextFormat* format)
{
    auto* timer = new QTimer;
    QObject::connect(timer, &QTimer::timeout, [timer, button, text, format] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            *text = box->text();
            *format = box->textFormat();
            box->button(button)->click();
            timer->deleteLater();
        }
    });
    timer->start(20);
}

using MainWindowHostileTextTest = MainWindowFixture;

} // namespace

TEST_F(MainWindowHostileTextTest, MarkupInRecipeStationAndSerialIsShownAsWrittenInProductionMode)
{
    QTemporaryDir dir;
    ProductionMode* production = window->production();
    EolStation* station = production->station();
    ASSERT_TRUE(station->setStation(kStation)); // before the database opens: no reopening
    const QString db = dir.filePath(QStringLiteral("results.db"));
    qputenv("OPENTOP_EOL_DB", db.toLocal8Bit());
    production->toggleAction()->trigger();
    qunsetenv("OPENTOP_EOL_DB");
    ASSERT_TRUE(production->isActive());
    ASSERT_TRUE(waitFor([&] { return station->hasDatabase(); }));
    ProductionView* view = production->view();
    ASSERT_TRUE(view->openRecipe(hostileRecipe(dir)));

    // The recipe's product and the station's name, where the operator reads them.
    EXPECT_GE(expectEveryLabelReadsAsWritten(window.get(), kProduct), 1);
    EXPECT_GE(expectEveryLabelReadsAsWritten(window.get(), kStation), 1);
    EXPECT_TRUE(
        seen(view->databaseLabel()->textFormat(), view->databaseLabel()->text()).contains(kStation))
        << qPrintable(view->databaseLabel()->text());
    // The figures' tool tip quotes the station in the command line that gives the same figures.
    ASSERT_TRUE(waitFor([&] {
        return view->countersLabel()->toolTip().contains(QLatin1String("Line-1"));
    })) << qPrintable(view->countersLabel()->toolTip());
    EXPECT_TRUE(seen(Qt::AutoText, view->countersLabel()->toolTip()).contains(kStation))
        << qPrintable(view->countersLabel()->toolTip());

    // A serial in markup, as a scanner types it: tested, and named as it is.
    QTest::keyClicks(view->serialField(), kSerial);
    QTest::keyClick(view->serialField(), Qt::Key_Return);
    ASSERT_TRUE(waitFor(
        [&] {
            const QTableWidgetItem* now = view->drivesTable()->item(0, 1);
            return now && now->text().contains(QLatin1String("hold"));
        },
        20000))
        << qPrintable(view->reasonLabel()->text());
    EXPECT_TRUE(
        seen(view->reasonLabel()->textFormat(), view->reasonLabel()->text()).contains(kSerial))
        << qPrintable(view->reasonLabel()->text());
    EXPECT_GE(expectEveryLabelReadsAsWritten(window.get(), kSerial), 1);
    EXPECT_GE(expectEveryLabelReadsAsWritten(window.get(), kProduct), 1);
    EXPECT_TRUE(view->drivesTable()->item(0, 0)->text().contains(kPosition))
        << qPrintable(view->drivesTable()->item(0, 0)->text());

    // Quitting asks about the unit, naming its serial as it is.
    QString question;
    Qt::TextFormat format = Qt::AutoText;
    answerNextBox(QMessageBox::No, &question, &format);
    EXPECT_FALSE(window->close());
    EXPECT_TRUE(question.contains(QStringLiteral("SN-H1"))) << qPrintable(question);
    EXPECT_TRUE(seen(format, question).contains(kSerial))
        << qPrintable(question) << " reads " << qPrintable(seen(format, question));

    station->cancel();
    ASSERT_TRUE(waitFor([&] { return !station->isRunning(); }, 20000));
    ASSERT_TRUE(
        waitFor([&] { return view->verdictLabel()->text() != QLatin1String("TESTING"); }, 20000));
    EXPECT_EQ(view->verdictLabel()->text(), QStringLiteral("ABORTED"));
    expectEveryLabelReadsAsWritten(window.get(), kSerial);
    ASSERT_EQ(view->unitsTable()->rowCount(), 1);
    EXPECT_EQ(view->unitsTable()->item(0, 1)->text(), kSerial);
    EXPECT_EQ(speedOf(1), 0);
}
