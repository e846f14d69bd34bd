#include "report/CertificatePdf.h"

#include "model/eol/CertificateHtml.h"
#include "model/io/DisplayText.h"
#include "model/io/OutputFile.h"

#include <QBuffer>
#include <QFont>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QTextDocument>

namespace opentop {

QByteArray CertificatePdf::pdf(const UnitRecord& record, const QVector<UnitRecord>& earlier)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        // The serial as the page shows it (DisplayText), in the title and every footer.
        const QString serial = DisplayText::escaped(record.serial);
        writer.setTitle(tr("End-of-line certificate %1").arg(serial));
        writer.setCreator(QStringLiteral("OpenTOP " OPENTOP_VERSION));
        writer.setResolution(300);
        writer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait,
                                         QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter));
        // The same page as bodySize() computes without a writer.
        QTextDocument document;
        document.setHtml(CertificateHtml::html(record, earlier));
        // Lay the text out in points on a page of the writer's size less a footer line, then
        // scale to the writer's dots.
        const QRectF page = writer.pageLayout().paintRect(QPageLayout::Point);
        const QSizeF body = bodySize();
        const double footer = page.height() - body.height();
        document.setPageSize(body);
        QPainter painter(&writer);
        const double scale = writer.resolution() / 72.0;
        painter.scale(scale, scale);
        const int pages = document.pageCount();
        for (int i = 0; i < pages; ++i) {
            if (i > 0)
                writer.newPage();
            painter.save();
            painter.translate(0, -body.height() * i);
            document.drawContents(&painter, QRectF(QPointF(0, body.height() * i), body));
            painter.restore();
            // Every page names its unit and verdict: a page that comes loose is still traceable.
            QFont font(QStringLiteral("DejaVu Sans"));
            font.setPixelSize(7); // the painter's unit is a point
            painter.setFont(font);
            painter.drawText(QRectF(0, body.height(), page.width(), footer),
                             Qt::AlignRight | Qt::AlignBottom,
                             tr("%1 · %2 · page %3 of %4")
                                 .arg(serial, CertificateHtml::verdictText(record.status))
                                 .arg(i + 1)
                                 .arg(pages));
        }
        painter.end();
    }
    return bytes;
}

QSizeF CertificatePdf::bodySize()
{
    const QRectF page = QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait,
                                    QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter)
                            .paintRect(QPageLayout::Point);
    constexpr double footer = 14;
    return QSizeF(page.width(), page.height() - footer);
}

bool CertificatePdf::save(const UnitRecord& record, const QString& path, QString* error,
                          const QVector<UnitRecord>& earlier)
{
    return OutputFile::write(path, pdf(record, earlier), error);
}

} // namespace opentop
