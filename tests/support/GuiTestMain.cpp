// GoogleTest entry point for widget tests: offscreen, set before the QApplication exists, on a
// laptop's 1366×768 screen (the smallest the program is made for).
#include <QApplication>
#include <gtest/gtest.h>

#include "tests/support/PrivateUserDirs.h"

int main(int argc, char** argv)
{
    const opentop::test::PrivateUserDirs dirs;
    qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen:configfile=" OPENTOP_SOURCE_DIR
                                                 "/tests/support/offscreen-laptop.json"));
    QApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    opentop::test::PrivateUserDirs::startEachTestWithoutJournal();
    return RUN_ALL_TESTS();
}
