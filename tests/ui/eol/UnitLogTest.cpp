// The operator screen shows serials and reasons from outside escaped (issue 28, item 5): a
// bidi override or a control character in a serial is shown as its escape, never acted on.
#include "ui/eol/UnitLog.h"

#include <gtest/gtest.h>

using namespace opentop;

TEST(UnitLogTest, SerialsAndReasonsAreShownEscaped)
{
    UnitLog log;
    UnitRecord r;
    r.serial = QStringLiteral("SN\u202e321");
    r.status = UnitStatus::Fail;
    r.ended = QDateTime::currentDateTime();
    r.failureReason = QStringLiteral("speed low\r\nPASS\x1b[1A");
    log.add(r, UnitLog::Kept::Recorded);
    ASSERT_EQ(log.rowCount(), 1);
    EXPECT_EQ(log.item(0, 1)->text(), QStringLiteral("SN\\u202e321"));
    EXPECT_EQ(log.item(0, 2)->text(), QStringLiteral("FAIL"));
    EXPECT_EQ(log.item(0, 3)->text(), QStringLiteral("speed low\\r\\nPASS\\x1b[1A"));
}
