#pragma once

#include <QString>
#include <optional>

namespace opentop {

class CliContext;
class Recipe;
class ResultWriter;

// Who tests with `eol run` and under which approval: on a station with users (the results
// database has some) the --user who may test units, with the recipe's checksum approved; asked
// of the database on the station writer's thread (AccessCheck), audited there. Nothing (a
// message printed, *code an ExitCode) when refused: nothing is sent then.
struct EolRunIdentity
{
    QString user; // empty: a station without users (the operator is --operator, as before)
    QString approvalId;
    QString approver;

    static std::optional<EolRunIdentity> check(CliContext& context, ResultWriter& writer,
                                               const QString& station, const Recipe& recipe,
                                               const QString& checksum, int* code);
};

} // namespace opentop
