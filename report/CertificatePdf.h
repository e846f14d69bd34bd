#pragma once

#include "eol/UnitRecord.h"

#include <QCoreApplication>

namespace opentop {

// A unit's end-of-line certificate as a printable PDF (A4, the HTML of CertificateHtml laid out
// by QTextDocument), written through OutputFile. Needs a QGuiApplication.
class CertificatePdf
{
    Q_DECLARE_TR_FUNCTIONS(opentop::CertificatePdf)
public:
    static QByteArray pdf(const UnitRecord& record);
    static bool save(const UnitRecord& record, const QString& path, QString* error);
};

} // namespace opentop
