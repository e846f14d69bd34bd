#include "CertificatePdf.h"
#include "EolSampleUnit.h"

#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
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
