// The certificate shows hostile text from the record escaped (issue 28, item 5): a control
// character or a bidi override in a serial, a name or a reason is printed as its escape, never
// acted on by the PDF's text layout, and what is escaped is made safe for HTML after.
#include "model/eol/CertificateHtml.h"
#include "tests/support/EolSampleUnit.h"

#include <gtest/gtest.h>

using namespace opentop;

TEST(CertificateHtmlHostileTextTest, ControlsAndBidiOverridesAreShownEscaped)
{
    UnitRecord r = test::eolSampleUnit(QStringLiteral("SN\x1b]0;owned\x07<b>"));
    r.operatorName = QStringLiteral("Ann\u202eeM");
    r.failureReason = QStringLiteral("speed low\r\nfake line");
    r.measurements[0].quantity = QStringLiteral("speed\u2066mean");
    const QString html = CertificateHtml::html(r);
    for (const QChar c : html) {
        const char16_t u = c.unicode();
        ASSERT_FALSE(u < 0x20 && u != u'\n') << int(u);
        ASSERT_FALSE((u >= 0x7f && u <= 0x9f) || (u >= 0x202a && u <= 0x202e) ||
                     (u >= 0x2066 && u <= 0x2069))
            << int(u);
    }
    EXPECT_TRUE(html.contains(QStringLiteral("SN\\x1b]0;owned\\x07&lt;b&gt;"))) << qPrintable(html);
    EXPECT_TRUE(html.contains(QStringLiteral("Ann\\u202eeM")));
    EXPECT_TRUE(html.contains(QStringLiteral("speed low\\r\\nfake line")));
    EXPECT_TRUE(html.contains(QStringLiteral("speed\\u2066mean")));
}
