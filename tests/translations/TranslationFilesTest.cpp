// The program's translations (issue 13): every .ts file finished, in step with the source (no
// message the code has that a file lacks, none a file keeps that the code lost), and every
// translation carrying the source's placeholders, rich-text tags and accelerator.
#include "model/i18n/Language.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <gtest/gtest.h>

namespace {

struct Message
{
    QString context;
    QString source;
    QString type;             // "", "unfinished", "vanished", "obsolete"
    QStringList translations; // one, or the numerus forms
    qint64 line = 0;
};

std::vector<Message> readTs(const QString& path, QString* error)
{
    std::vector<Message> messages;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.errorString();
        return messages;
    }
    QXmlStreamReader xml(&file);
    QString context;
    Message m;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            m = Message();
            m.context = context;
            m.line = xml.lineNumber();
        } else if (name == QLatin1String("source")) {
            m.source = xml.readElementText();
        } else if (name == QLatin1String("translation")) {
            m.type = xml.attributes().value(QLatin1String("type")).toString();
            // Either text or <numerusform> children.
            QString text;
            while (!(xml.isEndElement() && xml.name() == QLatin1String("translation")) &&
                   !xml.atEnd()) {
                xml.readNext();
                if (xml.isCharacters())
                    text += xml.text();
                else if (xml.isStartElement() && xml.name() == QLatin1String("numerusform"))
                    m.translations << xml.readElementText();
            }
            if (m.translations.isEmpty())
                m.translations << text;
            messages.push_back(m);
        }
    }
    if (xml.hasError())
        *error = QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return messages;
}

QStringList sorted(QStringList list)
{
    list.sort();
    return list;
}

QStringList matches(const QRegularExpression& re, const QString& text)
{
    QStringList found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found << it.next().captured(0);
    return sorted(found);
}

const QRegularExpression kPlaceholder(QStringLiteral("%(?:L?\\d{1,2}|n|%)"));
const QRegularExpression kTag(QStringLiteral("</?[A-Za-z][A-Za-z0-9]*(?:\\s[^<>]*)?/?>"));

// The mnemonic letters of a text ("&File", "檔案(&F)"); "&&" is a literal ampersand.
QStringList accelerators(const QString& text)
{
    QStringList found;
    for (int i = 0; i + 1 < text.size(); ++i) {
        if (text.at(i) != QLatin1Char('&'))
            continue;
        if (text.at(i + 1) == QLatin1Char('&')) {
            ++i;
            continue;
        }
        if (text.at(i + 1).isLetterOrNumber())
            found << text.at(i + 1).toUpper();
    }
    return found;
}

QStringList tsFiles()
{
    const QDir dir(QStringLiteral(OPENTOP_SOURCE_DIR "/translations"));
    QStringList files;
    for (const QString& f : dir.entryList({QStringLiteral("opentop_*.ts")}, QDir::Files))
        files << dir.filePath(f);
    return files;
}

QString where(const QString& file, const Message& m)
{
    return QStringLiteral("%1:%2 [%3] \"%4\"")
        .arg(QFileInfo(file).fileName())
        .arg(m.line)
        .arg(m.context, m.source.left(70));
}

} // namespace

TEST(TranslationFilesTest, EveryLanguageTheProgramOffersHasAFileAndEveryFileIsOffered)
{
    QStringList offered = opentop::Language::available();
    offered.removeAll(QStringLiteral("en")); // the source
    QStringList files;
    for (const QString& f : tsFiles())
        files << QFileInfo(f).completeBaseName().mid(int(qstrlen("opentop_")));
    EXPECT_EQ(sorted(files), sorted(offered));
}

TEST(TranslationFilesTest, EveryMessageIsTranslatedWithTheSourcesPlaceholdersTagsAndAccelerator)
{
    const QStringList files = tsFiles();
    ASSERT_FALSE(files.isEmpty());
    QStringList problems;
    std::map<QString, QStringList> keysByFile;
    for (const QString& file : files) {
        QString error;
        const std::vector<Message> messages = readTs(file, &error);
        ASSERT_TRUE(error.isEmpty()) << qPrintable(error);
        ASSERT_GT(messages.size(), 1000u) << qPrintable(file);
        for (const Message& m : messages) {
            keysByFile[file] << m.context + QLatin1Char('|') + m.source;
            if (!m.type.isEmpty()) {
                problems << where(file, m) + QStringLiteral(": %1").arg(m.type);
                continue;
            }
            for (const QString& t : m.translations) {
                if (t.trimmed().isEmpty()) {
                    problems << where(file, m) + QStringLiteral(": empty translation");
                    continue;
                }
                if (matches(kPlaceholder, m.source) != matches(kPlaceholder, t))
                    problems << where(file, m) +
                                    QStringLiteral(": placeholders %1 vs %2")
                                        .arg(matches(kPlaceholder, m.source).join(u' '),
                                             matches(kPlaceholder, t).join(u' '));
                if (matches(kTag, m.source) != matches(kTag, t))
                    problems << where(file, m) + QStringLiteral(": tags differ");
                if (accelerators(m.source) != accelerators(t))
                    problems << where(file, m) + QStringLiteral(": accelerator %1 vs %2")
                                                     .arg(accelerators(m.source).join(u' '),
                                                          accelerators(t).join(u' '));
            }
        }
    }
    // The same messages in every language.
    const QStringList first = sorted(keysByFile.begin()->second);
    for (const auto& [file, keys] : keysByFile)
        EXPECT_EQ(sorted(keys), first) << qPrintable(file);
    EXPECT_TRUE(problems.isEmpty()) << problems.size() << " problem(s):\n"
                                    << qPrintable(problems.mid(0, 40).join(u'\n'));
}

// lupdate over the source tree, into a copy of each file: a message the code gained is
// "unfinished" in the copy, one it lost is "vanished". Either means the file is out of step.
TEST(TranslationFilesTest, TheFilesAreInStepWithTheSource)
{
    const QString lupdate = QStringLiteral(OPENTOP_LUPDATE);
    ASSERT_TRUE(QFileInfo(lupdate).isExecutable())
        << "lupdate (Debian package qt6-l10n-tools) is needed: " << qPrintable(lupdate);
    QTemporaryDir dir;
    QStringList copies;
    for (const QString& file : tsFiles()) {
        const QString copy = dir.filePath(QFileInfo(file).fileName());
        ASSERT_TRUE(QFile::copy(file, copy));
        copies << copy;
    }
    QProcess p;
    p.setWorkingDirectory(QStringLiteral(OPENTOP_SOURCE_DIR));
    p.start(lupdate, QStringList{QStringLiteral("-silent")}
                         << QStringLiteral(OPENTOP_LUPDATE_DIRS).split(u' ')
                         << QStringLiteral("-ts") << copies);
    ASSERT_TRUE(p.waitForFinished(120000));
    ASSERT_EQ(p.exitCode(), 0) << p.readAllStandardError().constData();
    QStringList problems;
    for (const QString& copy : copies) {
        QString error;
        for (const Message& m : readTs(copy, &error)) {
            if (m.type == QLatin1String("unfinished"))
                problems << where(copy, m) + QStringLiteral(": in the code, not translated");
            else if (m.type == QLatin1String("vanished") || m.type == QLatin1String("obsolete"))
                problems << where(copy, m) + QStringLiteral(": no longer in the code");
        }
        ASSERT_TRUE(error.isEmpty()) << qPrintable(error);
    }
    EXPECT_TRUE(problems.isEmpty())
        << problems.size() << " message(s) out of step; run the update_translations target and "
        << "translate:\n"
        << qPrintable(problems.mid(0, 40).join(u'\n'));
}

// English is the source; only its plural forms come from a file (translations/plurals): every
// %n message of the code there, finished, "1 setting" and "3 settings" with the source's
// placeholders, and no "word(s)" left for the counted noun.
TEST(TranslationFilesTest, EveryEnglishPluralHasItsTwoFormsAndIsInStepWithTheSource)
{
    const QString file = QStringLiteral(OPENTOP_SOURCE_DIR "/translations/plurals/opentop_en.ts");
    QString error;
    const std::vector<Message> messages = readTs(file, &error);
    ASSERT_TRUE(error.isEmpty()) << qPrintable(error);
    ASSERT_GT(messages.size(), 40u);
    QStringList problems;
    for (const Message& m : messages) {
        if (!m.type.isEmpty() || m.translations.size() != 2) {
            problems << where(file, m) + QStringLiteral(": not two finished forms");
            continue;
        }
        for (const QString& t : m.translations)
            if (matches(kPlaceholder, m.source) != matches(kPlaceholder, t))
                problems << where(file, m) + QStringLiteral(": placeholders differ in ") + t;
        // The noun %n counts has lost its "(s)" in both forms.
        static const QRegularExpression counted(QStringLiteral("%n (?:[\\w-]+ )?[\\w-]+\\(s\\)"));
        for (const QString& t : m.translations)
            if (counted.match(t).hasMatch())
                problems << where(file, m) + QStringLiteral(": \"(s)\" left in ") + t;
        if (m.translations.first() == m.translations.last())
            problems << where(file, m) + QStringLiteral(": one and many read the same");
    }
    EXPECT_TRUE(problems.isEmpty()) << qPrintable(problems.mid(0, 40).join(u'\n'));

    // In step: lupdate -pluralonly into a copy finds nothing new and nothing gone.
    QTemporaryDir dir;
    const QString copy = dir.filePath(QStringLiteral("opentop_en.ts"));
    ASSERT_TRUE(QFile::copy(file, copy));
    QProcess p;
    p.setWorkingDirectory(QStringLiteral(OPENTOP_SOURCE_DIR));
    p.start(QStringLiteral(OPENTOP_LUPDATE),
            QStringList{QStringLiteral("-silent"), QStringLiteral("-pluralonly")}
                << QStringLiteral(OPENTOP_LUPDATE_DIRS).split(u' ') << QStringLiteral("-ts")
                << copy);
    ASSERT_TRUE(p.waitForFinished(120000));
    ASSERT_EQ(p.exitCode(), 0) << p.readAllStandardError().constData();
    QStringList stale;
    for (const Message& m : readTs(copy, &error))
        if (!m.type.isEmpty())
            stale << where(copy, m) + QLatin1Char(' ') + m.type;
    EXPECT_TRUE(stale.isEmpty()) << "run the update_translations target:\n"
                                 << qPrintable(stale.mid(0, 20).join(u'\n'));
}

TEST(TranslationFilesTest, EnglishSaysOneSettingAndThreeSettings)
{
    QString error;
    ASSERT_TRUE(opentop::Language::install(QStringLiteral("en"), &error)) << qPrintable(error);
    const char* source = "Write %n setting(s) to drive(s) %1, each verified by reading it back?";
    EXPECT_EQ(QCoreApplication::translate("opentop::RestoreDialog", source, nullptr, 1),
              QStringLiteral("Write 1 setting to drive(s) %1, each verified by reading it back?"));
    EXPECT_EQ(QCoreApplication::translate("opentop::RestoreDialog", source, nullptr, 3),
              QStringLiteral("Write 3 settings to drive(s) %1, each verified by reading it back?"));
    opentop::Language::uninstall();
    EXPECT_EQ(
        QCoreApplication::translate("opentop::RestoreDialog", source, nullptr, 1),
        QStringLiteral("Write 1 setting(s) to drive(s) %1, each verified by reading it back?"));
}
