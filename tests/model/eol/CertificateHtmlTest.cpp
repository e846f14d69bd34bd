#include "model/eol/CertificateHtml.h"
#include "tests/support/EolSampleUnit.h"

#include <gtest/gtest.h>

using namespace opentop;

TEST(CertificateHtmlTest, HoldsEveryValueTheVerdictAndEscapesTheRecordsText)
{
    const UnitRecord r = test::eolSampleUnit(QStringLiteral("SN<9>"));
    const QString html = CertificateHtml::html(r);
    EXPECT_TRUE(html.contains(QLatin1String("SN&lt;9&gt;")));
    EXPECT_FALSE(html.contains(QLatin1String("SN<9>")));
    EXPECT_TRUE(html.contains(QLatin1String("Brake &lt;mode&gt; &amp; &quot;stop&quot;")));
    EXPECT_TRUE(html.contains(QLatin1String(">FAIL<")));
    EXPECT_TRUE(html.contains(r.failureReason.toHtmlEscaped()));
    for (const WrittenValue& w : r.writtenValues)
        EXPECT_TRUE(html.contains(w.readBack.toHtmlEscaped())) << w.readBack.toStdString();
    EXPECT_TRUE(html.contains(QString::fromUtf8("1498.25\u00a0r/min")));
    EXPECT_TRUE(html.contains(QString::fromUtf8("1450 … 1550\u00a0r/min")));
    EXPECT_TRUE(html.contains(QString::fromUtf8("≤ 120\u00a0%")));
    EXPECT_TRUE(html.contains(QLatin1String("no reply (timeout 200 ms)")));
    EXPECT_TRUE(html.contains(QLatin1String("already set")));
    const QString pass =
        CertificateHtml::html(test::eolSampleUnit(QStringLiteral("P"), UnitStatus::Pass));
    EXPECT_TRUE(pass.contains(QLatin1String(">PASS<")));
    EXPECT_FALSE(pass.contains(QLatin1String("First failure")));
}
