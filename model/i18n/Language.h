#pragma once

#include <QCoreApplication>
#include <QLocale>
#include <QString>
#include <QStringList>
#include <optional>

namespace opentop {

// The language people read OpenTOP in: English (the source) or one of the translations
// compiled in (translations/opentop_<code>.ts). Chosen by --lang on every executable, else the
// GUI's setting, else the system locale. Installed once, before any text is made: the program's
// messages, Qt's own (dialog buttons), the device profiles' texts (ProfileRegistry) and the
// locale that formats dates and numbers for people. Files and --json never follow it.
class Language
{
    Q_DECLARE_TR_FUNCTIONS(opentop::Language)
public:
    // "en" and every translated language, in menu order.
    static QStringList available();
    // The language's name in itself ("한국어"), for a language menu.
    static QString nativeName(const QString& code);
    // A language code as people write it ("zh-TW", "zh_tw", "ko_KR", "ja.UTF-8", "C") as one of
    // available(); nullopt when none matches.
    static std::optional<QString> normalized(const QString& requested);
    // The translated language a locale asks for; "en" when there is none (zh_HK reads
    // Traditional Chinese, zh_SG Simplified).
    static QString forLocale(const QLocale& locale);
    // --lang X or --lang=X from a raw command line, before any parser (whose help is translated)
    // exists; empty when absent.
    static QString requestedIn(int argc, const char* const* argv);
    static QString requestedIn(const QStringList& arguments);
    // The choice saved by the GUI's language menu (QSettings "language"); empty: the system's.
    static QString saved();
    static void save(const QString& code);

    // Installs `code` on the application: translators, Qt's translations, the default locale and
    // the device profiles' language. Call once, after the QCoreApplication exists and before any
    // window, parser or profile. An unknown code is refused with a message naming the choices.
    static bool install(const QString& code, QString* error);
    // Resolves what a program was asked for (--lang, else `fallbackSetting`, else the system
    // locale) and installs it.
    static bool installFor(const QString& requested, const QString& fallbackSetting,
                           QString* error);
    // Takes back what install() put in place: English again (tests that show the program in
    // several languages in one process).
    static void uninstall();
    // What install() put in place ("en" before).
    static QString current();
    // The locale people read numbers and dates in: the installed language's.
    static QLocale locale();
};

} // namespace opentop
