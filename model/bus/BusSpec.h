#pragma once

#include <QString>
#include <QVector>
#include <optional>

namespace opentop {

// A simulated bus as written everywhere one is named: "dbu200@1,dbu400@150,dcpid@7". A drive
// may carry simulated defects in braces, "dbu200@3{firmware=1.4,stall}" (their syntax is the
// simulator's, checked when the bus is made).
struct BusSpecEntry
{
    QString type; // family or variant id
    int slave = 1;
    QString defects; // the text between the braces, empty for none
};

class BusSpec
{
public:
    // Parses and checks types against the built-in profiles, ids 1–247 and duplicates.
    static std::optional<QVector<BusSpecEntry>> parse(const QString& text, QString* error);
    static QString toString(const QVector<BusSpecEntry>& entries);
};

} // namespace opentop
