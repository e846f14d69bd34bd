#pragma once

#include <QCoreApplication>
#include <QString>

namespace opentop {

class Recipe;

// Which serial numbers a station tests (docs/recipe-format.md, "Serial numbers"): the one rule
// every entry point asks (`eol run --serial`, the operator screen's serial field, EolStation).
// Always refused, whatever the recipe says: an empty serial, one longer than kMaxLength,
// control characters (C0, DEL, C1), format characters (bidirectional overrides), line breaks,
// and white space at either end: a serial is printed in terminals, files, certificates and the
// audit trail, and "SN1 " must not be another unit than "SN1". Then, when the recipe has a
// `serialPattern`, the whole serial must match it.
class SerialRule
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SerialRule)
public:
    // Far more than any barcode a line prints, well inside the results database's column.
    static constexpr int kMaxLength = 64;
    static constexpr int kMaxPatternLength = 1000;

    // Why `serial` may not be tested under `recipe`; empty when it may.
    static QString problem(const QString& serial, const Recipe& recipe);
    // The same with the recipe's pattern and example (either may be empty).
    static QString problem(const QString& serial, const QString& pattern,
                           const QString& example = QString());

    // What is wrong with a recipe's `serialPattern` and `serialExample` (empty: nothing), the
    // message naming the field; *field (optional) gets the field's name.
    static QString recipeProblem(const QString& pattern, const QString& example,
                                 QString* field = nullptr);

    // For people: "^TR[0-9]{8}$ (e.g. TR00012345)", or that any serial number is tested.
    static QString patternText(const Recipe& recipe);
};

} // namespace opentop
