#include "model/profile/ProfileTexts.h"

#include "model/profile/ProfileLoader.h"
#include "tests/model/i18n/I18nTestSupport.h"
#include "tests/model/profile/TestProfileJson.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <gtest/gtest.h>

using namespace opentop;

// The key set and English texts equal what translations/profiles/extract.py made: the files the
// translators worked from, and the keys of every translation.
TEST(ProfileTexts, EqualExtractPyOutputForEveryBuiltInProfile)
{
    const ProfileRegistry english = registryIn(QStringLiteral("en"));
    ASSERT_EQ(english.families(), (QStringList{QStringLiteral("dbu"), QStringLiteral("dcpid")}));
    for (const Profile& profile : english.profiles()) {
        const QString path = QStringLiteral(OPENTOP_SOURCE_DIR "/translations/profiles/%1.en.json")
                                 .arg(profile.family);
        const QJsonObject file = QJsonDocument::fromJson(readAll(path)).object();
        ASSERT_EQ(file.value(QStringLiteral("family")).toString(), profile.family)
            << qPrintable(path);
        const QJsonObject texts = file.value(QStringLiteral("texts")).toObject();
        const QMap<QString, QString> ours = ProfileTexts::of(profile);
        EXPECT_EQ(ours.size(), texts.size()) << qPrintable(profile.family);
        for (auto it = texts.begin(); it != texts.end(); ++it)
            EXPECT_EQ(ours.value(it.key()), it.value().toString()) << qPrintable(it.key());
        for (auto it = ours.begin(); it != ours.end(); ++it)
            EXPECT_TRUE(texts.contains(it.key()))
                << "not in extract.py's output: " << qPrintable(it.key());
    }
}

TEST(ProfileTexts, ConditionsNameOnlyTheTextsTheyGiveThemselves)
{
    QString error;
    const auto p = ProfileLoader::loadJson(QJsonDocument(testProfileJson()).toJson(),
                                           QStringLiteral("test"), &error);
    ASSERT_TRUE(p) << qPrintable(error);
    const QMap<QString, QString> texts = ProfileTexts::of(*p);
    // io.x0's `when` gives its own enumeration; speed's only another range.
    EXPECT_EQ(texts.value(QStringLiteral("parameters.io.x0.w0.enum.1")),
              QStringLiteral("RUN/STOP"));
    EXPECT_EQ(texts.value(QStringLiteral("parameters.io.x0.enum.17")), QStringLiteral("CW/STOP"));
    EXPECT_FALSE(texts.contains(QStringLiteral("parameters.speed.w0.unit")));
    EXPECT_EQ(texts.value(QStringLiteral("parameters.speed.unit")), QStringLiteral("r/min"));
    EXPECT_EQ(texts.value(QStringLiteral("codeTables.alarm.3.name")),
              QStringLiteral("Overcurrent"));
    EXPECT_EQ(texts.value(QStringLiteral("name")), QStringLiteral("Test drive"));
}
