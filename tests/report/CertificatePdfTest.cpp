#include "report/CertificatePdf.h"
#include "model/eol/CertificateHtml.h"
#include "tests/support/EolSampleUnit.h"

#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTextDocument>
#include <algorithm>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

// The PDF's text when poppler's pdftotext is installed; empty otherwise.
QString pdfText(const QString& path)
{
    if (QStandardPaths::findExecutable(QStringLiteral("pdftotext")).isEmpty())
        return QString();
    QProcess p;
    p.start(QStringLiteral("pdftotext"), {QStringLiteral("-layout"), path, QStringLiteral("-")});
    p.waitForFinished(30000);
    return QString::fromUtf8(p.readAllStandardOutput());
}

} // namespace

TEST(CertificatePdfTest, WritesAPdfWithTheUnitAndItsVerdict)
{
    QTemporaryDir dir;
    // OPENTOP_CERTIFICATE_DIR keeps the PDFs to look at them.
    const QString outDir = qEnvironmentVariable("OPENTOP_CERTIFICATE_DIR", dir.path());
    for (UnitStatus status : {UnitStatus::Fail, UnitStatus::Pass}) {
        UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-2026-000417"), status);
        r.id = QStringLiteral("4b1d9c0e-0000-4000-8000-000000000001");
        const QString path =
            outDir + QStringLiteral("/certificate-%1.pdf").arg(unitStatusName(status));
        QString error;
        ASSERT_TRUE(CertificatePdf::save(r, path, &error)) << error.toStdString();
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        EXPECT_TRUE(bytes.startsWith("%PDF-")) << bytes.left(16).data();
        EXPECT_GT(bytes.size(), 5000);
        EXPECT_TRUE(bytes.trimmed().endsWith("%%EOF"));
        const QString text = pdfText(path);
        if (text.isEmpty())
            continue; // no pdftotext: the header and size are what is checked
        EXPECT_TRUE(text.contains(r.serial)) << text.toStdString();
        EXPECT_TRUE(text.contains(status == UnitStatus::Pass ? QLatin1String("PASS")
                                                             : QLatin1String("FAIL")));
        EXPECT_TRUE(text.contains(QLatin1String("1498.25"))) << text.toStdString();
        EXPECT_TRUE(text.contains(QLatin1String("Acceleration time")));
    }
    QString error;
    EXPECT_FALSE(
        CertificatePdf::save(test::eolSampleUnit(QStringLiteral("X")), dir.path(), &error));
}

// Issue 25 item 6: a section's heading is never alone at the foot of a page, whatever the
// number of rows before it (read back from the PDF, page by page).
TEST(CertificatePdfTest, AHeadingAlwaysStandsOnThePageOfItsFirstRow)
{
    if (QStandardPaths::findExecutable(QStringLiteral("pdftotext")).isEmpty())
        GTEST_SKIP() << "pdftotext (poppler-utils) is not installed";
    QTemporaryDir dir;
    int broken = 0; // certificates whose pages break inside the sections tried
    for (int extra = 0; extra < 48; extra += 1) {
        UnitRecord r = test::eolSampleUnit(QStringLiteral("SN-LAYOUT"), UnitStatus::Pass);
        for (int i = 0; i < extra; ++i)
            r.writtenValues.append(r.writtenValues.first());
        const QString path = dir.filePath(QStringLiteral("c%1.pdf").arg(extra));
        QString error;
        ASSERT_TRUE(CertificatePdf::save(r, path, &error)) << error.toStdString();
        const QStringList pages = pdfText(path).split(QLatin1Char('\f'));
        broken += pages.size() > 2 ? 1 : 0;
        for (const QString& page : pages) {
            QStringList lines = page.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
            lines.erase(std::remove_if(lines.begin(), lines.end(),
                                       [](const QString& l) { return l.trimmed().isEmpty(); }),
                        lines.end());
            for (int i = 0; i < lines.size(); ++i) {
                const QString line = lines.at(i).trimmed();
                if (line != QLatin1String("Measurements") && line != QLatin1String("Settings") &&
                    line != QLatin1String("Drives"))
                    continue;
                // The column titles and a first row follow on the same page (the footer line
                // comes last on every page).
                EXPECT_LT(i + 3, lines.size()) << qPrintable(line) << " at the foot of a page with "
                                               << extra << " more settings";
            }
        }
    }
    EXPECT_GT(broken, 0) << "the certificates tried never reached a third page";
}

TEST(CertificatePdfTest, APassAfterFailsListsThemAndLongTrafficLinesWrap)
{
    UnitRecord earlier = test::eolSampleUnit(QStringLiteral("SN-AGAIN"), UnitStatus::Fail);
    earlier.failureReason = QStringLiteral("position 1: Load rate 140 % above 100 %");
    earlier.attempt = 1;
    UnitRecord pass = test::eolSampleUnit(QStringLiteral("SN-AGAIN"), UnitStatus::Pass);
    pass.attempt = 2;
    pass.traffic = {QStringLiteral("12:00:00.000 TX ") +
                    QStringLiteral("01 03 10 00 00 0A ").repeated(30)};
    const QString html = CertificateHtml::html(pass, {earlier});
    EXPECT_TRUE(html.contains(QStringLiteral("This serial failed 1 earlier test")))
        << qPrintable(html);
    EXPECT_TRUE(html.contains(QStringLiteral("Load rate 140 %")));
    EXPECT_TRUE(html.contains(QStringLiteral("pre-wrap")));
    QTextDocument doc;
    doc.setHtml(html);
    doc.setPageSize(CertificatePdf::bodySize());
    EXPECT_LE(doc.idealWidth(), CertificatePdf::bodySize().width() + 1)
        << "nothing runs past the margin";
}
