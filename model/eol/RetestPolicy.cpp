#include "model/eol/RetestPolicy.h"

#include "model/eol/ResultWriter.h"

#include <memory>

namespace opentop {

RetestPolicy::Decision RetestPolicy::decide(const RecipeRetest& rules, const QString& serial,
                                            const ResultQueries::SerialHistory& history)
{
    Decision d;
    d.attempt = history.verdicts + 1;
    d.passedBefore = history.passedAny;
    d.failuresBefore = history.failures;
    if (history.passedAny && rules.passed != RecipeRetest::Passed::Allow) {
        d.kind = rules.passed == RecipeRetest::Passed::Refuse ? Decision::Kind::Refused
                                                              : Decision::Kind::NeedsTechnician;
        d.reason = rules.passed == RecipeRetest::Passed::Refuse
                       ? tr("serial %1 has passed already; this recipe never tests a passed "
                            "unit again")
                             .arg(serial)
                       : tr("serial %1 has passed already; testing it again needs a technician")
                             .arg(serial);
        return d;
    }
    if (rules.maxAttempts > 0 && history.verdicts >= rules.maxAttempts) {
        d.kind = Decision::Kind::NeedsTechnician;
        d.reason = tr("serial %1 was tested %2 times under this recipe, its limit; another "
                      "attempt needs a technician")
                       .arg(serial)
                       .arg(history.verdicts);
    }
    return d;
}

void RetestPolicy::check(ResultWriter* writer, const RecipeRetest& rules, const QString& serial,
                         const QString& checksum, QObject* context, Done done)
{
    struct Answer
    {
        std::optional<ResultQueries::SerialHistory> history;
        QString error;
    };
    auto answer = std::make_shared<Answer>();
    writer->run(
        context,
        [answer, serial, checksum](ResultDatabase* db) {
            if (!db) {
                answer->error = tr("the results database is not open");
                return;
            }
            answer->history = ResultQueries(*db).serialHistory(serial, checksum, &answer->error);
        },
        [answer, rules, serial, done = std::move(done)] {
            if (!answer->history) {
                Decision d;
                d.reason = tr("earlier tests of %1 were not checked (%2): the result is kept in "
                              "the station's spool")
                               .arg(serial, answer->error);
                done(d);
                return;
            }
            done(decide(rules, serial, *answer->history));
        });
}

} // namespace opentop
