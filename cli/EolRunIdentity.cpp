#include "EolRunIdentity.h"

#include "CliContext.h"
#include "CliIdentity.h"
#include "ExitCode.h"
#include "access/AccessCheck.h"
#include "eol/Recipe.h"
#include "eol/ResultWriter.h"

#include <QEventLoop>
#include <memory>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolRunIdentity", text);
}

} // namespace

std::optional<EolRunIdentity> EolRunIdentity::check(CliContext& context, ResultWriter& writer,
                                                    const QString& station, const Recipe& recipe,
                                                    const QString& checksum, int* code)
{
    QTextStream& err = context.err();
    std::optional<Identity> who;
    if (context.parser().isSet(QStringLiteral("user"))) {
        who = CliIdentity::fromOptions(context);
        if (!who) {
            *code = ExitUsage;
            return std::nullopt;
        }
    }
    struct Answer
    {
        AccessDecision decision;
        std::optional<RecipeApproval> approval;
        QString error;
    };
    auto answer = std::make_shared<Answer>();
    QEventLoop loop;
    writer.run(
        &loop,
        [answer, who, station, checksum](ResultDatabase* db) {
            if (!db) {
                answer->error = tr("the results database is not open");
                return;
            }
            AccessCheck access(*db, station);
            const int managed = access.managed(&answer->error);
            if (managed <= 0) {
                answer->decision.allowed = managed == 0;
                return;
            }
            answer->decision.managed = true;
            if (!who) {
                answer->decision.message = tr("this station has users: name who tests with "
                                              "--user NAME (the password from OPENTOP_PASSWORD "
                                              "or the terminal)");
                return;
            }
            answer->decision = access.login(*who, Privilege::RunUnits);
            if (!answer->decision.allowed)
                return;
            answer->approval = RecipeApprovals(*db).current(checksum, &answer->error);
            if (!answer->approval && answer->error.isEmpty())
                access.audit(who->name, QStringLiteral("refused"),
                             tr("run-units: recipe checksum %1 is not approved").arg(checksum));
        },
        [&loop] { loop.quit(); });
    loop.exec();
    if (!answer->error.isEmpty()) {
        err << tr("results database: %1; nothing was sent").arg(answer->error) << Qt::endl;
        *code = ExitCommunication;
        return std::nullopt;
    }
    const AccessDecision& d = answer->decision;
    if (!d.allowed) {
        err << tr("refused: %1; nothing was sent").arg(d.message) << Qt::endl;
        *code = who ? ExitInvalid : ExitUsage;
        return std::nullopt;
    }
    EolRunIdentity identity;
    if (!d.managed)
        return identity; // unmanaged: as before users existed
    if (context.parser().isSet(QStringLiteral("operator"))) {
        err << tr("error: on a station with users the operator is the user who logs in "
                  "(--user); --operator is not taken")
            << Qt::endl;
        *code = ExitUsage;
        return std::nullopt;
    }
    if (!answer->approval) {
        err << tr("refused: %1 Nothing was sent.")
                   .arg(RecipeApprovals::draftText(recipe.product, recipe.revision))
            << Qt::endl;
        *code = ExitInvalid;
        return std::nullopt;
    }
    identity.user = d.user->name;
    identity.approvalId = answer->approval->id;
    identity.approver = answer->approval->approver;
    err << tr("%1 logged in; recipe approved by %2 (approval %3)")
               .arg(identity.user, identity.approver, identity.approvalId)
        << Qt::endl;
    return identity;
}

} // namespace opentop
