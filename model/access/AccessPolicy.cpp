#include "model/access/AccessPolicy.h"

#include <QStringList>
#include <array>

namespace opentop {

namespace {

struct Row
{
    Privilege privilege;
    const char* key;
    Role minimum;
};

// The one table of privileges: which role each needs at least.
constexpr std::array<Row, 7> kTable{{
    {Privilege::RunUnits, "run-units", Role::Operator},
    {Privilege::ResetAlarm, "reset-alarm", Role::Operator},
    {Privilege::OverrideRetestLimit, "override-retest-limit", Role::Technician},
    {Privilege::LeaveProduction, "leave-production", Role::Engineer},
    {Privilege::EditRecipe, "edit-recipe", Role::Engineer},
    {Privilege::ApproveRecipe, "approve-recipe", Role::Engineer},
    {Privilege::ManageUsers, "manage-users", Role::Administrator},
}};

constexpr std::array<const char*, 4> kRoleKeys{"operator", "technician", "engineer",
                                               "administrator"};

const Row& rowOf(Privilege privilege)
{
    for (const Row& row : kTable)
        if (row.privilege == privilege)
            return row;
    return kTable.back(); // unreachable: every privilege has its row; the strictest otherwise
}

} // namespace

Role AccessPolicy::minimumRole(Privilege privilege)
{
    return rowOf(privilege).minimum;
}

bool AccessPolicy::allows(Role role, Privilege privilege)
{
    return int(role) >= int(minimumRole(privilege));
}

QString AccessPolicy::roleKey(Role role)
{
    return QString::fromLatin1(kRoleKeys[size_t(role)]);
}

std::optional<Role> AccessPolicy::roleFromKey(const QString& key)
{
    for (size_t i = 0; i < kRoleKeys.size(); ++i)
        if (key.trimmed().compare(QLatin1String(kRoleKeys[i]), Qt::CaseInsensitive) == 0)
            return Role(i);
    return std::nullopt;
}

QStringList AccessPolicy::roleKeys()
{
    QStringList keys;
    for (const char* k : kRoleKeys)
        keys << QString::fromLatin1(k);
    return keys;
}

QString AccessPolicy::roleText(Role role)
{
    switch (role) {
    case Role::Operator:
        return tr("operator");
    case Role::Technician:
        return tr("technician");
    case Role::Engineer:
        return tr("engineer");
    case Role::Administrator:
        break;
    }
    return tr("administrator");
}

QString AccessPolicy::privilegeKey(Privilege privilege)
{
    return QString::fromLatin1(rowOf(privilege).key);
}

QString AccessPolicy::privilegeText(Privilege privilege)
{
    switch (privilege) {
    case Privilege::RunUnits:
        return tr("test units");
    case Privilege::ResetAlarm:
        return tr("reset an alarm and retry");
    case Privilege::OverrideRetestLimit:
        return tr("override a retest limit");
    case Privilege::LeaveProduction:
        return tr("leave production mode");
    case Privilege::EditRecipe:
        return tr("open or edit a recipe");
    case Privilege::ApproveRecipe:
        return tr("approve a recipe");
    case Privilege::ManageUsers:
        break;
    }
    return tr("manage users");
}

} // namespace opentop
