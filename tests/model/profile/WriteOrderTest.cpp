// WriteOrder: each setting after the ones its allowed values follow, through a chain, stable
// otherwise; a cycle keeps its members as given; the real profiles' dependent settings (a DBU's
// speed display and its range) come after what they depend on.
#include "model/profile/WriteOrder.h"
#include "model/profile/Profile.h"
#include "model/profile/ProfileRegistry.h"

using namespace opentop;

namespace {

// A profile whose parameter `name` has its allowed values decided by `after` (one each).
Profile chained(const QVector<QPair<QString, QString>>& parameters)
{
    Profile profile;
    for (const auto& [name, after] : parameters) {
        ParameterMeta meta;
        meta.name = name;
        if (!after.isEmpty()) {
            ValueCondition c;
            c.param = after;
            meta.conditions << c;
        }
        profile.parameters << meta;
    }
    profile.index();
    return profile;
}

QStringList names(const char* text)
{
    return QString::fromLatin1(text).split(QLatin1Char(' '));
}

} // namespace

TEST(WriteOrderTest, AChainIsWrittenFromItsRootWhateverTheGivenOrder)
{
    // c follows b, b follows a: a chain, the case a sort on direct dependencies gets wrong.
    const Profile p = chained({{QStringLiteral("a"), QString()},
                               {QStringLiteral("b"), QStringLiteral("a")},
                               {QStringLiteral("c"), QStringLiteral("b")},
                               {QStringLiteral("d"), QString()}});
    EXPECT_EQ(WriteOrder::of(p, names("c d b a")), names("d a b c"));
    EXPECT_EQ(WriteOrder::of(p, names("c b a")), names("a b c"));
    EXPECT_EQ(WriteOrder::of(p, names("a b c d")), names("a b c d"));
    // A link that is not written does not hold the others back: c after a is fine without b.
    EXPECT_EQ(WriteOrder::of(p, names("c a")), names("c a"));
    EXPECT_EQ(WriteOrder::of(p, names("d")), names("d"));
    EXPECT_TRUE(WriteOrder::of(p, {}).isEmpty());
    // Every permutation of the chain comes out in one valid order.
    QStringList given = names("a b c d");
    std::sort(given.begin(), given.end());
    do {
        const QStringList order = WriteOrder::of(p, given);
        EXPECT_LT(order.indexOf(QStringLiteral("a")), order.indexOf(QStringLiteral("b")));
        EXPECT_LT(order.indexOf(QStringLiteral("b")), order.indexOf(QStringLiteral("c")));
        EXPECT_EQ(order.size(), 4);
    } while (std::next_permutation(given.begin(), given.end()));
}

TEST(WriteOrderTest, ACycleKeepsItsMembersAsGivenAtTheEnd)
{
    const Profile p = chained({{QStringLiteral("a"), QStringLiteral("b")},
                               {QStringLiteral("b"), QStringLiteral("a")},
                               {QStringLiteral("c"), QString()},
                               {QStringLiteral("e"), QStringLiteral("e")}});
    EXPECT_EQ(WriteOrder::of(p, names("b a c")), names("c b a"));
    EXPECT_EQ(WriteOrder::of(p, names("e c")), names("e c")); // itself: no wait
    EXPECT_EQ(WriteOrder::of(p, names("unknown c")), names("unknown c"));
}

TEST(WriteOrderTest, TheProfilesDependentSettingsFollowWhatTheyDependOn)
{
    for (const Profile& profile : ProfileRegistry::builtIn().profiles()) {
        QStringList all;
        for (auto it = profile.parameters.crbegin(); it != profile.parameters.crend(); ++it)
            all << it->name; // reversed: the profile's own order would hide a wrong sort
        const QStringList order = WriteOrder::of(profile, all);
        ASSERT_EQ(order.size(), all.size()) << profile.family.toStdString();
        int dependent = 0;
        for (const QString& name : order) {
            for (const QString& before : profile.parameter(name)->controllingParameters()) {
                if (before == name)
                    continue;
                ++dependent;
                EXPECT_LT(order.indexOf(before), order.indexOf(name))
                    << profile.family.toStdString() << ": " << name.toStdString() << " after "
                    << before.toStdString();
            }
        }
        if (profile.family == QLatin1String("dbu")) {
            EXPECT_GT(dependent, 0); // the DBU's profile has dependent settings to order
        }
    }
}
