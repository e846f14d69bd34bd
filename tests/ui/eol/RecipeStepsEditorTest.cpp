// The recipe editor's steps form is the step table's (RecipeStepKinds): the Add step menu lists
// every type with the table's title, and each type's form has exactly one widget per field of
// its entry; a number typed sets its key, an emptied optional one leaves it out.
#include "ui/eol/RecipeStepsEditor.h"
#include "model/eol/RecipeStepKinds.h"
#include "model/profile/ProfileRegistry.h"

#include <QComboBox>
#include <QGroupBox>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>

using namespace opentop;

namespace {

QString capitalised(QString text)
{
    if (!text.isEmpty())
        text[0] = text[0].toUpper();
    return text;
}

} // namespace

TEST(RecipeStepsEditorTest, TheAddMenuListsEveryStepTypeWithTheTablesTitle)
{
    RecipeStepsEditor editor;
    QMenu* menu = nullptr;
    for (QPushButton* b : editor.findChildren<QPushButton*>())
        if (b->menu())
            menu = b->menu();
    ASSERT_TRUE(menu);
    QStringList shown;
    for (QAction* a : menu->actions())
        shown << a->text();
    QStringList table;
    for (const RecipeStepKinds::Kind& k : RecipeStepKinds::all())
        table << capitalised(RecipeStepKinds::title(k.type));
    EXPECT_EQ(shown, table);
}

TEST(RecipeStepsEditorTest, EachTypesFormHasOneWidgetPerFieldOfItsEntry)
{
    RecipeStepsEditor editor;
    editor.setProfile(ProfileRegistry::builtIn().family(QStringLiteral("dbu")));
    editor.show();
    for (const RecipeStepKinds::Kind& kind : RecipeStepKinds::all()) {
        editor.setSteps({});
        editor.addStep(QString::fromLatin1(kind.name));
        EXPECT_TRUE(
            editor.detail()->title().endsWith(capitalised(RecipeStepKinds::title(kind.type))))
            << qPrintable(editor.detail()->title());
        for (const RecipeStepKinds::Field& f : kind.fields) {
            if (f.kind == RecipeStepKinds::Field::Kind::Limits)
                continue; // a table of limits, not a field of its own
            const QString name = QStringLiteral("step_") + QLatin1String(f.key);
            EXPECT_TRUE(editor.detail()->findChild<QWidget*>(name))
                << kind.name << ": no widget for " << f.key;
        }
        // No widget for a key the entry does not have.
        for (QWidget* w : editor.detail()->findChildren<QWidget*>()) {
            if (!w->objectName().startsWith(QLatin1String("step_")))
                continue;
            const QString key = w->objectName().mid(5);
            EXPECT_TRUE(RecipeStepKinds::keys(kind.type).contains(key))
                << kind.name << ": a widget for " << qPrintable(key);
        }
    }
}

TEST(RecipeStepsEditorTest, ANumberTypedSetsItsKeyAndAnEmptiedOptionalOneIsLeftOut)
{
    RecipeStepsEditor editor;
    editor.show();
    editor.addStep(QStringLiteral("waitSpeed"));
    auto* target = editor.detail()->findChild<QLineEdit*>(QStringLiteral("step_target"));
    ASSERT_TRUE(target);
    EXPECT_FALSE(target->placeholderText().isEmpty()); // says what empty means
    QTest::keyClicks(target, QStringLiteral("1500"));
    EXPECT_EQ(editor.steps().at(0).toObject().value(QStringLiteral("target")).toDouble(), 1500);
    target = editor.detail()->findChild<QLineEdit*>(QStringLiteral("step_target"));
    ASSERT_TRUE(target);
    target->selectAll();
    QTest::keyClick(target, Qt::Key_Backspace);
    EXPECT_FALSE(editor.steps().at(0).toObject().contains(QStringLiteral("target")));

    editor.addStep(QStringLiteral("select"));
    auto* spno = editor.detail()->findChild<QSpinBox*>(QStringLiteral("step_spno"));
    ASSERT_TRUE(spno);
    const RecipeStepKinds::Field& range =
        RecipeStepKinds::of(RecipeStep::Type::Select)->fields.first();
    EXPECT_EQ(spno->minimum(), int(range.min));
    EXPECT_EQ(spno->maximum(), int(range.max));
    spno->setValue(3);
    EXPECT_EQ(editor.steps().at(1).toObject().value(QStringLiteral("spno")).toInt(), 3);
}
