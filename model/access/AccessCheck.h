#pragma once

#include "model/access/AccessPolicy.h"
#include "model/access/RecipeApprovals.h"
#include "model/access/UserStore.h"

#include <QCoreApplication>
#include <optional>

namespace opentop {

class ResultDatabase;

// Who claims to act: a user name and the password typed (never kept).
struct Identity
{
    QString name;
    QString password;
};

struct AccessDecision
{
    bool allowed = false;
    bool managed = false;            // the database has users: everything is checked
    std::optional<StationUser> user; // who was identified (also when refused for the privilege)
    QString message;                 // why not, in words; empty when allowed
};

// The workflows of people at a station, on the results database's thread (the station's
// ResultWriter, or the command line): logging in, a privilege asked for with an identity, the
// users' own changes. Every login, failed login, use and refusal of a privilege and change to a
// user is written to the audit trail here, so no caller can forget it.
//
// A database with no users is an unmanaged station: everything is allowed, as before users
// existed. The first user added needs no identity and must be an administrator; from then on
// everything is checked.
class AccessCheck
{
    Q_DECLARE_TR_FUNCTIONS(opentop::AccessCheck)
public:
    AccessCheck(ResultDatabase& database, const QString& station);

    // 1: managed, 0: no users, -1: an error (*error).
    int managed(QString* error);
    // A login at the station (a session follows): the user must exist, be active and hold
    // `privilege` (an operator's is RunUnits).
    AccessDecision login(const Identity& who, Privilege privilege = Privilege::RunUnits);
    // A privilege asked for once, with an identity (a dialog, the command line's --user).
    // `what`: the object of the privilege for the audit trail ("recipe C-200 rev. A").
    AccessDecision authorize(Privilege privilege, const Identity& who, const QString& what);
    // The same for a user already logged in (no password again): read again, so a user disabled
    // meanwhile is refused.
    AccessDecision authorizeUser(Privilege privilege, const QString& userName, const QString& what);
    bool audit(const QString& user, const QString& action, const QString& detail);
    // Approves a recipe's checksum as `who` (an engineer or above), audited; *approval is the
    // approval in force afterwards. Refused on a station without users: nobody could be named.
    AccessDecision approveRecipe(const Identity& who, const QString& recipeName,
                                 const QString& revision, const QString& checksum,
                                 std::optional<RecipeApproval>* approval);

    // User administration; `actor` is an administrator, except for the first user (an
    // administrator, no actor needed) and a user changing their own password (their old one as
    // the actor's). False with *error; *refused tells a refusal from a database error.
    bool addUser(const Identity& actor, StationUser user, const QString& password, QString* error,
                 bool* refused = nullptr);
    bool setActive(const Identity& actor, const QString& name, bool active, QString* error,
                   bool* refused = nullptr);
    bool setPassword(const Identity& actor, const QString& name, const QString& password,
                     QString* error, bool* refused = nullptr);

    static QString refusedText(const StationUser& user, Privilege privilege);

private:
    // The user named, when the password is theirs and they are active; the audit trail gets a
    // failed attempt otherwise.
    AccessDecision identify(const Identity& who, const QString& action);
    AccessDecision decide(AccessDecision d, Privilege privilege, const QString& what);

    ResultDatabase& database_;
    QString station_;
};

} // namespace opentop
