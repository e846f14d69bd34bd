#include "cli/EolRunIdentity.h"

#include "cli/CliContext.h"
#include "cli/CliIdentity.h"
#include "cli/ExitCode.h"
#include "model/access/AccessCheck.h"
#include "model/eol/Recipe.h"
#include "model/eol/ResultWriter.h"
#include "model/io/DisplayText.h"

#include <QEventLoop>
#include <functional>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolRunIdentity", text);
}

} // namespace

namespace {

// Runs `job` on the writer's thread with its database and waits for it.
void onWriter(ResultWriter& writer, std::function<void(ResultDatabase* db)> job)
{
    QEventLoop loop;
    writer.run(&loop, std::move(job), [&loop] { loop.quit(); });
    loop.exec();
}

} // namespace

std::optional<EolRunIdentity> EolRunIdentity::check(CliContext& context, ResultWriter& writer,
                                                    const QString& station, const Recipe& recipe,
                                                    const QString& checksum, int* code)
{
    QTextStream& err = context.err();
    const bool userGiven = context.parser().isSet(QStringLiteral("user"));
    // First whether the station has users: a password is asked only when it does.
    int managed = -1;
    QString error;
    onWriter(writer, [&managed, &error, station](ResultDatabase* db) {
        if (db)
            managed = AccessCheck(*db, station).managed(&error);
        else
            error = tr("the results database is not open");
    });
    if (managed < 0) {
        err << tr("results database: %1; nothing was sent").arg(DisplayText::escapedLines(error))
            << Qt::endl;
        *code = ExitCommunication;
        return std::nullopt;
    }
    EolRunIdentity identity;
    if (managed == 0) {
        // Unmanaged: as before users existed; a --user is the operator's name, unchecked.
        identity.user = context.parser().value(QStringLiteral("user")).trimmed();
        return identity;
    }
    if (!userGiven) {
        err << tr("refused: %1; nothing was sent")
                   .arg(tr("this station has users: name who tests with --user NAME (the "
                           "password from OPENTOP_PASSWORD or the terminal)"))
            << Qt::endl;
        *code = ExitUsage;
        return std::nullopt;
    }
    if (context.parser().isSet(QStringLiteral("operator"))) {
        err << tr("error: on a station with users the operator is the user who logs in "
                  "(--user); --operator is not taken")
            << Qt::endl;
        *code = ExitUsage;
        return std::nullopt;
    }
    const std::optional<Identity> who = CliIdentity::fromOptions(context);
    if (!who) {
        *code = ExitUsage;
        return std::nullopt;
    }
    AccessDecision decision;
    std::optional<RecipeApproval> approval;
    onWriter(writer, [&, station, checksum](ResultDatabase* db) {
        if (!db) {
            error = tr("the results database is not open");
            return;
        }
        AccessCheck access(*db, station);
        decision = access.login(*who, Privilege::RunUnits);
        if (!decision.allowed)
            return;
        approval = RecipeApprovals(*db).current(checksum, &error);
        if (!approval && error.isEmpty())
            access.audit(who->name, QStringLiteral("refused"),
                         tr("run-units: recipe checksum %1 is not approved").arg(checksum));
    });
    if (!error.isEmpty()) {
        err << tr("results database: %1; nothing was sent").arg(DisplayText::escapedLines(error))
            << Qt::endl;
        *code = ExitCommunication;
        return std::nullopt;
    }
    if (!decision.allowed) {
        err << tr("refused: %1; nothing was sent").arg(DisplayText::escapedLines(decision.message))
            << Qt::endl;
        *code = ExitInvalid;
        return std::nullopt;
    }
    if (!approval) {
        err << tr("refused: %1 Nothing was sent.")
                   .arg(DisplayText::escapedLines(
                       RecipeApprovals::draftText(recipe.product, recipe.revision)))
            << Qt::endl;
        *code = ExitInvalid;
        return std::nullopt;
    }
    identity.user = decision.user->name;
    identity.approvalId = approval->id;
    identity.approver = approval->approver;
    err << tr("%1 logged in; recipe approved by %2 (approval %3)")
               .arg(DisplayText::escaped(identity.user), DisplayText::escaped(identity.approver),
                    identity.approvalId)
        << Qt::endl;
    return identity;
}

} // namespace opentop
