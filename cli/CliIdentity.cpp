#include "cli/CliIdentity.h"

#include "cli/CliContext.h"

#include <cstdio>
#ifdef Q_OS_WIN
#include <windows.h>

#include <io.h>
#else
#include <termios.h>
#include <unistd.h>
#endif

namespace opentop {

namespace {

#ifdef Q_OS_WIN
// One line from the console with echo off; nullopt when standard input is not a console.
std::optional<QString> readHidden(CliContext& context, const QString& prompt)
{
    HANDLE in = GetStdHandle(STD_INPUT_HANDLE);
    DWORD old = 0;
    if (!_isatty(_fileno(stdin)) || !GetConsoleMode(in, &old))
        return std::nullopt;
    context.err() << prompt;
    context.err().flush();
    SetConsoleMode(in, old & ~DWORD(ENABLE_ECHO_INPUT));
    // The console's own characters (UTF-16), not the code page stdin would convert them to.
    QString line;
    wchar_t c = 0;
    DWORD got = 0;
    while (ReadConsoleW(in, &c, 1, &got, nullptr) && got == 1 && c != L'\n' && c != L'\r')
        line.append(QChar(c));
    if (c == L'\r') // the console ends a line with CR LF: the LF must not start the next read
        ReadConsoleW(in, &c, 1, &got, nullptr);
    SetConsoleMode(in, old);
    context.err() << Qt::endl;
    return line;
}
#else
// One line from the terminal with echo off; nullopt when standard input is not a terminal.
std::optional<QString> readHidden(CliContext& context, const QString& prompt)
{
    if (!::isatty(STDIN_FILENO))
        return std::nullopt;
    context.err() << prompt;
    context.err().flush();
    termios old{};
    const bool saved = ::tcgetattr(STDIN_FILENO, &old) == 0;
    if (saved) {
        termios quiet = old;
        quiet.c_lflag &= ~tcflag_t(ECHO);
        ::tcsetattr(STDIN_FILENO, TCSAFLUSH, &quiet);
    }
    QByteArray line;
    int c = 0;
    while ((c = std::fgetc(stdin)) != EOF && c != '\n' && c != '\r')
        line.append(char(c));
    if (saved)
        ::tcsetattr(STDIN_FILENO, TCSAFLUSH, &old);
    context.err() << Qt::endl;
    return QString::fromUtf8(line);
}
#endif

} // namespace

QCommandLineOption CliIdentity::userOption()
{
    return {QStringLiteral("user"),
            tr("Who does it (a user of the results database); the password comes from "
               "OPENTOP_PASSWORD or is asked on the terminal."),
            tr("NAME")};
}

std::optional<QString> CliIdentity::password(CliContext& context, const char* variable,
                                             const QString& prompt, bool confirm)
{
    if (qEnvironmentVariableIsSet(variable))
        return qEnvironmentVariable(variable);
    const std::optional<QString> first = readHidden(context, prompt);
    if (!first) {
        context.err()
            << tr("error: no password: set %1 or run on a terminal").arg(QLatin1String(variable))
            << Qt::endl;
        return std::nullopt;
    }
    if (confirm) {
        const std::optional<QString> again = readHidden(context, tr("Again: "));
        if (!again || *again != *first) {
            context.err() << tr("error: the passwords differ; nothing was changed") << Qt::endl;
            return std::nullopt;
        }
    }
    return first;
}

std::optional<Identity> CliIdentity::fromOptions(CliContext& context)
{
    const QString name = context.parser().value(QStringLiteral("user")).trimmed();
    if (name.isEmpty()) {
        context.err() << tr("error: name who does it with --user NAME") << Qt::endl;
        return std::nullopt;
    }
    const std::optional<QString> pw =
        password(context, "OPENTOP_PASSWORD", tr("Password for %1: ").arg(name), false);
    if (!pw)
        return std::nullopt;
    return Identity{name, *pw};
}

} // namespace opentop
