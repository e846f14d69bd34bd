#pragma once

#include "model/eol/UnitRecord.h"

#include <QCoreApplication>
#include <QSizeF>

namespace opentop {

// A unit's end-of-line certificate as a printable PDF (A4, the HTML of CertificateHtml laid out
// by QTextDocument), written through OutputFile. Needs a QGuiApplication.
class CertificatePdf
{
    Q_DECLARE_TR_FUNCTIONS(opentop::CertificatePdf)
public:
    // `earlier`: the serial's records before this one (CertificateHtml lists them).
    static QByteArray pdf(const UnitRecord& record, const QVector<UnitRecord>& earlier = {});
    static bool save(const UnitRecord& record, const QString& path, QString* error,
                     const QVector<UnitRecord>& earlier = {});
    // The text's page in points (A4 less margins and the footer line): where QTextDocument
    // breaks the certificate's pages.
    static QSizeF bodySize();
};

} // namespace opentop
