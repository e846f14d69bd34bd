#pragma once

#include <QCoreApplication>
#include <QString>
#include <optional>

namespace opentop {

// Who may do what at an end-of-line station (docs/eol-results.md, "Users and roles"), after
// TestStand's user manager: four roles, each holding every privilege of the roles below it, and
// ONE table saying which role a privilege needs. The station, the recipe workflows and the
// command line all ask this table; no page decides for itself.
enum class Role
{
    Operator,
    Technician,
    Engineer,
    Administrator
};

enum class Privilege
{
    RunUnits,            // test units with an approved recipe
    ResetAlarm,          // reset a drive's alarm on the operator screen and retry
    OverrideRetestLimit, // test a serial again past the recipe's limit
    LeaveProduction,     // back to engineering mode (parameters, the recipe editor)
    EditRecipe,          // open another recipe, or edit one
    ApproveRecipe,       // make a recipe's checksum runnable on the line
    ManageUsers          // add, disable users, set another user's password
};

class AccessPolicy
{
    Q_DECLARE_TR_FUNCTIONS(opentop::AccessPolicy)
public:
    // The role a privilege needs at least (the one table).
    static Role minimumRole(Privilege privilege);
    static bool allows(Role role, Privilege privilege);

    static QString roleKey(Role role); // "operator" … as the database and the CLI write it
    static std::optional<Role> roleFromKey(const QString& key);
    static QString roleText(Role role);                // translated
    static QString privilegeKey(Privilege privilege);  // "leave-production" (audit trail)
    static QString privilegeText(Privilege privilege); // "leave production mode" (translated)
    static QStringList roleKeys();
};

} // namespace opentop
