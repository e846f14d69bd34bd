// How a drive is named where its name or model came from a file (issue 28, item 5): a backup
// file's name or model, or a name kept before names were checked, is shown escaped in every
// message, page and file that names the drive.
#include "model/bus/DriveName.h"

#include <gtest/gtest.h>

using namespace opentop;

TEST(DriveNameEscapeTest, NamesAndModelsAreShownEscaped)
{
    const QString name = QStringLiteral("Infeed\x1b[2J");
    const QString model = QStringLiteral("DBU200\u202e");
    EXPECT_EQ(DriveName::text(1, name), QStringLiteral("machine number 1 (Infeed\\x1b[2J)"));
    EXPECT_EQ(DriveName::title(1, name), QStringLiteral("Machine number 1 (Infeed\\x1b[2J)"));
    EXPECT_EQ(DriveName::listed(1, name), QStringLiteral("1 (Infeed\\x1b[2J)"));
    EXPECT_EQ(DriveName::nameAndModel(name, model),
              QStringLiteral("Infeed\\x1b[2J, DBU200\\u202e"));
    EXPECT_EQ(DriveName::nameAndModel(QString(), model), QStringLiteral("DBU200\\u202e"));
    EXPECT_EQ(DriveName::withModel(2, QString(), QStringLiteral("DBU\n200")),
              QStringLiteral("drive 2 (DBU\\n200)"));
    // An ordinary name is shown as it is.
    EXPECT_EQ(DriveName::title(3, QStringLiteral("Förderband 3")),
              QStringLiteral("Machine number 3 (Förderband 3)"));
    // A name refused for its length is quoted escaped.
    const QString problem =
        DriveName::problem(QStringLiteral("\x1b]0;owned\x07") + QString(50, QLatin1Char('x')));
    EXPECT_FALSE(problem.contains(QChar(0x1b))) << qPrintable(problem);
    EXPECT_TRUE(problem.contains(QStringLiteral("\\x1b]0;owned\\x07"))) << qPrintable(problem);
}
