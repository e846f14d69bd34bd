// A profile's recommended range beside its allowed range ("recommended"): values allowed but
// outside it are accepted with a warning naming it, values outside the allowed range refused.
#include "model/profile/ProfileLoader.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include "tests/model/profile/TestProfileJson.h"

#include <QJsonArray>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

const ParameterMeta& dc(const char* name)
{
    const Profile* p = ProfileRegistry::builtIn().family(QStringLiteral("dcpid"));
    const ParameterMeta* m = p ? p->parameter(QString::fromLatin1(name)) : nullptr;
    if (!m)
        qFatal("no dcpid parameter %s", name);
    return *m;
}

// The test profile with `edit` applied to its parameter `name`.
std::optional<Profile> loadEdited(const QString& name,
                                  const std::function<void(QJsonObject&)>& edit, QString* error)
{
    QJsonObject root = testProfileJson();
    QJsonArray params = root.value(QStringLiteral("parameters")).toArray();
    for (int i = 0; i < params.size(); ++i) {
        QJsonObject p = params[i].toObject();
        if (p.value(QStringLiteral("name")).toString() != name)
            continue;
        edit(p);
        params[i] = p;
    }
    root[QStringLiteral("parameters")] = params;
    return ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), error);
}

QJsonArray interval(double min, double max)
{
    return QJsonArray{QJsonObject{{QStringLiteral("min"), min}, {QStringLiteral("max"), max}}};
}

} // namespace

TEST(RecommendedRange, PidCoefficientsAreAllowedTo100AndRecommendedTo1)
{
    for (const char* name : {"pid.p", "pid.i", "pid.d"}) {
        const ValueSpec& spec = dc(name).spec;
        ASSERT_EQ(spec.ranges.size(), 1) << name;
        EXPECT_EQ(spec.ranges.first().min, 0) << name;
        EXPECT_EQ(spec.ranges.first().max, 100) << name; // the autotune relies on exactly 100
        ASSERT_EQ(spec.recommended.size(), 1) << name;
        EXPECT_EQ(spec.recommended.first().min, 0) << name;
        EXPECT_EQ(spec.recommended.first().max, 1) << name;
    }
}

TEST(RecommendedRange, AboveTheRecommendationIsEncodedWithAWarningNamingIt)
{
    const ParameterMeta& p = dc("pid.p");
    const ValueCodec::Encoded inside = ValueCodec::encodeText(p, QStringLiteral("0.5"));
    ASSERT_TRUE(inside.ok) << qPrintable(inside.error);
    EXPECT_TRUE(inside.warning.isEmpty()) << qPrintable(inside.warning);

    const ValueCodec::Encoded above = ValueCodec::encodeText(p, QStringLiteral("2.5"));
    ASSERT_TRUE(above.ok) << qPrintable(above.error);
    EXPECT_EQ(above.registers, (QVector<quint16>{0x4020, 0x0000})); // 2.5f, high word first
    EXPECT_EQ(above.warning, QStringLiteral("pid.p: 2.5000 is outside the recommended range "
                                            "0.0000–1.0000; it is allowed and will be written"));
    EXPECT_EQ(ValueCodec::recommendationWarning(p, 2.5), above.warning);
    EXPECT_TRUE(ValueCodec::recommendationWarning(p, 1.0).isEmpty());
    EXPECT_TRUE(ValueCodec::recommendationWarning(p, 0.0).isEmpty());
    EXPECT_EQ(ValueCodec::recommendedText(p), QStringLiteral("0.0000–1.0000"));
    // The allowed maximum itself: still only a warning.
    const ValueCodec::Encoded top = ValueCodec::encodeNumber(p, 100);
    EXPECT_TRUE(top.ok) << qPrintable(top.error);
    EXPECT_FALSE(top.warning.isEmpty());
}

TEST(RecommendedRange, OutsideTheAllowedRangeIsRefusedAsBefore)
{
    const ParameterMeta& i = dc("pid.i");
    for (const char* text : {"100.5", "-0.1", "1000"}) {
        const ValueCodec::Encoded e = ValueCodec::encodeText(i, QString::fromLatin1(text));
        EXPECT_FALSE(e.ok) << text;
        EXPECT_TRUE(e.registers.isEmpty()) << text;
        EXPECT_TRUE(e.error.contains(QStringLiteral("allowed: 0.0000–100.0000")))
            << qPrintable(e.error);
        EXPECT_TRUE(e.warning.isEmpty()) << text;
    }
}

TEST(RecommendedRange, ParametersWithoutARecommendationNeverWarn)
{
    const ParameterMeta& current = dc("config.rated_current");
    EXPECT_TRUE(current.spec.recommended.isEmpty());
    const ValueCodec::Encoded e = ValueCodec::encodeText(current, QStringLiteral("20"));
    EXPECT_TRUE(e.ok);
    EXPECT_TRUE(e.warning.isEmpty());
    EXPECT_TRUE(ValueCodec::recommendationWarning(current, 2000).isEmpty());
}

TEST(RecommendedRange, TheLoaderReadsItAndRefusesOneOutsideTheAllowedRange)
{
    QString error;
    auto loaded = loadEdited(
        QStringLiteral("pid.p"),
        [](QJsonObject& p) { p[QStringLiteral("recommended")] = interval(0.001, 0.5); }, &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    const ParameterMeta* p = loaded->parameter(QStringLiteral("pid.p"));
    ASSERT_EQ(p->spec.recommended.size(), 1);
    EXPECT_DOUBLE_EQ(p->spec.recommended.first().max, 0.5);
    EXPECT_FALSE(ValueCodec::recommendationWarning(*p, 0.75).isEmpty());

    loaded = loadEdited(
        QStringLiteral("pid.p"),
        [](QJsonObject& edited) { edited[QStringLiteral("recommended")] = interval(0, 2); },
        &error);
    EXPECT_FALSE(loaded);
    EXPECT_TRUE(error.contains(QStringLiteral("recommended[0] is not inside one of the "
                                              "\"allowed\" intervals")))
        << qPrintable(error);
}
