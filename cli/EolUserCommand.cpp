#include "cli/EolUserCommand.h"

#include "cli/CliContext.h"
#include "cli/CliIdentity.h"
#include "cli/EolSupport.h"
#include "cli/ExitCode.h"
#include "cli/TextTable.h"
#include "model/access/AccessCheck.h"
#include "model/eol/ResultDatabase.h"
#include "model/io/DisplayText.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSysInfo>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::EolUserCommand", text);
}

const QString kRole = QStringLiteral("role");
const QString kDisplayName = QStringLiteral("display-name");
const QString kDb = QStringLiteral("db");

} // namespace

EolUserCommand::EolUserCommand(Action action)
    : m_action(action)
{
}

QString EolUserCommand::name() const
{
    switch (m_action) {
    case Action::Add:
        return QStringLiteral("user add");
    case Action::List:
        return QStringLiteral("user list");
    case Action::Disable:
        return QStringLiteral("user disable");
    case Action::Passwd:
        break;
    }
    return QStringLiteral("user passwd");
}

QString EolUserCommand::synopsis() const
{
    switch (m_action) {
    case Action::Add:
        return QStringLiteral("user add NAME --role ROLE [--display-name TEXT] [--user ADMIN] "
                              "[--db URL]");
    case Action::List:
        return QStringLiteral("user list [--db URL] [--json]");
    case Action::Disable:
        return QStringLiteral("user disable NAME --user ADMIN [--db URL]");
    case Action::Passwd:
        break;
    }
    return QStringLiteral("user passwd NAME [--user WHO] [--db URL]");
}

QString EolUserCommand::summary() const
{
    switch (m_action) {
    case Action::Add:
        return tr("Add a user (operator, technician, engineer or administrator); the first user "
                  "is an administrator and needs no --user");
    case Action::List:
        return tr("List the users of the results database");
    case Action::Disable:
        return tr("Disable a user: they can no longer log in; their records stay");
    case Action::Passwd:
        break;
    }
    return tr("Set a user's password (your own with your old one, anyone's as administrator)");
}

QList<QCommandLineOption> EolUserCommand::options() const
{
    QList<QCommandLineOption> list{
        {kDb, tr("Results database: an SQLite file or postgresql://user@host/db."), tr("URL")}};
    if (m_action == Action::Add)
        list << QCommandLineOption(kRole,
                                   tr("user add: operator, technician, engineer or "
                                      "administrator."),
                                   tr("ROLE"))
             << QCommandLineOption(kDisplayName, tr("user add: the name shown on the screen."),
                                   tr("TEXT"));
    if (m_action != Action::List)
        list << CliIdentity::userOption();
    return list;
}

int EolUserCommand::list(CliContext& context)
{
    int code = ExitOk;
    std::unique_ptr<ResultDatabase> db = EolSupport::openDatabase(context, &code);
    if (!db)
        return code;
    QString error;
    const auto users = UserStore(*db).list(&error);
    if (!users) {
        context.err() << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitCommunication;
    }
    if (context.json()) {
        QJsonArray array;
        for (const StationUser& u : *users)
            array << QJsonObject{{QStringLiteral("name"), u.name},
                                 {QStringLiteral("displayName"), u.displayName},
                                 {QStringLiteral("role"), AccessPolicy::roleKey(u.role)},
                                 {QStringLiteral("active"), u.active},
                                 {QStringLiteral("created"), u.created.toString(Qt::ISODate)}};
        context.out() << QJsonDocument(array).toJson(QJsonDocument::Indented);
        return ExitOk;
    }
    if (users->isEmpty()) {
        context.out() << tr("no users: this station is unmanaged (anyone can run, edit and "
                            "leave); add the first administrator with: opentop-cli eol user add "
                            "NAME --role administrator")
                      << Qt::endl;
        return ExitOk;
    }
    TextTable table({tr("user"), tr("name"), tr("role"), tr("active"), tr("created")});
    for (const StationUser& u : *users)
        table.addRow({u.name, u.displayName, AccessPolicy::roleText(u.role),
                      u.active ? tr("yes") : tr("no (disabled)"),
                      u.created.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"))});
    table.print(context.out());
    return ExitOk;
}

int EolUserCommand::run(CliContext& context, const QStringList& args)
{
    QTextStream& err = context.err();
    if (m_action == Action::List && args.isEmpty())
        return list(context);
    if (m_action == Action::List || args.size() != 1) {
        err << tr("usage: opentop-cli eol %1").arg(synopsis()) << Qt::endl;
        return ExitUsage;
    }
    const QString target = args.first().trimmed();
    std::optional<Role> role;
    if (m_action == Action::Add) {
        role = AccessPolicy::roleFromKey(context.parser().value(kRole));
        if (!role) {
            err << tr("error: --role is one of: %1")
                       .arg(AccessPolicy::roleKeys().join(QStringLiteral(", ")))
                << Qt::endl;
            return ExitUsage;
        }
    }
    int code = ExitOk;
    std::unique_ptr<ResultDatabase> db =
        EolSupport::openDatabase(context, &code, m_action == Action::Add);
    if (!db)
        return code;
    AccessCheck access(*db, QSysInfo::machineHostName());
    QString error;
    const int managed = access.managed(&error);
    if (managed < 0) {
        err << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitCommunication;
    }
    // Who does it: nobody for the first user; the user themselves by default for passwd.
    Identity actor;
    const bool needActor = managed > 0 && !(m_action == Action::Passwd &&
                                            !context.parser().isSet(QStringLiteral("user")));
    if (needActor) {
        const std::optional<Identity> who = CliIdentity::fromOptions(context);
        if (!who)
            return ExitUsage;
        actor = *who;
    } else if (m_action == Action::Passwd) {
        const auto old = CliIdentity::password(
            context, "OPENTOP_PASSWORD",
            tr("Present password for %1: ").arg(DisplayText::escaped(target)), false);
        if (!old)
            return ExitUsage;
        actor = Identity{target, *old};
    }
    bool refused = false;
    bool ok = false;
    switch (m_action) {
    case Action::Add: {
        const auto pw = CliIdentity::password(
            context, "OPENTOP_NEW_PASSWORD",
            tr("New password for %1: ").arg(DisplayText::escaped(target)), true);
        if (!pw)
            return ExitUsage;
        StationUser user;
        user.name = target;
        user.displayName = context.parser().value(kDisplayName).trimmed();
        user.role = *role;
        ok = access.addUser(actor, user, *pw, &error, &refused);
        if (ok)
            context.out() << tr("user %1 added as %2")
                                 .arg(DisplayText::escaped(target), AccessPolicy::roleText(*role))
                          << Qt::endl;
        break;
    }
    case Action::Disable:
        ok = access.setActive(actor, target, false, &error, &refused);
        if (ok)
            context.out() << tr("user %1 disabled").arg(DisplayText::escaped(target)) << Qt::endl;
        break;
    case Action::Passwd: {
        const auto pw = CliIdentity::password(
            context, "OPENTOP_NEW_PASSWORD",
            tr("New password for %1: ").arg(DisplayText::escaped(target)), true);
        if (!pw)
            return ExitUsage;
        ok = access.setPassword(actor, target, *pw, &error, &refused);
        if (ok)
            context.out() << tr("password of %1 changed").arg(DisplayText::escaped(target))
                          << Qt::endl;
        break;
    }
    case Action::List:
        break;
    }
    if (ok)
        return ExitOk;
    err << tr("error: %1; nothing was changed").arg(DisplayText::escapedLines(error)) << Qt::endl;
    return refused ? ExitInvalid : ExitCommunication;
}

} // namespace opentop
