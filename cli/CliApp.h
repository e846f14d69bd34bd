#pragma once

#include "cli/CliCommand.h"

#include <QStringList>
#include <memory>
#include <vector>

class QTextStream;

namespace opentop {

// opentop-cli: parses the command line, picks the command, runs it, returns the exit code.
// Output streams are parameters so that tests run commands in-process.
class CliApp
{
public:
    CliApp();
    ~CliApp();

    int run(const QStringList& arguments, QTextStream& out, QTextStream& err);
    // True when the command line needs a QGuiApplication (offscreen) rather than a
    // QCoreApplication: drawing a certificate's PDF (eol certificate).
    static bool needsGui(const QStringList& arguments);
    // After a command: when standard output could not all be written (a closed pipe, a full
    // disk; `lost`: the C stream behind `out` saw a write fail), says so on `err` with what the
    // exit code means; the work itself was not cut short. Returns `code`.
    static int finishOutput(int code, QTextStream& out, QTextStream& err,
                            const std::function<bool()>& lost);
    // The language of the device profiles' texts for this command line, to give
    // ProfileRegistry::setLanguage before anything loads the profiles: `language` (the program's
    // language), except "en" with --json: JSON is for programs and keeps the profiles' English
    // (labels, units, alarm names), the same on every machine.
    static QString profileLanguage(const QStringList& arguments, const QString& language);
    const std::vector<std::unique_ptr<CliCommand>>& commands() const { return m_commands; }

private:
    CliCommand* find(const QString& name) const;
    QString helpText(const QString& program) const;

    std::vector<std::unique_ptr<CliCommand>> m_commands;
};

} // namespace opentop
