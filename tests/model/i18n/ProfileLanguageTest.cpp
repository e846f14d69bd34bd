// A registry in another language: texts for people translated, interfaces kept in English.
#include "model/files/BackupFile.h"
#include "model/profile/ProfileLoader.h"
#include "model/profile/ProfileTexts.h"
#include "model/profile/ValueCodec.h"
#include "tests/model/i18n/I18nTestSupport.h"
#include "tests/model/profile/TestProfileJson.h"

#include <QDir>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

QString koText(const QString& family, const QString& key)
{
    return builtInTranslationJson(family, QStringLiteral("ko"))
        .value(QStringLiteral("texts"))
        .toObject()
        .value(key)
        .toString();
}

const EnumOption* option(const ParameterMeta& meta, qint64 value)
{
    for (const EnumOption& o : meta.spec.options) {
        if (o.value == value)
            return &o;
    }
    return nullptr;
}

// Every backup setting of every built-in profile at its factory default.
BackupFile defaultsBackup(const ProfileRegistry& registry)
{
    BackupFile file;
    file.tool = QStringLiteral("OpenTOP test");
    file.created = QDateTime::fromString(QStringLiteral("2026-11-25T10:00:00Z"), Qt::ISODate);
    int slave = 1;
    for (const Profile& p : registry.profiles()) {
        BackupDevice d;
        d.slave = slave++;
        d.family = p.family;
        d.variant = p.variants.isEmpty() ? QString() : p.variants.first().id;
        d.model = p.variants.isEmpty() ? p.family : p.variants.first().model;
        for (const ParameterMeta& m : p.parameters) {
            if (m.backup && m.spec.defaultRaw)
                d.parameters << BackupParameter{m.name,
                                                ValueCodec::rawToRegisters(m, *m.spec.defaultRaw)};
        }
        file.devices << d;
    }
    return file;
}

} // namespace

TEST(ProfileLanguage, KoreanRegistryShowsKoreanAlarmTextsAndGroupLabels)
{
    const ProfileRegistry ko = registryIn(QStringLiteral("ko"));
    const ProfileRegistry en = registryIn(QStringLiteral("en"));
    const Profile* dbu = ko.family(QStringLiteral("dbu"));
    ASSERT_NE(dbu, nullptr);
    const CodeEntry* al001 = dbu->codeTable(QStringLiteral("alarm"))->find(1);
    ASSERT_NE(al001, nullptr);
    EXPECT_EQ(al001->panel, QStringLiteral("AL001"));
    EXPECT_EQ(al001->remedy,
              koText(QStringLiteral("dbu"), QStringLiteral("codeTables.alarm.1.remedy")));
    EXPECT_NE(
        al001->remedy,
        en.family(QStringLiteral("dbu"))->codeTable(QStringLiteral("alarm"))->find(1)->remedy);
    EXPECT_EQ(al001->name,
              koText(QStringLiteral("dbu"), QStringLiteral("codeTables.alarm.1.name")));
    EXPECT_EQ(dbu->group(QStringLiteral("core"))->label,
              koText(QStringLiteral("dbu"), QStringLiteral("groups.core.label")));
    EXPECT_NE(dbu->group(QStringLiteral("core"))->label,
              en.family(QStringLiteral("dbu"))->group(QStringLiteral("core"))->label);
    // Every text of both families is the Korean file's.
    for (const Profile& p : ko.profiles()) {
        const QMap<QString, QString> shown = ProfileTexts::of(p);
        const QJsonObject texts = builtInTranslationJson(p.family, QStringLiteral("ko"))
                                      .value(QStringLiteral("texts"))
                                      .toObject();
        ASSERT_EQ(shown.size(), texts.size()) << qPrintable(p.family);
        for (auto it = shown.begin(); it != shown.end(); ++it)
            EXPECT_EQ(it.value(), texts.value(it.key()).toString()) << qPrintable(it.key());
    }
}

TEST(ProfileLanguage, InterfacesStayEnglish)
{
    const ProfileRegistry ko = registryIn(QStringLiteral("ko"));
    const ProfileRegistry en = registryIn(QStringLiteral("en"));
    for (const Profile& p : ko.profiles()) {
        const Profile& e = *en.family(p.family);
        ASSERT_EQ(p.parameters.size(), e.parameters.size());
        for (int i = 0; i < p.parameters.size(); ++i) {
            const ParameterMeta& m = p.parameters[i];
            EXPECT_EQ(m.name, e.parameters[i].name);
            EXPECT_EQ(m.canonicalLabel, e.parameters[i].label);
            EXPECT_EQ(m.spec.canonicalUnit, e.parameters[i].spec.unit) << qPrintable(m.name);
            for (int j = 0; j < m.spec.options.size(); ++j)
                EXPECT_EQ(m.spec.options[j].canonicalLabel, e.parameters[i].spec.options[j].label);
            for (int c = 0; c < m.conditions.size(); ++c) {
                for (int j = 0; j < m.conditions[c].spec.options.size(); ++j)
                    EXPECT_EQ(m.conditions[c].spec.options[j].canonicalLabel,
                              e.parameters[i].conditions[c].spec.options[j].label);
            }
        }
        for (auto it = p.codeTables.begin(); it != p.codeTables.end(); ++it) {
            for (int j = 0; j < it->entries.size(); ++j)
                EXPECT_EQ(it->entries[j].panel, e.codeTables.value(it.key()).entries[j].panel);
        }
    }
    const ParameterMeta* priority =
        ko.family(QStringLiteral("dbu"))->parameter(QStringLiteral("core.control_priority"));
    ASSERT_NE(priority, nullptr);
    const EnumOption* comm = option(*priority, 2);
    ASSERT_NE(comm, nullptr);
    EXPECT_EQ(comm->canonicalLabel, QStringLiteral("Communication priority"));
    EXPECT_EQ(comm->label, koText(QStringLiteral("dbu"),
                                  QStringLiteral("parameters.core.control_priority.enum.2")));
    EXPECT_NE(comm->label, comm->canonicalLabel);
}

TEST(ProfileLanguage, TypedValuesAcceptTheEnglishAndTheTranslatedLabel)
{
    const ProfileRegistry ko = registryIn(QStringLiteral("ko"));
    const ParameterMeta& priority =
        *ko.family(QStringLiteral("dbu"))->parameter(QStringLiteral("core.control_priority"));
    const EnumOption& comm = *option(priority, 2);
    for (const QString& typed :
         {QStringLiteral("Communication priority"), QStringLiteral("communication"), comm.label}) {
        const ValueCodec::Encoded e = ValueCodec::encodeText(priority, typed);
        EXPECT_TRUE(e.ok) << qPrintable(typed) << qPrintable(e.error);
        EXPECT_EQ(e.raw, 2) << qPrintable(typed);
    }
    // What a value reads as: the English for files and scripts, the Korean for people.
    const ParamValue v = ValueCodec::decode(priority, {2});
    EXPECT_EQ(v.text, QStringLiteral("Communication priority"));
    EXPECT_EQ(ValueCodec::formatCanonical(priority, v), QStringLiteral("Communication priority"));
    EXPECT_EQ(ValueCodec::format(priority, v), comm.label);

    // A unit the translation changes (Korean days): both read, the file keeps the profile's.
    const ParameterMeta* days =
        ko.family(QStringLiteral("dbu"))->parameter(QStringLiteral("va.countdown_days"));
    ASSERT_NE(days, nullptr);
    ASSERT_NE(days->spec.unit, days->spec.canonicalUnit);
    const double someDays = days->spec.ranges.isEmpty() ? 1 : days->spec.ranges.last().max;
    const QString n = QString::number(someDays);
    for (const QString& typed : {n + QLatin1Char(' ') + days->spec.unit,
                                 n + QLatin1Char(' ') + days->spec.canonicalUnit}) {
        const ValueCodec::Encoded e = ValueCodec::encodeText(*days, typed);
        EXPECT_TRUE(e.ok) << qPrintable(typed) << qPrintable(e.error);
    }
    const ParamValue d = ValueCodec::decode(*days, ValueCodec::rawToRegisters(*days, someDays));
    EXPECT_TRUE(ValueCodec::formatCanonical(*days, d).endsWith(QStringLiteral(" d")));
    EXPECT_TRUE(ValueCodec::format(*days, d).endsWith(days->spec.unit));
}

TEST(ProfileLanguage, BackupFromATranslatedRegistryEqualsTheEnglishOne)
{
    for (const QString& language : profileLanguages()) {
        const ProfileRegistry translated = registryIn(language);
        const ProfileRegistry en = registryIn(QStringLiteral("en"));
        const BackupFile file = defaultsBackup(en);
        const QByteArray english = file.toJson(en);
        ASSERT_TRUE(english.contains("\"text\""));
        EXPECT_EQ(file.toJson(translated), english) << qPrintable(language);
        // While the same values read in the language for people.
        const BackupDevice& dbu = file.devices.first();
        const Profile& tp = *translated.family(dbu.family);
        const Profile& ep = *en.family(dbu.family);
        int differing = 0;
        for (const BackupParameter& p : dbu.parameters)
            differing += dbu.text(tp, p.name) != dbu.text(ep, p.name);
        EXPECT_GT(differing, 0) << qPrintable(language);
        // The translated registry reads the file back.
        QString error;
        EXPECT_TRUE(BackupFile::fromJson(english, translated, &error)) << qPrintable(error);
    }
}

TEST(ProfileLanguage, AFamilyWithoutATranslationStaysEnglish)
{
    QTemporaryDir dir;
    ASSERT_TRUE(QDir(dir.path()).mkpath(QStringLiteral("profiles/i18n")));
    const QString profiles = dir.filePath(QStringLiteral("profiles"));
    const QString texts = dir.filePath(QStringLiteral("profiles/i18n"));
    ASSERT_TRUE(
        QFile::copy(QStringLiteral(":/profiles/dbu.json"), profiles + QStringLiteral("/dbu.json")));
    QFile third(profiles + QStringLiteral("/tdev.json"));
    ASSERT_TRUE(third.open(QIODevice::WriteOnly));
    third.write(QJsonDocument(testProfileJson()).toJson());
    third.close();
    ASSERT_TRUE(QFile::copy(builtInTranslationPath(QStringLiteral("dbu"), QStringLiteral("ko")),
                            texts + QStringLiteral("/dbu.ko.json")));
    QString error;
    const auto ko = ProfileRegistry::load(QStringLiteral("ko"), &error, profiles, texts);
    ASSERT_TRUE(ko) << qPrintable(error);
    ASSERT_EQ(ko->families(), (QStringList{QStringLiteral("dbu"), QStringLiteral("tdev")}));
    EXPECT_EQ(ko->family(QStringLiteral("dbu"))->name,
              koText(QStringLiteral("dbu"), QStringLiteral("name")));
    EXPECT_EQ(ko->family(QStringLiteral("tdev"))->name, QStringLiteral("Test drive"));
    EXPECT_EQ(ko->family(QStringLiteral("tdev"))->codeTable(QStringLiteral("alarm"))->find(1)->name,
              QStringLiteral("Overvoltage"));

    // A translation that exists but does not fit is refused with its name and key.
    QFile broken(texts + QStringLiteral("/tdev.ko.json"));
    ASSERT_TRUE(broken.open(QIODevice::WriteOnly));
    broken.write(R"({"format": "opentop-profile-translation", "formatVersion": 1,
                     "family": "tdev", "language": "ko", "texts": {"name": "시험"}})");
    broken.close();
    EXPECT_FALSE(ProfileRegistry::load(QStringLiteral("ko"), &error, profiles, texts));
    EXPECT_TRUE(error.startsWith(QStringLiteral("tdev.ko.json: "))) << qPrintable(error);
    EXPECT_TRUE(error.contains(QStringLiteral("missing"))) << qPrintable(error);
}

TEST(ProfileLanguage, TheBuiltInLanguageIsFixedOnceTheProfilesAreLoaded)
{
    const QString before = ProfileRegistry::language();
    ProfileRegistry::builtIn();
    EXPECT_FALSE(ProfileRegistry::setLanguage(
        before == QLatin1String("ko") ? QStringLiteral("ja") : QStringLiteral("ko")));
    EXPECT_EQ(ProfileRegistry::language(), before);
    EXPECT_TRUE(ProfileRegistry::setLanguage(before)); // the same language: nothing changes
}
