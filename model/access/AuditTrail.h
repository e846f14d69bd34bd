#pragma once

#include <QCoreApplication>
#include <QDateTime>
#include <QVector>
#include <optional>

namespace opentop {

class ResultDatabase;

struct AuditEntry
{
    QDateTime time; // UTC, by the database's clock (stations' clocks may differ)
    QString station;
    QString user;   // empty: nobody identified (a failed login names who was tried in `detail`)
    QString action; // "login", "login-failed", "logout", "privilege", "refused", …
    QString detail; // in words
};

struct AuditFilter
{
    QDateTime since; // invalid: from the start
    QString user;
    QString station;
    int limit = 10000; // the newest this many
};

// The audit trail of the results database (schema version 6): who did what, when and at which
// station: logins and failed logins, logouts, approvals, every use and refusal of a privilege,
// overrides, changes to users. Rows are only ever added.
class AuditTrail
{
    Q_DECLARE_TR_FUNCTIONS(opentop::AuditTrail)
public:
    explicit AuditTrail(ResultDatabase& database);

    bool record(const QString& station, const QString& user, const QString& action,
                const QString& detail, QString* error);
    std::optional<QVector<AuditEntry>> query(const AuditFilter& filter, QString* error);

private:
    ResultDatabase& database_;
};

} // namespace opentop
