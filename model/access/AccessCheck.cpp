#include "model/access/AccessCheck.h"

#include "model/access/AuditTrail.h"
#include "model/eol/ResultDatabase.h"

namespace opentop {

AccessCheck::AccessCheck(ResultDatabase& database, const QString& station)
    : database_(database)
    , station_(station)
{
}

int AccessCheck::managed(QString* error)
{
    const int users = UserStore(database_).count(error);
    return users < 0 ? -1 : users > 0 ? 1 : 0;
}

bool AccessCheck::audit(const QString& user, const QString& action, const QString& detail)
{
    return AuditTrail(database_).record(station_, user, action, detail, nullptr);
}

QString AccessCheck::refusedText(const StationUser& user, Privilege privilege)
{
    return tr("%1 (%2) may not %3: it needs the %4 role or higher")
        .arg(user.name, AccessPolicy::roleText(user.role), AccessPolicy::privilegeText(privilege),
             AccessPolicy::roleText(AccessPolicy::minimumRole(privilege)));
}

AccessDecision AccessCheck::identify(const Identity& who, const QString& action)
{
    AccessDecision d;
    QString error;
    const int m = managed(&error);
    if (m < 0) {
        d.managed = true; // unknown: nothing is allowed
        d.message = tr("the users cannot be read from the results database: %1").arg(error);
        return d;
    }
    d.managed = m > 0;
    if (!d.managed) {
        d.allowed = true;
        return d;
    }
    const std::optional<StationUser> user = UserStore(database_).find(who.name.trimmed(), &error);
    if (!error.isEmpty()) {
        d.message = tr("the users cannot be read from the results database: %1").arg(error);
        return d;
    }
    // One message for an unknown name and a wrong password: which one it was is not told.
    if (!user || !user->password.matches(who.password)) {
        d.message = tr("wrong user name or password");
        audit(QString(), QStringLiteral("%1-failed").arg(action),
              tr("user \"%1\": wrong user name or password").arg(who.name.trimmed()));
        return d;
    }
    if (!user->active) {
        d.message = tr("user %1 is disabled").arg(user->name);
        audit(user->name, QStringLiteral("%1-failed").arg(action), d.message);
        return d;
    }
    d.user = user;
    d.allowed = true;
    return d;
}

AccessDecision AccessCheck::decide(AccessDecision d, Privilege privilege, const QString& what)
{
    if (!d.allowed || !d.managed || !d.user)
        return d;
    const QString detail =
        what.isEmpty() ? AccessPolicy::privilegeKey(privilege)
                       : QStringLiteral("%1: %2").arg(AccessPolicy::privilegeKey(privilege), what);
    if (!AccessPolicy::allows(d.user->role, privilege)) {
        d.allowed = false;
        d.message = refusedText(*d.user, privilege);
        audit(d.user->name, QStringLiteral("refused"), detail);
        return d;
    }
    audit(d.user->name, QStringLiteral("privilege"), detail);
    return d;
}

AccessDecision AccessCheck::login(const Identity& who, Privilege privilege)
{
    AccessDecision d = identify(who, QStringLiteral("login"));
    if (!d.allowed || !d.managed)
        return d;
    if (!AccessPolicy::allows(d.user->role, privilege)) {
        d.allowed = false;
        d.message = refusedText(*d.user, privilege);
        audit(d.user->name, QStringLiteral("login-failed"), d.message);
        return d;
    }
    audit(d.user->name, QStringLiteral("login"),
          tr("logged in as %1").arg(AccessPolicy::roleText(d.user->role)));
    return d;
}

AccessDecision AccessCheck::authorize(Privilege privilege, const Identity& who, const QString& what)
{
    return decide(identify(who, QStringLiteral("login")), privilege, what);
}

AccessDecision AccessCheck::authorizeUser(Privilege privilege, const QString& userName,
                                          const QString& what)
{
    AccessDecision d;
    QString error;
    const int m = managed(&error);
    d.managed = m != 0;
    if (m == 0) {
        d.allowed = true;
        return d;
    }
    const std::optional<StationUser> user =
        m < 0 ? std::nullopt : UserStore(database_).find(userName, &error);
    if (!user || !user->active) {
        d.message = !error.isEmpty()
                        ? tr("the users cannot be read from the results database: %1").arg(error)
                        : tr("user %1 is not an active user").arg(userName);
        audit(userName, QStringLiteral("refused"), AccessPolicy::privilegeKey(privilege));
        return d;
    }
    d.user = user;
    d.allowed = true;
    return decide(d, privilege, what);
}

AccessDecision AccessCheck::approveRecipe(const Identity& who, const QString& recipeName,
                                          const QString& revision, const QString& checksum,
                                          std::optional<RecipeApproval>* approval)
{
    const QString what = tr("recipe %1 rev. %2, checksum %3").arg(recipeName, revision, checksum);
    AccessDecision d = authorize(Privilege::ApproveRecipe, who, what);
    if (!d.allowed)
        return d;
    if (!d.managed) {
        d.allowed = false;
        d.message = tr("this station has no users yet: an approval names its approver, so add "
                       "users first (opentop-cli eol user add)");
        return d;
    }
    QString error;
    *approval = RecipeApprovals(database_).approve(recipeName, revision, checksum, d.user->name,
                                                   station_, &error);
    if (!*approval) {
        d.allowed = false;
        d.message = tr("the approval was not recorded: %1").arg(error);
        return d;
    }
    audit(d.user->name, QStringLiteral("recipe-approved"),
          tr("%1; approval %2").arg(what, (*approval)->id));
    return d;
}

bool AccessCheck::addUser(const Identity& actor, StationUser user, const QString& password,
                          QString* error, bool* refused)
{
    auto refuse = [&](const QString& why) {
        if (refused)
            *refused = true;
        *error = why;
        return false;
    };
    if (refused)
        *refused = false;
    const QString bad = UserStore::nameProblem(user.name);
    if (!bad.isEmpty())
        return refuse(bad);
    const QString weak = PasswordHash::weakness(password);
    if (!weak.isEmpty())
        return refuse(weak);
    UserStore store(database_);
    const int m = managed(error);
    if (m < 0)
        return false;
    QString by;
    if (m == 0) {
        // The bootstrap: the first user needs no identity, so it must be able to manage the rest.
        if (user.role != Role::Administrator)
            return refuse(tr("the first user must be an administrator (--role administrator): "
                             "they add everyone else"));
        by = user.name;
    } else {
        const AccessDecision d =
            authorize(Privilege::ManageUsers, actor, tr("add user %1").arg(user.name));
        if (!d.allowed)
            return refuse(d.message);
        by = d.user->name;
    }
    QString lookup;
    if (store.find(user.name, &lookup))
        return refuse(tr("user %1 exists already").arg(user.name));
    user.password = PasswordHash::make(password);
    user.active = true;
    if (!store.add(user, error))
        return false;
    audit(by, QStringLiteral("user-added"),
          tr("user %1 (%2) added as %3")
              .arg(user.name, user.displayName, AccessPolicy::roleKey(user.role)));
    return true;
}

bool AccessCheck::setActive(const Identity& actor, const QString& name, bool active, QString* error,
                            bool* refused)
{
    if (refused)
        *refused = true;
    const AccessDecision d =
        authorize(Privilege::ManageUsers, actor,
                  (active ? tr("enable user %1") : tr("disable user %1")).arg(name));
    if (!d.allowed || !d.managed) {
        *error = d.managed ? d.message : tr("there are no users yet");
        return false;
    }
    UserStore store(database_);
    const std::optional<StationUser> user = store.find(name, error);
    if (!user) {
        if (error->isEmpty())
            *error = tr("no user %1").arg(name);
        return false;
    }
    if (!active && user->role == Role::Administrator && user->active &&
        store.activeAdministrators(error) <= 1) {
        *error = tr("%1 is the last active administrator: add another first").arg(name);
        return false;
    }
    if (refused)
        *refused = false;
    if (!store.setActive(name, active, error))
        return false;
    audit(d.user->name, active ? QStringLiteral("user-enabled") : QStringLiteral("user-disabled"),
          name);
    return true;
}

bool AccessCheck::setPassword(const Identity& actor, const QString& name, const QString& password,
                              QString* error, bool* refused)
{
    if (refused)
        *refused = true;
    const QString weak = PasswordHash::weakness(password);
    if (!weak.isEmpty()) {
        *error = weak;
        return false;
    }
    // Their own password with the old one, anyone's as an administrator.
    const bool own = actor.name.trimmed() == name;
    const AccessDecision d =
        own ? login(actor, Privilege::RunUnits)
            : authorize(Privilege::ManageUsers, actor, tr("set the password of %1").arg(name));
    if (!d.allowed || !d.managed) {
        *error = d.managed ? d.message : tr("there are no users yet");
        return false;
    }
    UserStore store(database_);
    if (!store.find(name, error)) {
        if (error->isEmpty())
            *error = tr("no user %1").arg(name);
        return false;
    }
    if (refused)
        *refused = false;
    if (!store.setPassword(name, PasswordHash::make(password), error))
        return false;
    audit(d.user->name, QStringLiteral("password-changed"), name);
    return true;
}

} // namespace opentop
