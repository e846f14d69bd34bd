// What the program's translation files say an English text is in a language, for tests that
// find actions and buttons by the text a user sees.
#pragma once

#include <QFile>
#include <QHash>
#include <QRegularExpression>
#include <QStringList>
#include <QXmlStreamReader>

namespace opentop::test {

// A menu or button text without its accelerator ("&Connect…", "連線(&C)…" → "Connect", "連線").
inline QString plainMenuText(QString text)
{
    static const QRegularExpression cjkAccelerator(QStringLiteral("\\(&[^)]\\)"));
    text.remove(cjkAccelerator);
    text.remove(QLatin1Char('&'));
    text.remove(QChar(0x2026));
    text.remove(QStringLiteral("..."));
    return text.trimmed();
}

// The plain texts `english` (plain too) translates to in `language`; {english} for "en".
inline QStringList translationsOf(const QString& language, const QString& english)
{
    if (language == QLatin1String("en"))
        return {english};
    static QHash<QString, QMultiHash<QString, QString>> cache;
    if (!cache.contains(language)) {
        QMultiHash<QString, QString>& index = cache[language];
        QFile file(QStringLiteral(OPENTOP_SOURCE_DIR "/translations/opentop_%1.ts").arg(language));
        if (file.open(QIODevice::ReadOnly)) {
            QXmlStreamReader xml(&file);
            QString source;
            while (!xml.atEnd()) {
                xml.readNext();
                if (!xml.isStartElement())
                    continue;
                if (xml.name() == QLatin1String("source"))
                    source = plainMenuText(xml.readElementText());
                else if (xml.name() == QLatin1String("translation"))
                    index.insert(source, plainMenuText(xml.readElementText(
                                             QXmlStreamReader::IncludeChildElements)));
            }
        }
    }
    QStringList found = cache[language].values(english);
    found.removeDuplicates();
    return found;
}

} // namespace opentop::test
