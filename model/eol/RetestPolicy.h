#pragma once

#include "model/eol/RecipeTypes.h"
#include "model/eol/ResultQueries.h"

#include <QCoreApplication>
#include <QObject>
#include <functional>

namespace opentop {

class ResultWriter;

// Whether a serial may be tested (again) under a recipe's retest rules (RecipeRetest), decided
// on its recorded verdicts before anything is sent: the same rule for the station's screen and
// `eol run`. A decision that needs a technician names why; who may give it is the access
// rules' business.
class RetestPolicy
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RetestPolicy)
public:
    struct Decision
    {
        enum class Kind
        {
            Allowed,
            NeedsTechnician, // a passed serial, or the attempts used up
            Refused          // the recipe never tests a passed serial again
        };
        Kind kind = Kind::Allowed;
        int attempt = 0; // the verdict this test would be (1 = first test); 0: not known
        QString reason;  // why not allowed, or a note (the history could not be read)
        bool passedBefore = false;
        int failuresBefore = 0; // fail verdicts under this recipe version
    };
    using Done = std::function<void(const Decision&)>;

    static Decision decide(const RecipeRetest& rules, const QString& serial,
                           const ResultQueries::SerialHistory& history);
    // Reads the serial's history on the writer's thread and decides; `done` runs on `context`'s
    // thread. Without an open database the test is allowed (its record is spooled) and the
    // decision's reason says the history was not checked.
    static void check(ResultWriter* writer, const RecipeRetest& rules, const QString& serial,
                      const QString& checksum, QObject* context, Done done);
};

} // namespace opentop
