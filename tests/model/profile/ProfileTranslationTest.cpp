#include "model/profile/ProfileTranslation.h"

#include "model/profile/ProfileTexts.h"
#include "tests/model/i18n/I18nTestSupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

const Profile& englishProfile(const QString& family)
{
    static const ProfileRegistry english = registryIn(QStringLiteral("en"));
    const Profile* p = english.family(family);
    EXPECT_NE(p, nullptr) << qPrintable(family);
    return p ? *p : english.profiles().first();
}

// Loads the built-in ko DBU file after `change` edited it; returns the error ("" if it loaded).
QString errorAfter(const std::function<void(QJsonObject&, QJsonObject&)>& change,
                   const QString& language = QStringLiteral("ko"))
{
    QJsonObject root = builtInTranslationJson(QStringLiteral("dbu"), QStringLiteral("ko"));
    QJsonObject texts = root.value(QStringLiteral("texts")).toObject();
    change(root, texts);
    if (!root.contains(QStringLiteral("texts")) || root.value(QStringLiteral("texts")).isObject())
        root.insert(QStringLiteral("texts"), texts);
    QString error;
    const auto t =
        ProfileTranslation::loadJson(QJsonDocument(root).toJson(), QStringLiteral("dbu.ko.json"),
                                     englishProfile(QStringLiteral("dbu")), language, &error);
    EXPECT_EQ(t.has_value(), error.isEmpty());
    return error;
}

} // namespace

TEST(ProfileTranslation, EveryBuiltInLanguageValidatesAndTranslatesEveryText)
{
    static const QRegularExpression sentenceWord(QStringLiteral("[a-z]{4,}"));
    static const QRegularExpression prose(
        QStringLiteral("\\.(help|cause|remedy|resetText|note)$|^groups\\.|\\.label$|\\.name$"));
    for (const QString& family : {QStringLiteral("dbu"), QStringLiteral("dcpid")}) {
        const Profile& profile = englishProfile(family);
        const QMap<QString, QString> english = ProfileTexts::of(profile);
        for (const QString& language : profileLanguages()) {
            const QString where = family + QLatin1Char('.') + language;
            QString error;
            const auto t = ProfileTranslation::loadFile(builtInTranslationPath(family, language),
                                                        profile, language, &error);
            ASSERT_TRUE(t) << qPrintable(error);
            EXPECT_EQ(t->family(), family);
            EXPECT_EQ(t->language(), language);
            EXPECT_EQ(t->texts().keys(), english.keys()) << qPrintable(where);
            int same = 0;
            for (auto it = english.begin(); it != english.end(); ++it) {
                const QString translated = t->texts().value(it.key());
                EXPECT_FALSE(translated.trimmed().isEmpty()) << qPrintable(where + it.key());
                if (translated != it.value())
                    continue;
                ++same;
                // Sentences and names are words for people; codes, terminals and symbols
                // ("CW/CCW", "M0", "r/min") and the manual's hyphenated terminal functions
                // ("Alarm-Reset") may stay.
                const bool words = sentenceWord.match(it.value()).hasMatch() &&
                                   it.value().contains(QLatin1Char(' ')) &&
                                   !it.key().contains(QLatin1String(".enum."));
                EXPECT_FALSE(words && prose.match(it.key()).hasMatch())
                    << "untranslated: " << qPrintable(where + QLatin1Char(' ') + it.key());
            }
            // An untranslated or half-translated file: most texts equal to the English.
            EXPECT_LT(same * 100 / english.size(), 40) << qPrintable(where);
        }
    }
}

TEST(ProfileTranslation, RefusesAWrongHeader)
{
    EXPECT_TRUE(errorAfter([](QJsonObject&, QJsonObject&) {}).isEmpty());
    QString e = errorAfter([](QJsonObject& r, QJsonObject&) {
        r.insert(QStringLiteral("family"), QStringLiteral("dcpid"));
    });
    EXPECT_TRUE(e.startsWith(QStringLiteral("dbu.ko.json: "))) << qPrintable(e);
    EXPECT_TRUE(e.contains(QStringLiteral("\"family\" is \"dcpid\""))) << qPrintable(e);
    e = errorAfter([](QJsonObject&, QJsonObject&) {}, QStringLiteral("ja"));
    EXPECT_TRUE(e.contains(QStringLiteral("\"language\" is \"ko\", expected \"ja\"")))
        << qPrintable(e);
    e = errorAfter([](QJsonObject& r, QJsonObject&) {
        r.insert(QStringLiteral("format"), QStringLiteral("opentop-profile-texts"));
    });
    EXPECT_TRUE(e.contains(QStringLiteral("\"format\""))) << qPrintable(e);
    e = errorAfter(
        [](QJsonObject& r, QJsonObject&) { r.insert(QStringLiteral("formatVersion"), 2); });
    EXPECT_TRUE(e.contains(QStringLiteral("\"formatVersion\" must be 1"))) << qPrintable(e);
    e = errorAfter(
        [](QJsonObject& r, QJsonObject&) { r.insert(QStringLiteral("texts"), QJsonArray()); });
    EXPECT_TRUE(e.contains(QStringLiteral("\"texts\" must be an object"))) << qPrintable(e);
}

TEST(ProfileTranslation, NamesMissingAndUnknownKeys)
{
    const QString alarm = QStringLiteral("codeTables.alarm.1.remedy");
    QString e = errorAfter([&](QJsonObject&, QJsonObject& t) { t.remove(alarm); });
    EXPECT_TRUE(e.contains(QStringLiteral("1 key(s) of the profile missing: ") + alarm))
        << qPrintable(e);
    e = errorAfter([](QJsonObject&, QJsonObject& t) {
        t.insert(QStringLiteral("parameters.nosuch.label"), QStringLiteral("x"));
    });
    EXPECT_TRUE(
        e.contains(QStringLiteral("1 key(s) the profile does not have: parameters.nosuch.label")))
        << qPrintable(e);
    // Many of each: a few named, the count given.
    e = errorAfter([](QJsonObject&, QJsonObject& t) {
        for (int i = 0; i < 5; ++i)
            t.insert(QStringLiteral("extra.%1").arg(i), QStringLiteral("x"));
        for (const QString& k : t.keys().mid(0, 7))
            if (!k.startsWith(QLatin1String("extra")))
                t.remove(k);
    });
    EXPECT_TRUE(e.contains(QStringLiteral("7 key(s) of the profile missing"))) << qPrintable(e);
    EXPECT_TRUE(e.contains(QStringLiteral("5 key(s) the profile does not have: extra.0, extra.1, "
                                          "extra.2 and 2 more")))
        << qPrintable(e);
}

TEST(ProfileTranslation, RefusesEmptyTextsChangedPanelCodesAndPlaceholders)
{
    const QString key = QStringLiteral("codeTables.alarm.11.name"); // AL00B
    QString e =
        errorAfter([&](QJsonObject&, QJsonObject& t) { t.insert(key, QStringLiteral(" ")); });
    EXPECT_TRUE(e.contains(QStringLiteral("texts \"%1\" must be a non-empty string").arg(key)))
        << qPrintable(e);
    e = errorAfter([&](QJsonObject&, QJsonObject& t) { t.insert(key, 3); });
    EXPECT_TRUE(e.contains(key)) << qPrintable(e);

    // A text whose English names a panel code: the translation must keep it.
    const QMap<QString, QString> english = ProfileTexts::of(englishProfile(QStringLiteral("dbu")));
    QString withCode;
    for (auto it = english.begin(); it != english.end() && withCode.isEmpty(); ++it) {
        if (it.value().contains(QRegularExpression(QStringLiteral("\\bAL00[0-9A-F]\\b"))))
            withCode = it.key();
    }
    ASSERT_FALSE(withCode.isEmpty());
    e = errorAfter([&](QJsonObject&, QJsonObject& t) {
        QString text = t.value(withCode).toString();
        text.replace(QRegularExpression(QStringLiteral("AL00([0-9A-F])")),
                     QStringLiteral("AL01\\1"));
        t.insert(withCode, text);
    });
    EXPECT_TRUE(e.contains(QStringLiteral("texts \"%1\": the panel codes").arg(withCode)))
        << qPrintable(e);
    e = errorAfter([&](QJsonObject&, QJsonObject& t) {
        t.insert(key, t.value(key).toString() + QStringLiteral(" %1"));
    });
    EXPECT_TRUE(e.contains(QStringLiteral("texts \"%1\": the placeholders").arg(key)))
        << qPrintable(e);
    // A percent sign that is text is no placeholder ("Load rate %").
    EXPECT_TRUE(errorAfter([&](QJsonObject&, QJsonObject& t) {
                    t.insert(key, t.value(key).toString() + QStringLiteral(" 100 %"));
                }).isEmpty());
}

TEST(ProfileTranslation, BrokenAndOversizedFilesGiveAnErrorNotACrash)
{
    const QString family = QStringLiteral("dbu"); // named: GCC 14 fears a dangling reference
    const Profile& dbu = englishProfile(family);
    QString error;
    for (const QByteArray& bad :
         {QByteArray(), QByteArray("{"), QByteArray("[]"), QByteArray("\"x\""),
          QByteArray("{\"format\": 1}"), QByteArray("{\"texts\": {\"a\": null}}"),
          QByteArray("\xff\xfe{}")}) {
        error.clear();
        EXPECT_FALSE(ProfileTranslation::loadJson(bad, QStringLiteral("bad.json"), dbu,
                                                  QStringLiteral("ko"), &error));
        EXPECT_TRUE(error.startsWith(QStringLiteral("bad.json: "))) << qPrintable(error);
    }
    EXPECT_FALSE(ProfileTranslation::loadJson("{", QStringLiteral("bad.json"), dbu,
                                              QStringLiteral("ko"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("not valid JSON"))) << qPrintable(error);

    QTemporaryDir dir;
    const QString big = dir.filePath(QStringLiteral("dbu.ko.json"));
    QFile f(big);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(readAll(builtInTranslationPath(QStringLiteral("dbu"), QStringLiteral("ko"))));
    f.write(QByteArray(ProfileTranslation::kMaxFileBytes, ' ')); // valid JSON, just too big
    f.close();
    EXPECT_FALSE(ProfileTranslation::loadFile(big, dbu, QStringLiteral("ko"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("larger than 4 MB"))) << qPrintable(error);
    EXPECT_TRUE(error.contains(big)) << qPrintable(error);
    EXPECT_FALSE(ProfileTranslation::loadFile(dir.filePath(QStringLiteral("none.json")), dbu,
                                              QStringLiteral("ko"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("cannot read"))) << qPrintable(error);
}
