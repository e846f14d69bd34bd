#include "model/profile/ProfileLoader.h"
#include "tests/model/profile/TestProfileJson.h"

#include <QJsonArray>
#include <functional>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

// Applies `edit` to parameter `index` of the test profile and loads the result.
std::optional<Profile> loadWithParam(int index, const std::function<void(QJsonObject&)>& edit,
                                     QString* error)
{
    QJsonObject root = testProfileJson();
    QJsonArray params = root.value(QStringLiteral("parameters")).toArray();
    QJsonObject p = params[index].toObject();
    edit(p);
    params[index] = p;
    root[QStringLiteral("parameters")] = params;
    return ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), error);
}

} // namespace

TEST(ProfileLoader, LoadsValidProfileWithEveryFeature)
{
    QString error;
    const auto profile =
        ProfileLoader::loadJson(toJson(testProfileJson()), QStringLiteral("tdev.json"), &error);
    ASSERT_TRUE(profile) << qPrintable(error);
    EXPECT_EQ(profile->family, QStringLiteral("tdev"));
    EXPECT_EQ(profile->maxReadRegisters, 17);
    EXPECT_EQ(profile->variants.size(), 2);
    const ParameterMeta* speed = profile->parameter(QStringLiteral("speed"));
    ASSERT_NE(speed, nullptr);
    EXPECT_EQ(speed->address, 0xCA03);
    EXPECT_EQ(speed->access, Access::ReadWrite);
    EXPECT_TRUE(speed->backup);
    ASSERT_EQ(speed->conditions.size(), 1);
    EXPECT_EQ(speed->conditions[0].spec.ranges[1].min, 300);
    const ParameterMeta* accel = profile->parameter(QStringLiteral("accel"));
    EXPECT_EQ(accel->spec.ranges[0].min, 5); // raw, 0.5 s at 0.1 s
    EXPECT_EQ(accel->spec.ranges[0].max, 300);
    EXPECT_EQ(accel->spec.decimals, 1);
    EXPECT_EQ(*accel->spec.defaultRaw, 5);
    EXPECT_EQ(*profile->parameter(QStringLiteral("group"))->spec.defaultRaw, 65535);
    EXPECT_EQ(profile->parameter(QStringLiteral("reduction"))->registerCount, 2);
    EXPECT_EQ(profile->parameter(QStringLiteral("start"))->access, Access::WriteOnly);
    EXPECT_FALSE(profile->parameter(QStringLiteral("start"))->backup);
    EXPECT_EQ(profile->parameter(QStringLiteral("status"))->bits.size(), 2);
    EXPECT_EQ(profile->parameterAt(4, 0x0066)->name, QStringLiteral("status"));
    EXPECT_EQ(profile->parameterAt(3, 0x0066), nullptr); // input and holding are separate
    EXPECT_EQ(profile->parameterAt(6, 0x2003)->name, QStringLiteral("start"));
    EXPECT_EQ(profile->codeTable(QStringLiteral("alarm"))->find(3)->panel, QStringLiteral("AL003"));
}

struct Rejection
{
    const char* what;
    int index;
    std::function<void(QJsonObject&)> edit;
    const char* expected; // part of the message
};

void PrintTo(const Rejection& r, std::ostream* os)
{
    *os << r.what;
}

class ProfileLoaderRejects : public ::testing::TestWithParam<Rejection>
{
};

TEST_P(ProfileLoaderRejects, NamesFileEntryAndProblem)
{
    QString error;
    const auto profile = loadWithParam(GetParam().index, GetParam().edit, &error);
    EXPECT_FALSE(profile) << GetParam().what;
    EXPECT_TRUE(error.startsWith(QStringLiteral("tdev.json: "))) << qPrintable(error);
    EXPECT_TRUE(error.contains(QString::fromUtf8(GetParam().expected))) << qPrintable(error);
}

INSTANTIATE_TEST_SUITE_P(
    Entries, ProfileLoaderRejects,
    ::testing::Values(
        Rejection{"unknown key", 0, [](QJsonObject& p) { p[QStringLiteral("sclae")] = 0.1; },
                  "parameters[0] \"speed\": entry: unknown key \"sclae\""},
        Rejection{"empty label", 1, [](QJsonObject& p) { p[QStringLiteral("label")] = QString(); },
                  "\"accel\": \"label\" is empty"},
        Rejection{"bad group", 1,
                  [](QJsonObject& p) { p[QStringLiteral("group")] = QStringLiteral("nope"); },
                  "group \"nope\" is not declared"},
        Rejection{"bad type", 1,
                  [](QJsonObject& p) { p[QStringLiteral("type")] = QStringLiteral("u8"); },
                  "type must be"},
        Rejection{"bad read fc", 1, [](QJsonObject& p) { p[QStringLiteral("read")] = 1; },
                  "read must be 3"},
        Rejection{"address too large", 1,
                  [](QJsonObject& p) { p[QStringLiteral("address")] = 70000; }, "address must be"},
        Rejection{"u32 with fc06", 8, [](QJsonObject& p) { p[QStringLiteral("write")] = 6; },
                  "cannot be written with function 06"},
        Rejection{"range not whole steps", 1,
                  [](QJsonObject& p) {
                      p[QStringLiteral("allowed")] = QJsonArray{QJsonObject{
                          {QStringLiteral("min"), 0.55}, {QStringLiteral("max"), 30.0}}};
                  },
                  "allowed[0]: 0.55 is not a whole number of steps of 0.1"},
        Rejection{"min > max", 1,
                  [](QJsonObject& p) {
                      p[QStringLiteral("allowed")] = QJsonArray{
                          QJsonObject{{QStringLiteral("min"), 3.0}, {QStringLiteral("max"), 1.0}}};
                  },
                  "min is greater than max"},
        Rejection{"default not allowed", 0,
                  [](QJsonObject& p) { p[QStringLiteral("default")] = 100; },
                  "\"speed\": the default is not among its allowed values"},
        Rejection{"setting without allowed", 1,
                  [](QJsonObject& p) { p.remove(QStringLiteral("allowed")); },
                  "a setting needs \"allowed\" or \"enum\""},
        Rejection{"duplicate enum", 3,
                  [](QJsonObject& p) {
                      p[QStringLiteral("enum")] =
                          QJsonArray{QJsonObject{{QStringLiteral("value"), 0},
                                                 {QStringLiteral("label"), QStringLiteral("CW")}},
                                     QJsonObject{{QStringLiteral("value"), 0},
                                                 {QStringLiteral("label"), QStringLiteral("X")}}};
                  },
                  "enum[1] repeats a code or label"},
        Rejection{"overlap", 2,
                  [](QJsonObject& p) { p[QStringLiteral("address")] = QStringLiteral("0x0404"); },
                  "overlaps \"decel\" at 0x0404 (holding registers)"},
        Rejection{"unknown variant", 0,
                  [](QJsonObject& p) {
                      p[QStringLiteral("when")] = QJsonArray{
                          QJsonObject{{QStringLiteral("variant"), QStringLiteral("t999")}}};
                  },
                  "variant \"t999\" is not declared"},
        Rejection{"unknown controlling param", 5,
                  [](QJsonObject& p) {
                      p[QStringLiteral("when")] =
                          QJsonArray{QJsonObject{{QStringLiteral("param"), QStringLiteral("nope")},
                                                 {QStringLiteral("equals"), 0}}};
                  },
                  "condition on unknown parameter \"nope\""},
        Rejection{"command without safety", 14,
                  [](QJsonObject& p) { p.remove(QStringLiteral("safety")); },
                  "commands need a \"safety\" class"},
        Rejection{"unknown code table", 13,
                  [](QJsonObject& p) { p[QStringLiteral("codeTable")] = QStringLiteral("warn"); },
                  "code table \"warn\" is not declared"},
        Rejection{"bits outside register", 12,
                  [](QJsonObject& p) {
                      p[QStringLiteral("count")] = 1;
                      p[QStringLiteral("bits")] =
                          QJsonArray{QJsonObject{{QStringLiteral("bit"), 16},
                                                 {QStringLiteral("name"), QStringLiteral("x")},
                                                 {QStringLiteral("label"), QStringLiteral("X")}}};
                  },
                  "bits[0] lies outside the 16-bit register"},
        Rejection{"string without count", 10,
                  [](QJsonObject& p) { p.remove(QStringLiteral("count")); },
                  "string parameters need \"count\""},
        Rejection{"terminal function not a parameter", 12,
                  [](QJsonObject& p) {
                      p[QStringLiteral("bits")] = QJsonArray{
                          QJsonObject{{QStringLiteral("bit"), 0},
                                      {QStringLiteral("name"), QStringLiteral("x0")},
                                      {QStringLiteral("label"), QStringLiteral("X0")},
                                      {QStringLiteral("function"), QStringLiteral("io.x9")}}};
                  },
                  "bit field \"x0\": function \"io.x9\" is not a readable parameter"},
        Rejection{"storeWith not a command", 1,
                  [](QJsonObject& p) { p[QStringLiteral("storeWith")] = QStringLiteral("speed"); },
                  "storeWith \"speed\" is not a command parameter"},
        Rejection{
            "word order of a 1-register value", 1,
            [](QJsonObject& p) { p[QStringLiteral("wordOrder")] = QStringLiteral("low-first"); },
            "\"wordOrder\" is for 2-register numbers and bit fields only"},
        Rejection{"unknown word order", 8,
                  [](QJsonObject& p) { p[QStringLiteral("wordOrder")] = QStringLiteral("little"); },
                  "\"wordOrder\" must be \"high-first\" or \"low-first\""},
        Rejection{"bad name", 1,
                  [](QJsonObject& p) { p[QStringLiteral("name")] = QStringLiteral("Accel X"); },
                  "name must be lower-case dotted words"}));

TEST(ProfileLoader, RejectsDuplicateNamesAndBrokenJson)
{
    QJsonObject root = testProfileJson();
    QJsonArray params = root.value(QStringLiteral("parameters")).toArray();
    QJsonObject copy = params[1].toObject();
    copy[QStringLiteral("address")] = QStringLiteral("0x7000");
    params.append(copy);
    root[QStringLiteral("parameters")] = params;
    QString error;
    EXPECT_FALSE(ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("\"accel\": name repeated"))) << qPrintable(error);

    EXPECT_FALSE(
        ProfileLoader::loadJson(QByteArray("{\"schema\": 1,"), QStringLiteral("x.json"), &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("x.json: not valid JSON at offset")))
        << qPrintable(error);

    root = testProfileJson();
    root[QStringLiteral("schema")] = 2;
    EXPECT_FALSE(ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("\"schema\" must be 1")));

    root = testProfileJson();
    QJsonObject identify = root.value(QStringLiteral("identify")).toObject();
    identify[QStringLiteral("count")] = 2; // name lies outside the identify read
    root[QStringLiteral("identify")] = identify;
    EXPECT_FALSE(ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("identify: \"info.name\""))) << qPrintable(error);

    EXPECT_FALSE(ProfileLoader::loadFile(QStringLiteral("/nonexistent/p.json"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("/nonexistent/p.json: cannot open")));
}

TEST(ProfileLoader, WordOrderIsReadPerParameter)
{
    QString error;
    const auto high = loadWithParam(
        12, [](QJsonObject&) {}, &error);
    ASSERT_TRUE(high) << qPrintable(error);
    EXPECT_EQ(high->parameter(QStringLiteral("status"))->wordOrder, WordOrder::HighFirst);
    const auto low = loadWithParam(
        12, [](QJsonObject& p) { p[QStringLiteral("wordOrder")] = QStringLiteral("low-first"); },
        &error);
    ASSERT_TRUE(low) << qPrintable(error);
    EXPECT_EQ(low->parameter(QStringLiteral("status"))->wordOrder, WordOrder::LowFirst);
    const auto explicitHigh = loadWithParam(
        8, [](QJsonObject& p) { p[QStringLiteral("wordOrder")] = QStringLiteral("high-first"); },
        &error);
    ASSERT_TRUE(explicitHigh) << qPrintable(error);
    EXPECT_EQ(explicitHigh->parameter(QStringLiteral("reduction"))->wordOrder,
              WordOrder::HighFirst);
}

TEST(ProfileLoader, RolesBindMeaningToParameters)
{
    QJsonObject root = testProfileJson();
    root[QStringLiteral("roles")] = QJsonObject{
        {QStringLiteral("stop"), QJsonObject{{QStringLiteral("param"), QStringLiteral("start")},
                                             {QStringLiteral("value"), 0}}},
        {QStringLiteral("running"),
         QJsonObject{{QStringLiteral("param"), QStringLiteral("status")},
                     {QStringLiteral("field"), QStringLiteral("running")}}},
        {QStringLiteral("currentSpeed"), QStringLiteral("speed")},
        {QStringLiteral("monitor"), QJsonArray{QStringLiteral("status"), QStringLiteral("speed")}}};
    QString error;
    const auto profile = ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error);
    ASSERT_TRUE(profile) << qPrintable(error);
    EXPECT_EQ(profile->role(QStringLiteral("stop"))->parameter, QStringLiteral("start"));
    EXPECT_EQ(*profile->role(QStringLiteral("stop"))->value, 0);
    EXPECT_EQ(profile->role(QStringLiteral("running"))->field, QStringLiteral("running"));
    EXPECT_EQ(profile->role(QStringLiteral("monitor"))->parameters.size(), 2);
    EXPECT_EQ(profile->role(QStringLiteral("nothing")), nullptr);
    EXPECT_EQ(profile->records(QStringLiteral("alarm")).size(), 1);

    const struct
    {
        QJsonValue role;
        const char* expected;
    } bad[] = {
        {QStringLiteral("nope"), "roles.r: unknown parameter \"nope\""},
        {QJsonObject{{QStringLiteral("param"), QStringLiteral("status")},
                     {QStringLiteral("field"), QStringLiteral("x")}},
         "has no bit field \"x\""},
        {QJsonObject{{QStringLiteral("param"), QStringLiteral("start")},
                     {QStringLiteral("value"), 7}},
         "7 is not a value \"start\" can be written with"},
        {QJsonObject{{QStringLiteral("param"), QStringLiteral("speed")},
                     {QStringLiteral("valeu"), 1}},
         "unknown key \"valeu\""},
        {42, "must be a parameter name"},
    };
    for (const auto& b : bad) {
        root[QStringLiteral("roles")] = QJsonObject{{QStringLiteral("r"), b.role}};
        EXPECT_FALSE(ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error));
        EXPECT_TRUE(error.contains(QString::fromUtf8(b.expected))) << qPrintable(error);
    }
}

TEST(ProfileLoader, AHugeNumberIsRefusedAsOutOfRange)
{
    // FuzzProfileLoader: a baud rate of 10^300 was converted to a 64-bit integer, which is
    // undefined behaviour (UBSan stops the sanitizer build's test here without the check).
    QJsonObject root = testProfileJson();
    QJsonObject serial = root.value(QStringLiteral("serial")).toObject();
    serial[QStringLiteral("baud")] = 1e300;
    root[QStringLiteral("serial")] = serial;
    QString error;
    EXPECT_FALSE(ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("out of range"))) << qPrintable(error);
}

TEST(ProfileLoader, DecelerationKnobsNeedTheSelectedRole)
{
    QJsonObject root = testProfileJson();
    root[QStringLiteral("decelerationKnobs")] = QJsonArray{
        QJsonObject{{QStringLiteral("selected"), 0}, {QStringLiteral("maxSeconds"), 30}}};
    QString error;
    EXPECT_FALSE(ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("decelerationKnobs need the \"selected\" role")))
        << qPrintable(error);

    root[QStringLiteral("roles")] =
        QJsonObject{{QStringLiteral("selected"),
                     QJsonObject{{QStringLiteral("param"), QStringLiteral("status")},
                                 {QStringLiteral("field"), QStringLiteral("spno")}}}};
    auto profile = ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error);
    ASSERT_TRUE(profile) << qPrintable(error);
    EXPECT_EQ(profile->knobDeceleration(0), std::optional<double>(30));
    EXPECT_FALSE(profile->knobDeceleration(1));

    // The spno field is 3 bits wide: 8 is not a value of it.
    root[QStringLiteral("decelerationKnobs")] = QJsonArray{
        QJsonObject{{QStringLiteral("selected"), 8}, {QStringLiteral("maxSeconds"), 30}}};
    EXPECT_FALSE(ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("decelerationKnobs[0]: \"selected\" 8")))
        << qPrintable(error);
    root[QStringLiteral("decelerationKnobs")] =
        QJsonArray{QJsonObject{{QStringLiteral("selected"), 0}, {QStringLiteral("maxSeconds"), 0}}};
    EXPECT_FALSE(ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("\"maxSeconds\" must be more than 0")))
        << qPrintable(error);
}

TEST(ProfileLoader, StatusLedTableAndPowerOnDelay)
{
    QJsonObject root = testProfileJson();
    const QJsonObject red{{QStringLiteral("light"), QStringLiteral("red")},
                          {QStringLiteral("colour"), QStringLiteral("#e51c23")},
                          {QStringLiteral("label"), QStringLiteral("Red")},
                          {QStringLiteral("meaning"), QStringLiteral("Alarm")},
                          {QStringLiteral("blink"), QStringLiteral("Flashes")}};
    root[QStringLiteral("statusLed")] = QJsonArray{red};
    QJsonObject serial = root.value(QStringLiteral("serial")).toObject();
    serial[QStringLiteral("powerOnDelayMs")] = 1000;
    root[QStringLiteral("serial")] = serial;
    QString error;
    auto profile = ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error);
    ASSERT_TRUE(profile) << qPrintable(error);
    EXPECT_EQ(profile->serial.powerOnDelayMs, 1000);
    ASSERT_NE(profile->ledEntry(QStringLiteral("red")), nullptr);
    EXPECT_EQ(profile->ledEntry(QStringLiteral("red"))->blink, QStringLiteral("Flashes"));
    EXPECT_EQ(profile->ledEntry(QStringLiteral("green")), nullptr);

    const struct
    {
        QJsonArray table;
        const char* expected;
    } bad[] = {
        {QJsonArray{red, red}, "statusLed[1]: \"light\" must be one of"},
        {QJsonArray{[&] {
             QJsonObject o = red;
             o[QStringLiteral("light")] = QStringLiteral("pink");
             return o;
         }()},
         "statusLed[0]: \"light\" must be one of"},
        {QJsonArray{[&] {
             QJsonObject o = red;
             o[QStringLiteral("colour")] = QStringLiteral("red");
             return o;
         }()},
         "statusLed[0]: \"colour\" must be #rrggbb"},
        {QJsonArray{[&] {
             QJsonObject o = red;
             o[QStringLiteral("meaning")] = QString();
             return o;
         }()},
         "\"label\" and \"meaning\" must not be empty"},
    };
    for (const auto& b : bad) {
        root[QStringLiteral("statusLed")] = b.table;
        EXPECT_FALSE(ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error));
        EXPECT_TRUE(error.contains(QString::fromUtf8(b.expected))) << qPrintable(error);
    }
    root[QStringLiteral("statusLed")] = QJsonArray{red};
    serial[QStringLiteral("powerOnDelayMs")] = -1;
    root[QStringLiteral("serial")] = serial;
    EXPECT_FALSE(ProfileLoader::loadJson(toJson(root), QStringLiteral("tdev.json"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("serial.powerOnDelayMs must be 0–60000")))
        << qPrintable(error);
}
