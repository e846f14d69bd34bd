#pragma once

#include "cli/EolSubcommand.h"

#include <QHash>
#include <optional>

namespace opentop {

class Recipe;

// `eol run RECIPE --serial S [--operator O] [--station NAME] [--db URL] [--units CSV]
// [--value ID:NAME=VALUE]... [--variant ...] [--retest] [--user NAME]`: one unit through the
// end-of-line station (EolRun), recorded in the results database. Progress as lines for people,
// or one JSON object per line (--json) for a PLC or MES. Exit codes: 0 PASS, 5 FAIL, 6 station
// error, 3 recipe, serial (SerialRule: the recipe's serialPattern) or unit values not valid or
// the retest rules hold the serial back (nothing sent), 1 communication lost or results database
// unusable, 4 a motor not confirmed stopped, 130 interrupted. On a station with users: --user NAME
// (who may test units) and an approved recipe, else 3 and nothing sent.
class EolRunCommand : public EolSubcommand
{
public:
    QString name() const override { return QStringLiteral("run"); }
    QString synopsis() const override;
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

private:
    // This unit's per-unit values by machine number, from --units and --value; nothing (and a
    // message) when one is missing, malformed or not allowed.
    static std::optional<QHash<int, QHash<QString, double>>>
    unitValues(CliContext& context, const Recipe& recipe, const QString& serial, QString* error);
    // The variants --variant states, by machine number; nothing (and a message) when one is not
    // the recipe's.
    static std::optional<QHash<int, QString>>
    assertedVariants(CliContext& context, const Recipe& recipe, QString* error);
};

} // namespace opentop
