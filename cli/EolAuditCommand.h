#pragma once

#include "cli/EolSubcommand.h"

namespace opentop {

// `eol audit`: the audit trail of the results database (logins, approvals, privileges used and
// refused, changes to users), oldest first.
class EolAuditCommand : public EolSubcommand
{
public:
    QString name() const override { return QStringLiteral("audit"); }
    QString synopsis() const override;
    QString summary() const override;
    QList<QCommandLineOption> options() const override;
    int run(CliContext& context, const QStringList& args) override;
};

} // namespace opentop
