// The program in each language (issue 13): its menus keep one accelerator per key, the
// language menu saves a choice for the next start, and --lang's codes are understood.
#include "tests/ui/main/MainWindowFixture.h"
#include "tests/ui/main/TsIndex.h"
#include "ui/i18n/LanguageMenu.h"

#include <QMenu>
#include <QMenuBar>

using namespace opentop;
using namespace opentop::test;

namespace {

// "Alt+letter" conflicts of one menu (or the menu bar): "&File" and "&Find" both take F.
QStringList acceleratorClashes(const QList<QAction*>& actions, const QString& where)
{
    QStringList clashes;
    QHash<QString, QString> taken;
    for (QAction* a : actions) {
        if (a->isSeparator() || !a->isVisible())
            continue;
        const QKeySequence mnemonic = QKeySequence::mnemonic(a->text());
        if (mnemonic.isEmpty())
            continue;
        const QString key = mnemonic.toString();
        if (taken.contains(key))
            clashes << QStringLiteral("%1: %2 in \"%3\" and \"%4\"")
                           .arg(where, key, taken.value(key), a->text());
        else
            taken.insert(key, a->text());
    }
    return clashes;
}

QStringList clashesIn(QMenu* menu, const QString& where)
{
    QStringList clashes = acceleratorClashes(menu->actions(), where);
    for (QAction* a : menu->actions())
        if (a->menu())
            clashes << clashesIn(a->menu(), where + QStringLiteral(" ▸ ") + a->text());
    return clashes;
}

} // namespace

class MainWindowLanguageTest : public MainWindowFixture,
                               public ::testing::WithParamInterface<const char*>
{
protected:
    void SetUp() override
    {
        language = QString::fromLatin1(GetParam());
        MainWindowFixture::SetUp();
    }
};

TEST_P(MainWindowLanguageTest, NoTwoActionsOfAMenuShareAnAccelerator)
{
    QMenuBar* bar = window->menuBar();
    QStringList clashes = acceleratorClashes(bar->actions(), QStringLiteral("menu bar"));
    int menus = 0;
    for (QAction* a : bar->actions()) {
        if (!a->menu())
            continue;
        ++menus;
        // Menus fill some entries as they open (recent files, drives).
        emit a->menu()->aboutToShow();
        clashes << clashesIn(a->menu(), a->text());
    }
    EXPECT_GE(menus, 6);
    EXPECT_TRUE(clashes.isEmpty()) << qPrintable(clashes.join(u'\n'));
    // Every top-level menu can be opened with Alt and a key.
    for (QAction* a : bar->actions())
        EXPECT_FALSE(QKeySequence::mnemonic(a->text()).isEmpty()) << qPrintable(a->text());
}

INSTANTIATE_TEST_SUITE_P(Languages, MainWindowLanguageTest,
                         ::testing::Values("en", "zh_TW", "zh_CN", "ko", "ja"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                             return std::string(param.param);
                         });

TEST_F(MainWindowFixture, TheLanguageMenuSavesTheChoiceAndSaysItAppliesAtTheNextStart)
{
    auto* menu = window->findChild<LanguageMenu*>();
    ASSERT_TRUE(menu);
    // Offered by their own names, the system's first and checked while nothing is saved.
    QStringList names;
    for (QAction* a : menu->actions())
        if (!a->isSeparator())
            names << a->text();
    EXPECT_TRUE(names.contains(QStringLiteral("繁體中文")));
    EXPECT_TRUE(names.contains(QStringLiteral("한국어")));
    EXPECT_TRUE(names.first().contains(QStringLiteral("(")));
    EXPECT_TRUE(menu->actions().first()->isChecked());
    EXPECT_TRUE(Language::saved().isEmpty());

    QAction* korean = nullptr;
    for (QAction* a : menu->actions())
        if (a->data().toString() == QLatin1String("ko"))
            korean = a;
    ASSERT_TRUE(korean);
    korean->trigger();
    EXPECT_EQ(Language::saved(), QStringLiteral("ko"));
    EXPECT_TRUE(korean->isChecked());
    EXPECT_FALSE(menu->actions().first()->isChecked());
    auto* box = window->findChild<QMessageBox*>(QStringLiteral("languageRestartBox"));
    ASSERT_TRUE(box);
    EXPECT_TRUE(box->isVisible());
    EXPECT_TRUE(box->text().contains(QStringLiteral("한국어"))) << qPrintable(box->text());
    box->accept();
    // Back to English, the language running: saved, and nothing to restart for.
    menu->choose(QStringLiteral("en"));
    EXPECT_EQ(Language::saved(), QStringLiteral("en"));
    QCoreApplication::processEvents();
    EXPECT_EQ(window->findChild<QMessageBox*>(QStringLiteral("languageRestartBox")), nullptr);
}

TEST(LanguageTest, CodesAsPeopleAndLocalesWriteThemAreUnderstood)
{
    EXPECT_EQ(Language::normalized(QStringLiteral("zh-TW")), QStringLiteral("zh_TW"));
    EXPECT_EQ(Language::normalized(QStringLiteral("zh_HK.UTF-8")), QStringLiteral("zh_TW"));
    EXPECT_EQ(Language::normalized(QStringLiteral("zh_CN")), QStringLiteral("zh_CN"));
    EXPECT_EQ(Language::normalized(QStringLiteral("zh")), QStringLiteral("zh_CN"));
    EXPECT_EQ(Language::normalized(QStringLiteral("ko_KR.UTF-8")), QStringLiteral("ko"));
    EXPECT_EQ(Language::normalized(QStringLiteral("JA")), QStringLiteral("ja"));
    EXPECT_EQ(Language::normalized(QStringLiteral("C")), QStringLiteral("en"));
    EXPECT_EQ(Language::normalized(QStringLiteral("en_GB")), QStringLiteral("en"));
    EXPECT_EQ(Language::normalized(QStringLiteral("de")), std::nullopt);
    EXPECT_EQ(Language::forLocale(QLocale(QStringLiteral("zh_TW"))), QStringLiteral("zh_TW"));
    EXPECT_EQ(Language::forLocale(QLocale(QStringLiteral("zh_SG"))), QStringLiteral("zh_CN"));
    EXPECT_EQ(Language::forLocale(QLocale(QStringLiteral("ko_KR"))), QStringLiteral("ko"));
    EXPECT_EQ(Language::forLocale(QLocale(QStringLiteral("de_DE"))), QStringLiteral("en"));
    EXPECT_EQ(Language::requestedIn(QStringList{QStringLiteral("opentop"), QStringLiteral("--lang"),
                                                QStringLiteral("ja"), QStringLiteral("--sim")}),
              QStringLiteral("ja"));
    EXPECT_EQ(Language::requestedIn(QStringList{QStringLiteral("x"), QStringLiteral("--lang=ko")}),
              QStringLiteral("ko"));
    QString error;
    EXPECT_FALSE(Language::install(QStringLiteral("xx"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("zh_TW"))) << qPrintable(error);
    EXPECT_EQ(Language::current(), QStringLiteral("en"));
}

TEST_F(MainWindowFixture, CtrlPageDownAndUpTurnTheSelectedDrivesPages)
{
    select({1});
    ASSERT_TRUE(
        waitFor([&] { return window->workspace()->drive() == window->drives()->parameters(1); }));
    QTabWidget* tabs = window->workspace()->tabs();
    ASSERT_GT(tabs->count(), 3);
    tabs->setCurrentIndex(0);
    window->activateWindow();
    QTest::keyClick(window.get(), Qt::Key_PageDown, Qt::ControlModifier);
    EXPECT_EQ(tabs->currentIndex(), 1);
    QTest::keyClick(window.get(), Qt::Key_PageUp, Qt::ControlModifier);
    QTest::keyClick(window.get(), Qt::Key_PageUp, Qt::ControlModifier);
    EXPECT_EQ(tabs->currentIndex(), tabs->count() - 1); // round to the last page
}
