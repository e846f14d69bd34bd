#pragma once

#include "model/access/AccessCheck.h"

#include <QCommandLineOption>
#include <QCoreApplication>
#include <optional>

namespace opentop {

class CliContext;

// Who runs an eol command that needs an identity: --user NAME, and the password from the
// OPENTOP_PASSWORD environment variable or asked on the terminal without echo. A password is
// never an argument (other users see a command line in ps and in the shell's history).
class CliIdentity
{
    Q_DECLARE_TR_FUNCTIONS(opentop::CliIdentity)
public:
    static QCommandLineOption userOption();
    // --user with its password; nullopt (reason printed) when --user is missing or no password
    // can be had (no OPENTOP_PASSWORD and no terminal).
    static std::optional<Identity> fromOptions(CliContext& context);
    // A password: `variable` when set, else asked on the terminal (twice when `confirm`).
    // nullopt with the reason printed.
    static std::optional<QString> password(CliContext& context, const char* variable,
                                           const QString& prompt, bool confirm);
};

} // namespace opentop
