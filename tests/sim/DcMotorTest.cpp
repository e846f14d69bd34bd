// The simulated DC motor and the controller's speed loop (DcMotor, DcSpeedLoop): physics that
// make gains matter, measured through the registers as OpenTOP would see them.
#include "tests/sim/SimTestSupport.h"

#include "sim/DcMotor.h"
#include "sim/DcPidSimDevice.h"

#include <cmath>
#include <cstring>

using namespace opentop;
using namespace opentop::test;

namespace {

class DcMotorLoop : public ::testing::Test
{
protected:
    void SetUp() override
    {
        ASSERT_TRUE(sim.write(7, "config.speed_mode", 2).ok()); // speed loop (commutation)
    }
    void setGains(float p, float i, float d)
    {
        QVector<quint16> regs;
        for (float v : {p, i, d}) {
            quint32 bits = 0;
            std::memcpy(&bits, &v, sizeof bits);
            regs << quint16(bits >> 16) << quint16(bits & 0xFFFF);
        }
        ASSERT_TRUE(sim.writeMany(7, 0x0090, regs).ok());
    }
    // The measured speed every 5 ms for `ms` after a speed command.
    QVector<double> stepTo(int command, int ms)
    {
        EXPECT_TRUE(sim.write(7, "speed.command", quint16(qint16(command))).ok());
        QVector<double> speeds;
        for (int t = 0; t < ms; t += 5) {
            sim.advance(5);
            speeds << sim.raw(7, "status.commutation");
        }
        return speeds;
    }
    static double peak(const QVector<double>& v) { return *std::max_element(v.begin(), v.end()); }
    // Peak-to-peak over the last `n` samples.
    static double ripple(const QVector<double>& v, int n)
    {
        const auto first = v.end() - n;
        return *std::max_element(first, v.end()) - *std::min_element(first, v.end());
    }

    SimFixture sim{"dcpid@7"};
};

} // namespace

TEST_F(DcMotorLoop, HighProportionalGainOscillatesAndModerateGainsSettle)
{
    setGains(10, 0.1f, 0);
    const QVector<double> high = stepTo(500, 1500);
    EXPECT_GT(ripple(high, 100), 50); // still ±25 1/s and more after a second

    stepTo(0, 1000);
    setGains(2, 0.1f, 0);
    const QVector<double> good = stepTo(500, 1500);
    EXPECT_LT(ripple(good, 100), 6);
    EXPECT_NEAR(good.last(), 500, 3);
    EXPECT_LT(peak(good), 650);

    stepTo(0, 1000);
    setGains(0.1f, 0.01f, 0); // the factory's: slow but steady
    const QVector<double> soft = stepTo(500, 1500);
    EXPECT_LT(soft[30], 450); // 150 ms after the command, still well short of the speed
    EXPECT_LE(peak(soft), 505);
    EXPECT_NEAR(soft.last(), 500, 3);
}

TEST_F(DcMotorLoop, MotorAndLoadSettingsChangeTheResponse)
{
    ASSERT_TRUE(sim.write(7, "config.speed_mode", 0).ok()); // PWM: the motor's own response
    const QVector<double> light = stepTo(500, 1000);
    stepTo(0, 1000);
    const SimControlResult r = sim.bus->control(
        7, {QStringLiteral("motor"), QStringLiteral("load=0.1"), QStringLiteral("inertia=4e-4")});
    ASSERT_TRUE(r.ok) << qPrintable(r.text);
    EXPECT_TRUE(r.text.contains(QStringLiteral("inertia=0.0004"))) << qPrintable(r.text);
    const QVector<double> heavy = stepTo(500, 1000);
    EXPECT_LT(heavy.last(), light.last() - 30); // the load torque costs speed
    EXPECT_LT(heavy[6], light[6] * 0.6);        // four times the inertia: slower rise
    EXPECT_FALSE(sim.bus->control(7, {QStringLiteral("motor"), QStringLiteral("mass=2")}).ok);
    EXPECT_FALSE(sim.bus->control(7, {QStringLiteral("motor"), QStringLiteral("supply=60")}).ok);
}

TEST_F(DcMotorLoop, TachogeneratorModeRegulatesTheTachoVoltage)
{
    ASSERT_TRUE(sim.write(7, "config.speed_mode", 3).ok());
    setGains(2, 0.1f, 0);
    stepTo(250, 1500); // 2.50 V
    EXPECT_NEAR(sim.raw(7, "status.ai1_voltage"), 250, 3);
    EXPECT_NEAR(sim.raw(7, "status.commutation"), 500, 8); // 5 mV per 1/s
}

TEST(DcMotorModel, ParsesSettingsAndNamesTheAllowed)
{
    QString error;
    const auto m = DcMotor::Model::parse(QStringLiteral("inertia=2e-4, load=0.1"), {}, &error);
    ASSERT_TRUE(m) << qPrintable(error);
    EXPECT_DOUBLE_EQ(m->inertia, 2e-4);
    EXPECT_DOUBLE_EQ(m->loadTorque, 0.1);
    EXPECT_DOUBLE_EQ(m->supplyV, 24);
    EXPECT_FALSE(DcMotor::Model::parse(QStringLiteral("gate=0"), {}, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("1..100"))) << qPrintable(error);
    EXPECT_FALSE(DcMotor::Model::parse(QStringLiteral("speed=3"), {}, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("inertia"))) << qPrintable(error);
}
