#pragma once

#include "model/access/AccessPolicy.h"
#include "model/access/PasswordHash.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QVector>
#include <optional>

namespace opentop {

class ResultDatabase;

struct StationUser
{
    QString name;        // what a person types or a badge scanner sends: unique, no spaces
    QString displayName; // shown on the screen
    Role role = Role::Operator;
    bool active = true; // a disabled user keeps their records and can no longer log in
    QDateTime created;  // UTC
    PasswordHash password;
};

// The users table of the results database (schema version 6): every station of a line that
// shares the database shares its users. Rows only; who may change them is UserAdmin's.
class UserStore
{
    Q_DECLARE_TR_FUNCTIONS(opentop::UserStore)
public:
    explicit UserStore(ResultDatabase& database);

    // How many users there are (active or not); -1 on an error. None: an unmanaged station.
    int count(QString* error);
    std::optional<StationUser> find(const QString& name, QString* error);
    std::optional<QVector<StationUser>> list(QString* error);
    bool add(const StationUser& user, QString* error);
    bool setActive(const QString& name, bool active, QString* error);
    bool setPassword(const QString& name, const PasswordHash& password, QString* error);
    // How many active administrators (the last one is never disabled); -1 on an error.
    int activeAdministrators(QString* error);

    // Why a user name is refused; empty when it is accepted.
    static QString nameProblem(const QString& name);

private:
    ResultDatabase& database_;
};

} // namespace opentop
