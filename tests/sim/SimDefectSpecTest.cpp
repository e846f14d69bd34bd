// The syntax of simulated defects (SimDefectSpec): every form, and every error naming what is
// allowed; their check against a profile (SimDefects::resolve); --defect and the bus spec.
#include "tests/sim/SimTestSupport.h"

#include "model/bus/BusSpec.h"
#include "model/profile/ProfileRegistry.h"
#include "sim/SimConsole.h"
#include "sim/SimDefectSpec.h"
#include "sim/SimDefects.h"
#include "sim/SimOptions.h"

using namespace opentop;
using namespace opentop::test;

namespace {

std::optional<SimDefectSpec> parse(const char* text, QString* error = nullptr)
{
    return SimDefectSpec::parse(QString::fromLatin1(text), error);
}

std::string why(const char* text)
{
    QString error;
    EXPECT_FALSE(parse(text, &error)) << text;
    EXPECT_FALSE(error.isEmpty()) << text;
    return error.toStdString();
}

const Profile& profileOf(const char* type)
{
    const Profile* p = ProfileRegistry::builtIn().forDeviceType(QString::fromLatin1(type));
    EXPECT_TRUE(p) << type;
    return *p;
}

} // namespace

TEST(SimDefectSpec, ParsesEveryForm)
{
    auto s = parse("firmware=1.4");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->firmware, 0x0104);
    EXPECT_EQ(parse("firmware=V2.15")->firmware, 0x020F);
    EXPECT_EQ(parse("max_speed=800")->maxSpeed, 800);
    EXPECT_TRUE(parse("stall")->stall);
    EXPECT_DOUBLE_EQ(*parse("load=+40")->loadOffset, 40);
    EXPECT_DOUBLE_EQ(*parse("load=-15")->loadOffset, -15);
    EXPECT_DOUBLE_EQ(*parse("load=x1.5")->loadScale, 1.5);
    EXPECT_DOUBLE_EQ(*parse("load=*2")->loadScale, 2);
    s = parse("alarm=0x07@1500ms");
    EXPECT_EQ(s->alarm, QStringLiteral("0x07"));
    EXPECT_EQ(s->alarmAfterMs, 1500);
    EXPECT_EQ(parse("alarm=Overload@2s")->alarm, QStringLiteral("overload"));
    EXPECT_EQ(parse("alarm=overload@2s")->alarmAfterMs, 2000);
    EXPECT_EQ(parse("alarm=stall@0.5s")->alarmAfterMs, 500);
    EXPECT_EQ(parse("alarm=7@250")->alarmAfterMs, 250); // ms without a unit
    EXPECT_EQ(parse("nostick=spno2.speed")->noStick, QStringList{QStringLiteral("spno2.speed")});
    EXPECT_EQ(parse("nostick=0x1102")->noStick, QStringList{QStringLiteral("0x1102")});
    EXPECT_EQ(parse("nostore=config.stall_time")->noStore,
              QStringList{QStringLiteral("config.stall_time")});
    EXPECT_TRUE(parse("clear")->clear);
    EXPECT_TRUE(parse("clear")->isEmpty());
    EXPECT_DOUBLE_EQ(*parse("turnaround=14")->turnaroundMs, 14);
    EXPECT_DOUBLE_EQ(*parse("turnaround=0.5")->turnaroundMs, 0.5);
    EXPECT_EQ(parse("turnaround=14")->toString(), QStringLiteral("turnaround=14"));

    // Several at once, spaces allowed around the items.
    s = parse("firmware=1.4, max_speed=800 ,load=+40,nostick=a.b,nostick=0x10");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->firmware, 0x0104);
    EXPECT_EQ(s->maxSpeed, 800);
    EXPECT_EQ(s->noStick.size(), 2);
    EXPECT_EQ(s->toString(), QStringLiteral("firmware=1.4,max_speed=800,load=+40,nostick=a.b,"
                                            "nostick=0x10"));
    // The text round-trips.
    const char* all = "firmware=1.4,max_speed=800,stall,load=-5,load=x1.5,alarm=0x07@1500ms,"
                      "nostick=spno2.speed,nostore=core.upper_limit";
    EXPECT_EQ(parse(all)->toString(), QString::fromLatin1(all));
    EXPECT_EQ(parse(parse(all)->toString().toLatin1().constData())->toString(),
              parse(all)->toString());
}

TEST(SimDefectSpec, ClearAndMergeReplaceEarlierItems)
{
    const SimDefectSpec a = *parse("firmware=1.4,load=+40,nostick=spno2.speed");
    SimDefectSpec m = a.merged(*parse("firmware=2.0,stall"));
    EXPECT_EQ(m.toString(), QStringLiteral("firmware=2.0,stall,load=+40,nostick=spno2.speed"));
    m = m.merged(*parse("clear"));
    EXPECT_TRUE(m.isEmpty());
    EXPECT_EQ(a.merged(*parse("clear,max_speed=5")).toString(), QStringLiteral("max_speed=5"));
    EXPECT_EQ(parse("load=+40,clear")->toString(), QString()); // clear drops what came before
}

TEST(SimDefectSpec, EveryErrorNamesTheAllowedForm)
{
    EXPECT_NE(why("").find("firmware=MAJOR.MINOR"), std::string::npos);
    EXPECT_NE(why("color=red").find("unknown defect"), std::string::npos);
    EXPECT_NE(why("color=red").find("max_speed=N"), std::string::npos);
    EXPECT_NE(why("stal").find("unknown defect"), std::string::npos);
    EXPECT_NE(why("stall,,load=+1").find("empty item"), std::string::npos);
    EXPECT_NE(why("firmware").find("needs a value"), std::string::npos);
    EXPECT_NE(why("firmware=").find("needs a value"), std::string::npos);
    EXPECT_NE(why("stall=1").find("takes no value"), std::string::npos);
    EXPECT_NE(why("clear=yes").find("takes no value"), std::string::npos);
    EXPECT_NE(why("firmware=1").find("MAJOR.MINOR"), std::string::npos);
    EXPECT_NE(why("firmware=1.256").find("0..255"), std::string::npos);
    EXPECT_NE(why("firmware=abc").find("MAJOR.MINOR"), std::string::npos);
    EXPECT_NE(why("max_speed=fast").find("0..10000"), std::string::npos);
    EXPECT_NE(why("max_speed=-1").find("0..10000"), std::string::npos);
    EXPECT_NE(why("max_speed=10001").find("0..10000"), std::string::npos);
    EXPECT_NE(why("load=40").find("load=+N"), std::string::npos);
    EXPECT_NE(why("load=+300").find("-200..+200"), std::string::npos);
    EXPECT_NE(why("load=+abc").find("-200..+200"), std::string::npos);
    EXPECT_NE(why("load=x20").find("x0.1..x10"), std::string::npos);
    EXPECT_NE(why("load=x0").find("x0.1..x10"), std::string::npos);
    EXPECT_NE(why("alarm=7").find("CODE@TIME"), std::string::npos);
    EXPECT_NE(why("alarm=@1s").find("CODE@TIME"), std::string::npos);
    EXPECT_NE(why("alarm=a b@1s").find("CODE@TIME"), std::string::npos);
    EXPECT_NE(why("alarm=7@soon").find("1500ms"), std::string::npos);
    EXPECT_NE(why("alarm=7@-1s").find("1500ms"), std::string::npos);
    EXPECT_NE(why("alarm=7@2h").find("1500ms"), std::string::npos);
    EXPECT_NE(why("alarm=7@3601s").find("0..3600 s"), std::string::npos);
    EXPECT_NE(why("alarm=7@0.5ms").find("1500ms"), std::string::npos);
    EXPECT_NE(why("nostick=spno2 speed").find("register address"), std::string::npos);
    EXPECT_NE(why("nostore=0x12345").find("register address"), std::string::npos);
    EXPECT_NE(why("turnaround=-1").find("0..1000"), std::string::npos);
    EXPECT_NE(why("turnaround=1001").find("0..1000"), std::string::npos);
    EXPECT_NE(why("turnaround=late").find("0..1000"), std::string::npos);
}

TEST(SimDefectSpec, OptionFormNeedsAMachineNumber)
{
    int slave = 0;
    QString error;
    auto s = SimDefectSpec::parseOption(QStringLiteral("3:firmware=1.4,stall"), &slave, &error);
    ASSERT_TRUE(s) << error.toStdString();
    EXPECT_EQ(slave, 3);
    EXPECT_TRUE(s->stall);
    for (const char* bad : {"firmware=1.4", "0:stall", "248:stall", "x:stall", ":stall"}) {
        EXPECT_FALSE(SimDefectSpec::parseOption(QString::fromLatin1(bad), &slave, &error)) << bad;
        EXPECT_TRUE(error.contains(QStringLiteral("ID:DEFECT"))) << error.toStdString();
    }
    EXPECT_FALSE(SimDefectSpec::parseOption(QStringLiteral("3:speed=1"), &slave, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("unknown defect"))) << error.toStdString();
}

TEST(SimDefects, ResolvesAgainstTheDrivesProfile)
{
    QString error;
    const Profile& dbu = profileOf("dbu200");
    const Profile& dc = profileOf("dcpid");
    auto d = SimDefects::resolve(*parse("alarm=overload@2s,nostick=0xCA03,nostore=spno2.speed"),
                                 dbu, &error);
    ASSERT_TRUE(d) << error.toStdString();
    EXPECT_EQ(d->alarmCode, 0x07);
    EXPECT_EQ(d->alarmAfterMs, 2000);
    EXPECT_EQ(d->noStick, QStringList{QStringLiteral("spno2.speed")}); // by its address
    EXPECT_EQ(SimDefects::resolve(*parse("alarm=0x05@1s"), dbu, &error)->alarmCode, 0x05);
    EXPECT_EQ(SimDefects::resolve(*parse("alarm=over_speed@1s"), dbu, &error)->alarmCode, 0x05);
    EXPECT_EQ(SimDefects::resolve(*parse("alarm=15@1s"), dbu, &error)->alarmCode, 0x0F);

    EXPECT_FALSE(SimDefects::resolve(*parse("alarm=0x02@1s"), dbu, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("0x07 overload"))) << error.toStdString();
    EXPECT_FALSE(SimDefects::resolve(*parse("alarm=stall@1s"), dbu, &error));
    EXPECT_FALSE(SimDefects::resolve(*parse("nostick=spno9.speed"), dbu, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("no writable parameter"))) << error.toStdString();
    EXPECT_FALSE(SimDefects::resolve(*parse("nostick=status.load"), dbu, &error)); // read-only
    EXPECT_FALSE(SimDefects::resolve(*parse("nostore=0xFFF0"), dbu, &error));

    d = SimDefects::resolve(*parse("alarm=stall@1s,nostore=0x0081,firmware=2.1"), dc, &error);
    ASSERT_TRUE(d) << error.toStdString();
    EXPECT_EQ(d->alarmCode, 0);
    EXPECT_EQ(d->noStore, QStringList{QStringLiteral("config.stall_time")});
    EXPECT_EQ(d->firmware, 0x0201);
    EXPECT_FALSE(SimDefects::resolve(*parse("alarm=0x07@1s"), dc, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("alarm=stall@TIME"))) << error.toStdString();
}

TEST(SimDefects, SpeedAndLoadArithmetic)
{
    SimDefects d;
    EXPECT_EQ(d.reachable(1000), 1000);
    d.maxSpeed = 800;
    EXPECT_EQ(d.reachable(1000), 800);
    EXPECT_EQ(d.reachable(500), 500);
    EXPECT_TRUE(d.limits(1000));
    EXPECT_FALSE(d.limits(500));
    d.stall = true;
    EXPECT_EQ(d.reachable(500), 0);
    d.loadScale = 1.5;
    d.loadOffset = 10;
    EXPECT_DOUBLE_EQ(d.load(20), 40);
}

TEST(SimDefectOptions, DefectOptionIsRepeatableAndChecked)
{
    QString error;
    auto o = SimOptions::parse({QStringLiteral("--devices"), QStringLiteral("dbu200@1-3"),
                                QStringLiteral("--defect"), QStringLiteral("3:firmware=1.4"),
                                QStringLiteral("--defect=1:max_speed=800,load=+40")},
                               &error);
    ASSERT_TRUE(o) << error.toStdString();
    ASSERT_EQ(o->defects.size(), 2);
    EXPECT_EQ(o->defects.at(0).first, 3);
    EXPECT_EQ(o->defects.at(0).second.firmware, 0x0104);
    EXPECT_EQ(o->defects.at(1).first, 1);
    EXPECT_EQ(o->defects.at(1).second.maxSpeed, 800);

    EXPECT_FALSE(SimOptions::parse(
        {QStringLiteral("--devices"), QStringLiteral("dbu200@1"), QStringLiteral("--defect")},
        &error));
    EXPECT_TRUE(error.contains(QStringLiteral("ID:DEFECT"))) << error.toStdString();
    EXPECT_FALSE(SimOptions::parse({QStringLiteral("--devices"), QStringLiteral("dbu200@1"),
                                    QStringLiteral("--defect"), QStringLiteral("1:speed=3")},
                                   &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("--defect: unknown defect")))
        << error.toStdString();
    EXPECT_TRUE(SimOptions::usage().contains(QStringLiteral("--defect ID:LIST")));
}

TEST(SimDefectOptions, BusSpecCarriesDefectsInBraces)
{
    QString error;
    auto bus =
        SimBus::fromSpec(QStringLiteral("dbu200@1{firmware=1.4,max_speed=800},dcpid@7{stall},"
                                        "dbu400@20-21{load=+40}"),
                         &error);
    ASSERT_TRUE(bus) << error.toStdString();
    EXPECT_EQ(bus->device(1)->defects().firmware, 0x0104);
    EXPECT_EQ(bus->device(1)->defects().maxSpeed, 800);
    EXPECT_TRUE(bus->device(7)->defects().stall);
    EXPECT_DOUBLE_EQ(bus->device(21)->defects().loadOffset, 40);
    EXPECT_FALSE(bus->device(20)->defects().stall);
    EXPECT_EQ(bus->spec(), QStringLiteral("dbu200@1,dcpid@7,dbu400@20,dbu400@21"));

    // The model's BusSpec keeps the text in braces for every drive of a range.
    const auto entries = BusSpec::parse(QStringLiteral("dbu200@1-2{ stall },dcpid@7"), &error);
    ASSERT_TRUE(entries) << error.toStdString();
    EXPECT_EQ(entries->at(1).defects, QStringLiteral("stall"));
    EXPECT_TRUE(entries->at(2).defects.isEmpty());
    EXPECT_EQ(BusSpec::toString(*entries),
              QStringLiteral("dbu200@1{stall},dbu200@2{stall},dcpid@7"));

    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("dbu200@1{stall"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("braces"))) << error.toStdString();
    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("dbu200@1{stall}x"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("end the item"))) << error.toStdString();
    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("dbu200@1{{stall}}"), &error));
    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("dbu200@1{speed=3}"), &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("dbu200@1{speed=3}: unknown defect")))
        << error.toStdString();
    EXPECT_FALSE(SimBus::fromSpec(QStringLiteral("dcpid@7{alarm=0x07@1s}"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("alarm=stall@TIME"))) << error.toStdString();
}

TEST(SimDefectOptions, ConsoleChangesAndListsDefects)
{
    SimFixture sim{"dbu200@1,dcpid@7"};
    SimConsole console(sim.bus);
    EXPECT_EQ(console.execute(QStringLiteral("defects")).text,
              QStringLiteral("no drive has defects"));
    SimControlResult r = console.execute(QStringLiteral("defect 1 max_speed=800 load=+40"));
    ASSERT_TRUE(r.ok) << r.text.toStdString();
    EXPECT_EQ(r.text, QStringLiteral("slave 1 defects: max_speed=800,load=+40"));
    ASSERT_TRUE(console.execute(QStringLiteral("defect 7 stall")).ok);
    EXPECT_EQ(console.execute(QStringLiteral("defects")).text,
              QStringLiteral("1 dbu200: max_speed=800,load=+40\n7 dcpid: stall"));
    EXPECT_TRUE(console.execute(QStringLiteral("list"))
                    .text.contains(QStringLiteral("defects: max_speed=800,load=+40")));
    ASSERT_TRUE(console.execute(QStringLiteral("defect 1 clear")).ok);
    EXPECT_EQ(console.execute(QStringLiteral("defects")).text, QStringLiteral("7 dcpid: stall"));
    EXPECT_TRUE(SimConsole::helpText().contains(QStringLiteral("defect ID clear")));

    r = console.execute(QStringLiteral("defect 1"));
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.text.contains(QStringLiteral("firmware=MAJOR.MINOR"))) << r.text.toStdString();
    EXPECT_FALSE(console.execute(QStringLiteral("defect x stall")).ok);
    r = console.execute(QStringLiteral("defect 9 stall"));
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.text.contains(QStringLiteral("no device with machine number 9")));
    r = console.execute(QStringLiteral("defect 7 nostick=spno2.speed"));
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.text.contains(QStringLiteral("no writable parameter of a dcpid")))
        << r.text.toStdString();
    EXPECT_EQ(console.execute(QStringLiteral("defects")).text, QStringLiteral("7 dcpid: stall"));
}
