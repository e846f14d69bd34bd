// Every communication error code a profile knows is explained in words a field engineer reads,
// with what to do: the DBU's E0h–E8h and the DC controller's Modbus exception codes.
#include "model/profile/CodeTable.h"
#include "model/profile/ProfileRegistry.h"

#include <QRegularExpression>
#include <gtest/gtest.h>

using namespace opentop;

TEST(CommErrorTexts, EveryCommunicationErrorCodeSaysWhatItMeansAndWhatToDo)
{
    int codes = 0;
    for (const Profile& profile : ProfileRegistry::builtIn().profiles()) {
        for (const CodeTable& table : profile.codeTables) {
            for (const CodeEntry& e : table.entries) {
                if (e.exceptionCode == 0)
                    continue; // not a communication error (alarms and warnings)
                ++codes;
                const QString where = profile.family + QLatin1Char(' ') + QString::number(e.code);
                EXPECT_GE(e.cause.size(), 40) << qPrintable(where);
                EXPECT_FALSE(e.remedy.isEmpty()) << qPrintable(where);
                // Settings by their names, not register addresses a field engineer cannot use.
                const QRegularExpression address(QStringLiteral("0x[0-9A-Fa-f]{4}"));
                EXPECT_FALSE(e.cause.contains(address)) << qPrintable(where);
                EXPECT_FALSE(e.remedy.contains(address)) << qPrintable(where);
                const QString text = e.explained();
                EXPECT_TRUE(text.startsWith(e.panel.isEmpty() ? e.name : e.panel))
                    << qPrintable(text);
                EXPECT_TRUE(text.contains(QStringLiteral("What to do: "))) << qPrintable(text);
                EXPECT_TRUE(text.endsWith(QLatin1Char('.'))) << qPrintable(text);
            }
        }
    }
    EXPECT_EQ(codes, 6 + 11); // the DBU's six codes, the DC controller's eleven
}

TEST(CommErrorTexts, E2hSaysARunCommandInIoPriorityIsRefusedAndHowToRunIt)
{
    const Profile* dbu = ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    ASSERT_NE(dbu, nullptr);
    const CodeEntry* e2 = dbu->codeTable(QStringLiteral("comm_error"))->find(0xE2);
    ASSERT_NE(e2, nullptr);
    EXPECT_TRUE(e2->cause.contains(QStringLiteral("I/O priority")));
    EXPECT_TRUE(e2->cause.contains(QStringLiteral("communication group")));
    EXPECT_TRUE(e2->remedy.contains(QStringLiteral("Communication priority")));
}
