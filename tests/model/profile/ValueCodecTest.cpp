#include "model/profile/ValueCodec.h"
#include "model/profile/ProfileLoader.h"
#include "tests/model/profile/TestProfileJson.h"

#include <gtest/gtest.h>

using namespace opentop;

namespace {

const Profile& profile()
{
    static const Profile p = [] {
        QString error;
        auto loaded =
            ProfileLoader::loadJson(toJson(testProfileJson()), QStringLiteral("tdev.json"), &error);
        if (!loaded)
            qFatal("%s", qPrintable(error));
        return *loaded;
    }();
    return p;
}

const ParameterMeta& meta(const char* name)
{
    const ParameterMeta* m = profile().parameter(QString::fromLatin1(name));
    if (!m)
        qFatal("no parameter %s", name);
    return *m;
}

ValueContext variant(const char* id)
{
    ValueContext c;
    c.variant = QString::fromLatin1(id);
    return c;
}

ValueContext withMode(qint64 mode)
{
    ValueContext c;
    c.parameterRaw = [mode](const QString& name) -> std::optional<qint64> {
        if (name == QLatin1String("mode"))
            return mode;
        return std::nullopt;
    };
    return c;
}

} // namespace

TEST(ValueCodec, ScaledRoundTrip)
{
    const auto e = ValueCodec::encodeNumber(meta("accel"), 2.5);
    ASSERT_TRUE(e.ok) << qPrintable(e.error);
    EXPECT_EQ(e.registers, QVector<quint16>{25});
    const ParamValue v = ValueCodec::decode(meta("accel"), {25});
    EXPECT_TRUE(v.valid);
    EXPECT_DOUBLE_EQ(v.number, 2.5);
    EXPECT_EQ(ValueCodec::format(meta("accel"), v), QStringLiteral("2.5 s"));
    // Every allowed raw value survives raw -> engineering -> raw.
    for (quint16 raw = 5; raw <= 300; ++raw) {
        const ParamValue d = ValueCodec::decode(meta("accel"), {raw});
        const auto back = ValueCodec::encodeNumber(meta("accel"), d.number);
        ASSERT_TRUE(back.ok) << raw;
        ASSERT_EQ(back.registers, QVector<quint16>{raw});
    }
}

TEST(ValueCodec, DisjointRangesNameTheAllowedValues)
{
    EXPECT_TRUE(ValueCodec::encodeNumber(meta("speed"), 0).ok);
    EXPECT_TRUE(ValueCodec::encodeNumber(meta("speed"), 250).ok);
    EXPECT_TRUE(ValueCodec::encodeNumber(meta("speed"), 3000).ok);
    const auto low = ValueCodec::encodeNumber(meta("speed"), 100);
    EXPECT_FALSE(low.ok);
    EXPECT_TRUE(low.registers.isEmpty());
    EXPECT_TRUE(low.error.contains(QStringLiteral("0 or 250–3000 r/min"))) << qPrintable(low.error);
    EXPECT_FALSE(ValueCodec::encodeNumber(meta("speed"), 3001).ok);
    EXPECT_FALSE(ValueCodec::encodeNumber(meta("speed"), 249).ok);
    const auto decel = ValueCodec::encodeNumber(meta("decel"), 1.0);
    EXPECT_FALSE(decel.ok);
    EXPECT_TRUE(decel.error.contains(QStringLiteral("0.5 or 2.0–30.0 s")))
        << qPrintable(decel.error);
    EXPECT_TRUE(ValueCodec::encodeNumber(meta("decel"), 0.5).ok);
    EXPECT_TRUE(ValueCodec::encodeNumber(meta("decel"), 2.0).ok);
}

TEST(ValueCodec, VariantChangesTheRange)
{
    EXPECT_TRUE(ValueCodec::encodeNumber(meta("speed"), 250, variant("t200")).ok);
    const auto e = ValueCodec::encodeNumber(meta("speed"), 250, variant("t400"));
    EXPECT_FALSE(e.ok);
    EXPECT_TRUE(e.error.contains(QStringLiteral("0 or 300–3000 r/min"))) << qPrintable(e.error);
    EXPECT_TRUE(ValueCodec::encodeNumber(meta("speed"), 300, variant("t400")).ok);
}

TEST(ValueCodec, RefusesValuesFinerThanTheStep)
{
    const auto e = ValueCodec::encodeNumber(meta("accel"), 2.55);
    EXPECT_FALSE(e.ok);
    EXPECT_TRUE(e.error.contains(QStringLiteral("finer than the step"))) << qPrintable(e.error);
    EXPECT_TRUE(e.error.contains(QStringLiteral("0.5–30.0 s")));
}

TEST(ValueCodec, EnumerationsByLabelOrCode)
{
    auto e = ValueCodec::encodeText(meta("direction"), QStringLiteral("ccw"));
    ASSERT_TRUE(e.ok);
    EXPECT_EQ(e.registers, QVector<quint16>{1});
    e = ValueCodec::encodeText(meta("direction"), QStringLiteral("0"));
    ASSERT_TRUE(e.ok);
    EXPECT_EQ(e.registers, QVector<quint16>{0});
    e = ValueCodec::encodeText(meta("direction"), QStringLiteral("2"));
    EXPECT_FALSE(e.ok);
    EXPECT_TRUE(e.error.contains(QStringLiteral("CW (0), CCW (1)"))) << qPrintable(e.error);
    e = ValueCodec::encodeText(meta("direction"), QStringLiteral("left"));
    EXPECT_FALSE(e.ok);
    EXPECT_TRUE(e.error.contains(QStringLiteral("\"left\" is not a valid value")));
    EXPECT_EQ(ValueCodec::format(meta("direction"), ValueCodec::decode(meta("direction"), {1})),
              QStringLiteral("CCW"));
    EXPECT_EQ(ValueCodec::format(meta("direction"), ValueCodec::decode(meta("direction"), {7})),
              QStringLiteral("unknown code 7"));
}

TEST(ValueCodec, EnumerationWhoseCodesDependOnAnotherParameter)
{
    // Mode1 codes are 0/1, Mode2 codes 16/17 (as the DBU's I/O functions).
    EXPECT_TRUE(ValueCodec::encodeText(meta("io.x0"), QStringLiteral("RUN/STOP"), withMode(0)).ok);
    EXPECT_FALSE(ValueCodec::encodeText(meta("io.x0"), QStringLiteral("RUN/STOP"), withMode(1)).ok);
    const auto mode2 =
        ValueCodec::encodeText(meta("io.x0"), QStringLiteral("not used"), withMode(1));
    ASSERT_TRUE(mode2.ok);
    EXPECT_EQ(mode2.registers, QVector<quint16>{16});
    const auto mode1 =
        ValueCodec::encodeText(meta("io.x0"), QStringLiteral("not used"), withMode(0));
    ASSERT_TRUE(mode1.ok);
    EXPECT_EQ(mode1.registers, QVector<quint16>{0});
    // Unknown mode: refuse rather than guess.
    const auto unknown = ValueCodec::encodeText(meta("io.x0"), QStringLiteral("16"));
    EXPECT_FALSE(unknown.ok);
    EXPECT_TRUE(unknown.error.contains(QStringLiteral("depend on mode")))
        << qPrintable(unknown.error);
    EXPECT_FALSE(ValueCodec::decode(meta("io.x0"), {17}, withMode(0)).allowed);
    EXPECT_TRUE(ValueCodec::decode(meta("io.x0"), {17}, withMode(1)).allowed);
}

TEST(ValueCodec, EnumBesideRange)
{
    EXPECT_EQ(ValueCodec::encodeText(meta("group"), QStringLiteral("Disabled")).registers,
              QVector<quint16>{0xFFFF});
    EXPECT_EQ(ValueCodec::encodeText(meta("group"), QStringLiteral("150")).registers,
              QVector<quint16>{150});
    const auto e = ValueCodec::encodeText(meta("group"), QStringLiteral("0"));
    EXPECT_FALSE(e.ok);
    EXPECT_TRUE(e.error.contains(QStringLiteral("1–247, or Disabled (65535)")))
        << qPrintable(e.error);
    EXPECT_FALSE(ValueCodec::encodeText(meta("group"), QStringLiteral("248")).ok);
}

TEST(ValueCodec, SignedValuesUseTwosComplement)
{
    EXPECT_EQ(ValueCodec::encodeNumber(meta("ro0"), -1).registers, QVector<quint16>{0xFFFF});
    EXPECT_EQ(ValueCodec::encodeNumber(meta("ro0"), -100).registers, QVector<quint16>{0xFF9C});
    EXPECT_DOUBLE_EQ(ValueCodec::decode(meta("ro0"), {0xFF9C}).number, -100);
    EXPECT_FALSE(ValueCodec::encodeNumber(meta("ro0"), -101).ok);
    EXPECT_FALSE(ValueCodec::decode(meta("ro0"), {0xFF9B}).allowed);
}

TEST(ValueCodec, ThirtyTwoBitHighWordFirst)
{
    // The manual's 0x10 example: reduction ratio 1.00 is written as 00 00 00 64.
    EXPECT_EQ(ValueCodec::encodeNumber(meta("reduction"), 1.0).registers,
              (QVector<quint16>{0x0000, 0x0064}));
    EXPECT_EQ(ValueCodec::encodeNumber(meta("reduction"), 9999.99).registers,
              (QVector<quint16>{0x000F, 0x423F}));
    EXPECT_DOUBLE_EQ(ValueCodec::decode(meta("reduction"), {0x0001, 0x0000}).number, 655.36);
    EXPECT_FALSE(ValueCodec::encodeNumber(meta("reduction"), 0.99).ok);
    const auto f = ValueCodec::encodeNumber(meta("pid.p"), 0.5);
    ASSERT_TRUE(f.ok);
    EXPECT_EQ(f.registers, (QVector<quint16>{0x3F00, 0x0000}));
    EXPECT_FLOAT_EQ(float(ValueCodec::decode(meta("pid.p"), {0x3DCC, 0xCCCD}).number), 0.1f);
    EXPECT_FALSE(ValueCodec::encodeNumber(meta("pid.p"), 1.5).ok);
}

TEST(ValueCodec, WordOrderDecidesWhichRegisterHoldsTheHighWord)
{
    // High word first (the default): the status bits 15–0 are in the second register.
    const ParameterMeta& high = meta("status"); // fields: bit 1 and bits 8–10 (mask 0x0702)
    ASSERT_EQ(high.wordOrder, WordOrder::HighFirst);
    EXPECT_EQ(ValueCodec::fieldMask(high), 0x0702u);
    EXPECT_DOUBLE_EQ(ValueCodec::decode(high, {0x0000, 0x0302}).raw, 0x0302);
    EXPECT_DOUBLE_EQ(ValueCodec::decode(high, {0x0001, 0x0302}).raw, 0x00010302);
    // Low word first: the same bits are in the first register.
    ParameterMeta low = high;
    low.wordOrder = WordOrder::LowFirst;
    EXPECT_DOUBLE_EQ(ValueCodec::decode(low, {0x0302, 0x0000}).raw, 0x0302);
    EXPECT_DOUBLE_EQ(ValueCodec::decode(low, {0x0302, 0x0001}).raw, 0x00010302);
}

TEST(ValueCodec, StatusBitsInTheOtherRegisterAreFound)
{
    // A drive that keeps the fields in the register the word order calls the high word: the
    // declared word reads 0 and the other one has bits only where fields are. Read either way
    // round, the running bit and the running data come out the same.
    const ParameterMeta& high = meta("status");
    EXPECT_DOUBLE_EQ(ValueCodec::decode(high, {0x0302, 0x0000}).raw, 0x0302);
    ParameterMeta low = high;
    low.wordOrder = WordOrder::LowFirst;
    EXPECT_DOUBLE_EQ(ValueCodec::decode(low, {0x0000, 0x0302}).raw, 0x0302);
    // Not swapped: bits outside the fields (0x0800), both words set, or nothing at all.
    EXPECT_FALSE(ValueCodec::wordsSwapped(high, 0x08020000u));
    EXPECT_DOUBLE_EQ(ValueCodec::decode(high, {0x0802, 0x0000}).raw, 0x08020000);
    EXPECT_FALSE(ValueCodec::wordsSwapped(high, 0x03020002u));
    EXPECT_FALSE(ValueCodec::wordsSwapped(high, 0));
    EXPECT_TRUE(ValueCodec::wordsSwapped(high, 0x03020000u));
    // Numbers have no fields to tell by: their word order is taken as declared.
    EXPECT_FALSE(ValueCodec::wordsSwapped(meta("reduction"), 0x00640000u));
}

TEST(ValueCodec, WordOrderOfNumbers)
{
    // Numbers both ways: 99999 = 0x0001869F.
    ParameterMeta wide = meta("reduction");
    EXPECT_EQ(ValueCodec::rawToRegisters(wide, 99999), (QVector<quint16>{0x0001, 0x869F}));
    EXPECT_DOUBLE_EQ(ValueCodec::registersToRaw(wide, {0x0001, 0x869F}), 99999);
    wide.wordOrder = WordOrder::LowFirst;
    EXPECT_EQ(ValueCodec::rawToRegisters(wide, 99999), (QVector<quint16>{0x869F, 0x0001}));
    EXPECT_DOUBLE_EQ(ValueCodec::registersToRaw(wide, {0x869F, 0x0001}), 99999);
    const auto encoded = ValueCodec::encodeNumber(wide, 1.0);
    ASSERT_TRUE(encoded.ok) << qPrintable(encoded.error);
    EXPECT_EQ(encoded.registers, (QVector<quint16>{0x0064, 0x0000}));
    ParameterMeta f = meta("pid.p");
    f.wordOrder = WordOrder::LowFirst;
    EXPECT_EQ(ValueCodec::rawToRegisters(f, 0.5), (QVector<quint16>{0x0000, 0x3F00}));
    EXPECT_FLOAT_EQ(float(ValueCodec::registersToRaw(f, {0xCCCD, 0x3DCC})), 0.1f);
}

TEST(ValueCodec, StringsAndBits)
{
    const ParamValue name = ValueCodec::decode(meta("info.name"), {0x5444, 0x2020, 0x2020, 0x2020});
    EXPECT_EQ(name.text, QStringLiteral("TD"));
    const auto e = ValueCodec::encodeText(meta("info.name"), QStringLiteral("ABC"));
    ASSERT_TRUE(e.ok);
    EXPECT_EQ(e.registers, (QVector<quint16>{0x4142, 0x4300, 0, 0}));
    EXPECT_FALSE(ValueCodec::encodeText(meta("info.name"), QStringLiteral("ABCDEFGHI")).ok);
    const ParamValue bits = ValueCodec::decode(meta("status"), {0x0000, 0x0302});
    EXPECT_DOUBLE_EQ(bits.raw, 0x0302);
    EXPECT_EQ(ValueCodec::format(meta("status"), bits), QStringLiteral("0x00000302"));
    EXPECT_FALSE(ValueCodec::decode(meta("status"), {0x0302}).valid); // one register short
}

TEST(ValueCodec, TextWithUnitsAndGarbage)
{
    EXPECT_EQ(ValueCodec::encodeText(meta("accel"), QStringLiteral("2.5 s")).registers,
              QVector<quint16>{25});
    EXPECT_EQ(ValueCodec::encodeText(meta("speed"), QStringLiteral("1500 rpm")).registers,
              QVector<quint16>{1500});
    EXPECT_EQ(ValueCodec::encodeText(meta("speed"), QStringLiteral("1500 r/min")).registers,
              QVector<quint16>{1500});
    EXPECT_FALSE(ValueCodec::encodeText(meta("speed"), QStringLiteral("fast")).ok);
    EXPECT_FALSE(ValueCodec::encodeText(meta("speed"), QString()).ok);
    EXPECT_FALSE(ValueCodec::encodeText(meta("speed"), QStringLiteral("1e9")).ok);
    EXPECT_FALSE(ValueCodec::encodeText(meta("speed"), QStringLiteral("nan")).ok);
}

TEST(ValueCodec, DecodeFlagsValuesOutsideTheProfile)
{
    const ParamValue v = ValueCodec::decode(meta("speed"), {100});
    EXPECT_TRUE(v.valid);
    EXPECT_FALSE(v.allowed);
    EXPECT_TRUE(v.error.contains(QStringLiteral("100 r/min is not allowed")));
    EXPECT_TRUE(ValueCodec::decode(meta("speed"), {1000}).allowed);
}

TEST(ValueCodec, UnknownVariantMustSuitEveryVariant)
{
    ValueContext unknown;
    unknown.possibleVariants = QStringList{QStringLiteral("t200"), QStringLiteral("t400")};
    const auto e = ValueCodec::encodeNumber(meta("speed"), 250, unknown);
    EXPECT_FALSE(e.ok);
    EXPECT_TRUE(e.error.contains(QStringLiteral("0 or 300–3000 r/min"))) << qPrintable(e.error);
    EXPECT_TRUE(e.error.contains(QStringLiteral("variant is not known"))) << qPrintable(e.error);
    EXPECT_TRUE(ValueCodec::encodeNumber(meta("speed"), 300, unknown).ok);
    EXPECT_TRUE(ValueCodec::encodeNumber(meta("accel"), 2.5, unknown).ok); // not variant-dependent
}

TEST(ValueCodec, UniqueLabelPrefixesAreAccepted)
{
    // "ccw" is a whole label; "c" would be the start of two labels and is refused.
    EXPECT_EQ(ValueCodec::encodeText(meta("mode"), QStringLiteral("mode2")).registers,
              QVector<quint16>{1});
    EXPECT_EQ(ValueCodec::encodeText(meta("group"), QStringLiteral("dis")).registers,
              QVector<quint16>{0xFFFF});
    EXPECT_FALSE(ValueCodec::encodeText(meta("direction"), QStringLiteral("c")).ok);
    EXPECT_FALSE(ValueCodec::encodeText(meta("mode"), QStringLiteral("mode")).ok);
}
