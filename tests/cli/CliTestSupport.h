#pragma once

#include "cli/CliApp.h"

#include <QStringList>
#include <QTextStream>

// Runs opentop-cli in-process with captured output, as the command-line tests do.
struct CliRun
{
    int code = -1;
    QString out;
    QString err;
};

inline CliRun runCli(const QStringList& args)
{
    CliRun r;
    QTextStream out(&r.out);
    QTextStream err(&r.err);
    opentop::CliApp app;
    r.code = app.run(QStringList{QStringLiteral("opentop-cli")} + args, out, err);
    return r;
}
