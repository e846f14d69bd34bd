#include "ui/i18n/LanguageFont.h"

#include <QApplication>
#include <QFont>
#include <QFontInfo>

namespace opentop {

QStringList LanguageFont::familiesFor(const QString& language, bool windows)
{
    // In the order of the languages below; each language's own family moves to the front.
    static const QStringList languages{QStringLiteral("zh_TW"), QStringLiteral("zh_CN"),
                                       QStringLiteral("ko"), QStringLiteral("ja")};
    const QStringList linux{QStringLiteral("Noto Sans CJK TC"), QStringLiteral("Noto Sans CJK SC"),
                            QStringLiteral("Noto Sans CJK KR"), QStringLiteral("Noto Sans CJK JP")};
    // The "UI" cuts are the ones Windows draws its own menus with; the plain ones are older.
    const QList<QStringList> win{
        {QStringLiteral("Microsoft JhengHei UI"), QStringLiteral("Microsoft JhengHei")},
        {QStringLiteral("Microsoft YaHei UI"), QStringLiteral("Microsoft YaHei")},
        {QStringLiteral("Malgun Gothic")},
        {QStringLiteral("Yu Gothic UI"), QStringLiteral("Yu Gothic"), QStringLiteral("Meiryo UI")}};
    QStringList families;
    const int own = int(languages.indexOf(language));
    for (int i = -1; i < int(languages.size()); ++i) {
        const int index = i < 0 ? own : i;
        if (index < 0 || (i >= 0 && i == own))
            continue;
        if (windows)
            families += win[index];
        else
            families << linux[index];
    }
    return families;
}

void LanguageFont::apply(const QString& language)
{
#ifdef Q_OS_WIN
    const bool windows = true;
#else
    const bool windows = false;
#endif
    QFont font = QApplication::font();
    // The family the system resolved ("Sans Serif" is an alias a list does not resolve).
    QStringList families{QFontInfo(font).family()};
    for (const QString& family : familiesFor(language, windows))
        if (!families.contains(family))
            families << family;
    font.setFamilies(families);
    QApplication::setFont(font);
}

} // namespace opentop
