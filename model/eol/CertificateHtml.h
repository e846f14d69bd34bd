#pragma once

#include "model/eol/UnitRecord.h"

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
    // `earlier`: the serial's records before this one (own rows: verdict, time, reason), listed
    // so that a PASS never hides the FAILs before it.
    static QString html(const UnitRecord& record, const QVector<UnitRecord>& earlier = {});
    static QString verdictText(UnitStatus status);   // "PASS", "FAIL", ...
    static QString limitsText(const Measurement& m); // "1450 … 1550 r/min", "≤ 2.5 A"
    // "dbu200", "dbu200 (assumed)", "not known": an assumed variant never reads as known.
    static QString variantText(const UnitDrive& drive);
    // How a variant was known, in words: "proven by the variant probe", "ASSUMED, not proven".
    static QString variantSourceText(VariantSource source);
};

} // namespace opentop
