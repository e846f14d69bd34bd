// GoogleTest entry point for non-GUI tests: a QCoreApplication so that Qt event loops,
// queued signals and resources work.
#include <QCoreApplication>
#include <gtest/gtest.h>

#include "tests/support/PrivateUserDirs.h"

int main(int argc, char** argv)
{
    const opentop::test::PrivateUserDirs dirs;
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    opentop::test::PrivateUserDirs::startEachTestWithoutJournal();
    return RUN_ALL_TESTS();
}
