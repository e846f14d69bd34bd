// The simulated DC motor and the controller's speed loop (DcMotor, DcSpeedLoop): physics that
// make gains matter, measured through the registers as OpenTOP would see them.
#include "SimTestSupport.h"

#include "DcMotor.h"
#include "DcPidSimDevice.h"

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

TEST_F(DcMotorLoop, Explore)
{
    for (auto g : std::vector<std::array<float, 3>>{{0.1f, 0.01f, 0}, {0.5f, 0.05f, 0}, {1, 0.1f, 0}, {2, 0.1f, 0}, {5, 0.1f, 0}, {10, 0.1f, 0}, {20, 0, 0}}) {
        setGains(g[0], g[1], g[2]);
        const QVector<double> s = stepTo(500, 1500);
        QString line;
        for (int k = 0; k < 60; k += 2) line += QString::number(s[k]) + QLatin1Char(' ');
        printf("P=%g I=%g: peak %g ripple %g end %g | %s\n", g[0], g[1], peak(s), ripple(s, 100), s.last(), qPrintable(line));
        stepTo(0, 1500);
    }
}
