#pragma once

#include "eol/UnitRecord.h"

#include <QCoreApplication>

namespace opentop {

// A unit's certificate as HTML for QTextDocument (the printable PDF, report/CertificatePdf):
// the unit, the recipe, the verdict in large letters with the first failure in words, each
// drive, every value written with its proof, every measured value with its limits and verdict,
// and the traffic around a failure. Every text from the record is escaped.
class CertificateHtml
{
    Q_DECLARE_TR_FUNCTIONS(opentop::CertificateHtml)
public:
    static QString html(const UnitRecord& record);
    static QString verdictText(UnitStatus status);   // "PASS", "FAIL", ...
    static QString limitsText(const Measurement& m); // "1450 … 1550 r/min", "≤ 2.5 A"
    // "dbu200", "dbu200 (assumed)", "not known": an assumed variant never reads as known.
    static QString variantText(const UnitDrive& drive);
    // How a variant was known, in words: "proven by the variant probe", "ASSUMED, not proven".
    static QString variantSourceText(VariantSource source);
};

} // namespace opentop
