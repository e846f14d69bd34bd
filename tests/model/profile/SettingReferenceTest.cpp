// Issue 24: profile texts name settings as the program shows them ({setting:…}, resolved in the
// language shown), and each family says how its machine number is set (AddressSwitches).
#include "model/profile/SettingReference.h"

#include "model/profile/ProfileLoader.h"
#include "model/profile/ProfileTexts.h"
#include "model/profile/ProfileTranslation.h"
#include "model/session/DeviceInfo.h"
#include "tests/model/i18n/I18nTestSupport.h"
#include "tests/model/profile/TestProfileJson.h"

#include <QJsonDocument>
#include <QRegularExpression>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

std::optional<Profile> load(const QJsonObject& json, QString* error)
{
    return ProfileLoader::loadJson(QJsonDocument(json).toJson(), QStringLiteral("test"), error);
}

// The built-in DBU's alarm 7 (Overload) in `language`.
CodeEntry overload(const QString& language)
{
    const ProfileRegistry r = registryIn(language);
    const CodeEntry* e =
        r.family(QStringLiteral("dbu"))->codeTable(QStringLiteral("alarm"))->find(7);
    EXPECT_NE(e, nullptr);
    return e ? *e : CodeEntry();
}

} // namespace

TEST(SettingReference, ATextNamesASettingByItsLabelAndPage)
{
    QString error;
    QJsonObject json = testProfileJson();
    QJsonObject tables = json.value(QStringLiteral("codeTables")).toObject();
    QJsonObject alarm = tables.value(QStringLiteral("alarm")).toObject();
    QJsonArray entries = alarm.value(QStringLiteral("entries")).toArray();
    QJsonObject first = entries.at(0).toObject();
    first.insert(QStringLiteral("remedy"),
                 QStringLiteral("Lower {setting:accel} or {setting:decel}"));
    entries.replace(0, first);
    alarm.insert(QStringLiteral("entries"), entries);
    tables.insert(QStringLiteral("alarm"), alarm);
    json.insert(QStringLiteral("codeTables"), tables);
    const auto p = load(json, &error);
    ASSERT_TRUE(p) << qPrintable(error);
    EXPECT_EQ(SettingReference::names(QStringLiteral("x {setting:b.c} {setting:a} {setting:b.c}")),
              (QStringList{QStringLiteral("a"), QStringLiteral("b.c")}));
    EXPECT_EQ(SettingReference::resolved(QStringLiteral("Lower {setting:accel}."), *p),
              QStringLiteral("Lower Acceleration (Main)."));
    Profile resolved = *p;
    SettingReference::resolveAll(resolved);
    EXPECT_EQ(resolved.codeTable(QStringLiteral("alarm"))->find(1)->remedy,
              QStringLiteral("Lower Acceleration (Main) or Deceleration (Main)"));
    // Translations are keyed by the text as written.
    EXPECT_EQ(ProfileTexts::of(resolved).value(QStringLiteral("codeTables.alarm.1.remedy")),
              QStringLiteral("Lower {setting:accel} or {setting:decel}"));

    // A reference to a parameter the profile lacks: the profile is refused, naming it.
    first.insert(QStringLiteral("remedy"), QStringLiteral("Adjust {setting:nosuch}"));
    entries.replace(0, first);
    alarm.insert(QStringLiteral("entries"), entries);
    tables.insert(QStringLiteral("alarm"), alarm);
    json.insert(QStringLiteral("codeTables"), tables);
    EXPECT_FALSE(load(json, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("codeTables.alarm.1.remedy: nosuch")))
        << qPrintable(error);
}

TEST(SettingReference, AlarmRemediesNameSettingsNotRegisterAddressesInEveryLanguage)
{
    const QRegularExpression address(QStringLiteral("0x[0-9A-Fa-f]{4}"));
    const CodeEntry en = overload(QStringLiteral("en"));
    for (const QString& text : {en.cause, en.remedy, en.resetText}) {
        EXPECT_FALSE(address.match(text).hasMatch()) << qPrintable(text);
        EXPECT_FALSE(text.contains(QStringLiteral("{setting:"))) << qPrintable(text);
    }
    EXPECT_TRUE(en.remedy.contains(
        QStringLiteral("Adjust Overload alarm output time (Alarm/warning parameters)")))
        << qPrintable(en.remedy);
    EXPECT_TRUE(en.resetText.contains(QStringLiteral("Alarm erase method (Core parameters)")))
        << qPrintable(en.resetText);
    // In Japanese the setting is named as the Japanese program shows it.
    const CodeEntry ja = overload(QStringLiteral("ja"));
    EXPECT_TRUE(
        ja.remedy.contains(QStringLiteral("過負荷アラーム出力時間 (アラーム/警告パラメータ)")))
        << qPrintable(ja.remedy);
    EXPECT_FALSE(address.match(ja.remedy).hasMatch()) << qPrintable(ja.remedy);
    // Every built-in alarm and warning text of every language is free of addresses.
    for (const QString& language : QStringList{QStringLiteral("en")} + profileLanguages()) {
        const ProfileRegistry r = registryIn(language);
        for (const Profile& p : r.profiles()) {
            for (const QString& table : {QStringLiteral("alarm"), QStringLiteral("warning")}) {
                const CodeTable* t = p.codeTable(table);
                for (const CodeEntry& e : t ? t->entries : QVector<CodeEntry>())
                    for (const QString& text : {e.cause, e.remedy, e.resetText})
                        EXPECT_FALSE(address.match(text).hasMatch())
                            << qPrintable(language + QLatin1Char(' ') + text);
            }
        }
    }
}

TEST(SettingReference, ATranslationMustKeepTheSettingsItNames)
{
    const ProfileRegistry english = registryIn(QStringLiteral("en"));
    QJsonObject root = builtInTranslationJson(QStringLiteral("dbu"), QStringLiteral("ko"));
    QJsonObject texts = root.value(QStringLiteral("texts")).toObject();
    const QString key = QStringLiteral("codeTables.alarm.7.remedy");
    texts.insert(
        key, texts.value(key).toString().replace(QStringLiteral("{setting:alarm.overload_time}"),
                                                 QStringLiteral("0x1011")));
    root.insert(QStringLiteral("texts"), texts);
    QString error;
    EXPECT_FALSE(ProfileTranslation::loadJson(
        QJsonDocument(root).toJson(), QStringLiteral("dbu.ko.json"),
        *english.family(QStringLiteral("dbu")), QStringLiteral("ko"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("the settings named"))) << qPrintable(error);
}

TEST(AddressSwitches, EachFamilyShowsItsOwnSwitches)
{
    EXPECT_EQ(DeviceInfo::switchText(150, QStringLiteral("dbu")), QStringLiteral("SW1=9 SW2=6"));
    EXPECT_EQ(DeviceInfo::switchText(7, QStringLiteral("dcpid")), QStringLiteral("DIP ON: 1,2,3"));
    EXPECT_EQ(DeviceInfo::switchText(100, QStringLiteral("dcpid")),
              QStringLiteral("DIP ON: 3,6,7"));
    EXPECT_EQ(DeviceInfo::addressText(150, QStringLiteral("dbu")),
              QStringLiteral("96h  SW1=9 SW2=6"));
    EXPECT_EQ(DeviceInfo::addressText(7, QStringLiteral("dcpid")), QStringLiteral("DIP ON: 1,2,3"));
    // Without a family: every family that can have the number.
    EXPECT_EQ(DeviceInfo::switchText(7), QStringLiteral("DBU SW1=0 SW2=7 / DCPID DIP ON: 1,2,3"));
    EXPECT_EQ(DeviceInfo::switchText(150), QStringLiteral("SW1=9 SW2=6")); // DC: 1–127 only
    const QString help = DeviceInfo::switchHelp();
    EXPECT_TRUE(help.contains(QStringLiteral("DBU: Set on the rotary switches SW1 and SW2")))
        << qPrintable(help);
    EXPECT_TRUE(help.contains(QStringLiteral("DCPID: Set in binary on DIP switches 1–7")))
        << qPrintable(help);
}

TEST(AddressSwitches, TheProfileSaysHowItsAddressIsSetOrIsRefused)
{
    QString error;
    QJsonObject json = testProfileJson();
    json.insert(QStringLiteral("address"),
                QJsonObject{{QStringLiteral("switches"), QStringLiteral("binary-dip")},
                            {QStringLiteral("names"),
                             QJsonArray{QStringLiteral("A"), QStringLiteral("B")}}});
    // Two DIP switches cannot set machine number 247.
    EXPECT_FALSE(load(json, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("cannot set machine number 247")))
        << qPrintable(error);
    json.insert(QStringLiteral("address"),
                QJsonObject{{QStringLiteral("switches"), QStringLiteral("thumbwheel")},
                            {QStringLiteral("names"), QJsonArray{QStringLiteral("A")}}});
    EXPECT_FALSE(load(json, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("hex-rotary"))) << qPrintable(error);
    json.insert(QStringLiteral("address"),
                QJsonObject{{QStringLiteral("switches"), QStringLiteral("hex-rotary")},
                            {QStringLiteral("names"),
                             QJsonArray{QStringLiteral("H"), QStringLiteral("L")}}});
    const auto p = load(json, &error);
    ASSERT_TRUE(p) << qPrintable(error);
    EXPECT_EQ(p->addressSwitches.positions(0x2A), QStringLiteral("H=2 L=A"));
    EXPECT_TRUE(p->addressSwitches.showsHex());
}
