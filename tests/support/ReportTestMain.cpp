// GoogleTest entry point for the report tests: a QGuiApplication (text layout needs its font
// database), offscreen, no widgets.
#include <QGuiApplication>
#include <gtest/gtest.h>

#include "tests/support/PrivateUserDirs.h"

int main(int argc, char** argv)
{
    const opentop::test::PrivateUserDirs dirs;
    qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
    QGuiApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    opentop::test::PrivateUserDirs::startEachTestWithoutJournal();
    return RUN_ALL_TESTS();
}
