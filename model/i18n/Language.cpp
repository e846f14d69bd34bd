#include "model/i18n/Language.h"

#include "model/ModelLog.h"
#include "model/i18n/NamespaceTranslator.h"
#include "model/profile/ProfileRegistry.h"

#include <QFile>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

namespace opentop {

namespace {

const QString kEnglish = QStringLiteral("en");
QString g_current = kEnglish;
QList<QTranslator*> g_installed;

const QString kLang = QStringLiteral("--lang");

} // namespace

QStringList Language::available()
{
    return {kEnglish, QStringLiteral("zh_TW"), QStringLiteral("zh_CN"), QStringLiteral("ko"),
            QStringLiteral("ja")};
}

QString Language::nativeName(const QString& code)
{
    // Each in its own script, never translated: a user who cannot read the current language
    // still finds theirs.
    if (code == QLatin1String("zh_TW"))
        return QStringLiteral("繁體中文");
    if (code == QLatin1String("zh_CN"))
        return QStringLiteral("简体中文");
    if (code == QLatin1String("ko"))
        return QStringLiteral("한국어");
    if (code == QLatin1String("ja"))
        return QStringLiteral("日本語");
    if (code == kEnglish)
        return QStringLiteral("English");
    return code;
}

std::optional<QString> Language::normalized(const QString& requested)
{
    QString text = requested.trimmed();
    const int dot = int(text.indexOf(QLatin1Char('.')));
    if (dot >= 0)
        text.truncate(dot); // "ko_KR.UTF-8"
    const int at = int(text.indexOf(QLatin1Char('@')));
    if (at >= 0)
        text.truncate(at);
    text.replace(QLatin1Char('-'), QLatin1Char('_'));
    const QString lower = text.toLower();
    if (lower.isEmpty())
        return std::nullopt;
    if (lower == QLatin1String("c") || lower == QLatin1String("posix") ||
        lower.startsWith(QLatin1String("en")))
        return kEnglish;
    if (lower == QLatin1String("zh_tw") || lower == QLatin1String("zh_hk") ||
        lower == QLatin1String("zh_mo") || lower == QLatin1String("zh_hant") ||
        lower.startsWith(QLatin1String("zh_hant_")))
        return QStringLiteral("zh_TW");
    if (lower == QLatin1String("zh") || lower == QLatin1String("zh_cn") ||
        lower == QLatin1String("zh_sg") || lower == QLatin1String("zh_hans") ||
        lower.startsWith(QLatin1String("zh_hans_")))
        return QStringLiteral("zh_CN");
    if (lower == QLatin1String("ko") || lower.startsWith(QLatin1String("ko_")))
        return QStringLiteral("ko");
    if (lower == QLatin1String("ja") || lower.startsWith(QLatin1String("ja_")))
        return QStringLiteral("ja");
    return std::nullopt;
}

QString Language::forLocale(const QLocale& locale)
{
    switch (locale.language()) {
    case QLocale::Chinese:
        return locale.script() == QLocale::TraditionalChineseScript ||
                       locale.territory() == QLocale::Taiwan ||
                       locale.territory() == QLocale::HongKong ||
                       locale.territory() == QLocale::Macau
                   ? QStringLiteral("zh_TW")
                   : QStringLiteral("zh_CN");
    case QLocale::Korean:
        return QStringLiteral("ko");
    case QLocale::Japanese:
        return QStringLiteral("ja");
    default:
        return kEnglish;
    }
}

QString Language::requestedIn(int argc, const char* const* argv)
{
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    return requestedIn(arguments);
}

QString Language::requestedIn(const QStringList& arguments)
{
    QString found;
    for (int i = 1; i < arguments.size(); ++i) {
        const QString& a = arguments.at(i);
        if (a == QLatin1String("--"))
            break;
        if (a == kLang || a == QLatin1String("-lang"))
            found = arguments.value(i + 1);
        else if (a.startsWith(kLang + QLatin1Char('=')))
            found = a.mid(kLang.size() + 1);
    }
    return found;
}

QString Language::saved()
{
    return QSettings().value(QStringLiteral("language")).toString();
}

void Language::save(const QString& code)
{
    QSettings settings;
    if (code.isEmpty())
        settings.remove(QStringLiteral("language"));
    else
        settings.setValue(QStringLiteral("language"), code);
}

bool Language::install(const QString& code, QString* error)
{
    const std::optional<QString> wanted = normalized(code);
    if (!wanted) {
        if (error) {
            QStringList choices = available();
            *error = tr("unknown language '%1'; available: %2")
                         .arg(code, choices.join(QStringLiteral(", ")));
        }
        return false;
    }
    uninstall();
    g_current = *wanted;
    // The device texts too, if the profiles are not loaded yet (then they stay as loaded).
    ProfileRegistry::setLanguage(*wanted);
    auto* app = QCoreApplication::instance();
    auto* own = new NamespaceTranslator(app);
    // English is the source, but its plural forms come from a file: "1 setting", "3 settings"
    // rather than "1 setting(s)".
    if (*wanted == kEnglish) {
        if (own->load(QStringLiteral(":/i18n/opentop_en.qm"))) {
            QCoreApplication::installTranslator(own);
            g_installed << own;
        } else {
            qCWarning(lcModel) << "the English plural forms are missing from this build";
            delete own;
        }
        return true;
    }
    if (!own->load(QStringLiteral(":/i18n/opentop_%1.qm").arg(*wanted))) {
        // Compiled in by the build: missing means a broken build, said plainly.
        delete own;
        if (error)
            *error = tr("the %1 translation is missing from this build").arg(*wanted);
        g_current = kEnglish;
        return false;
    }
    QCoreApplication::installTranslator(own);
    g_installed << own;
    // Qt's own texts (standard dialog buttons); Debian's qt6-translations-l10n. Without it
    // those few words stay English, which is said in the log, not an error.
    auto* qt = new QTranslator(app);
    if (qt->load(QStringLiteral("qtbase_%1").arg(*wanted),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt);
        g_installed << qt;
    } else {
        qCInfo(lcModel) << "Qt's own translation for" << *wanted << "is not installed";
        delete qt;
    }
    QLocale::setDefault(QLocale(*wanted));
    return true;
}

bool Language::installFor(const QString& requested, const QString& fallbackSetting, QString* error)
{
    if (!requested.isEmpty())
        return install(requested, error);
    if (!fallbackSetting.isEmpty() && normalized(fallbackSetting))
        return install(fallbackSetting, error);
    return install(forLocale(QLocale::system()), error);
}

void Language::uninstall()
{
    for (QTranslator* t : std::as_const(g_installed)) {
        QCoreApplication::removeTranslator(t);
        delete t;
    }
    g_installed.clear();
    QLocale::setDefault(QLocale::system());
    g_current = kEnglish;
}

QString Language::current()
{
    return g_current;
}

QLocale Language::locale()
{
    return g_current == kEnglish ? QLocale::system() : QLocale(g_current);
}

} // namespace opentop
