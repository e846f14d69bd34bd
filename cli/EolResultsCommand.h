#pragma once

#include "cli/EolSubcommand.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/YieldReport.h"

#include <optional>

namespace opentop {

// `eol results [filters] [--yield] [--csv [-o FILE]]`: units of the results database by serial,
// time, recipe, verdict and station as a table, CSV or JSON; with --yield the first-pass yield
// and failure reasons per recipe and per shift.
class EolResultsCommand : public EolSubcommand
{
public:
    QString name() const override { return QStringLiteral("results"); }
    QString synopsis() const override
    {
        return QStringLiteral("results [--db URL] [--serial S] [--since T] [--until T] "
                              "[--recipe NAME] [--verdict V] [--station NAME] [--limit N] "
                              "[--yield [--shifts LIST]] [--csv [-o FILE]]");
    }
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;

    // "2026-11-24", "2026-11-24T13:00", "2026-11-24 13:00:05Z", "8h", "2d", "today": a time
    // (local when no zone is given); invalid with *error when unreadable.
    static QDateTime parseTime(const QString& text, const QDateTime& now, QString* error);

private:
    // The filter of the command line; nullopt after printing a usage error.
    static std::optional<ResultFilter> filter(CliContext& context);
    int output(CliContext& context, const QByteArray& csv);
    static void printUnits(CliContext& context, const QVector<UnitRecord>& units);
    static void printYield(CliContext& context, const QVector<YieldRow>& perRecipe,
                           const QVector<YieldRow>& perShift);
};

} // namespace opentop
