// The DBU register map of 000_306a808c77939fd6.txt chapter 12, read independently of
// model/profiles/*.json, checked register by register against the built-in "dbu" profile.
//
// Where the manual contradicts itself the Modbus protocol and the rest of the manual win:
//  - 12-12 gives SPno8 as 0008h; the selection codes run 0000h–0007h (SPno8 = 7).
//  - 12-9 gives 0x1013 as "50 ~ 100 %" but 0032h–0078h and 7-1-3 say 50–120 %.
//  - 12-9 gives 0x1011 as 0.1–30.0 s but 0000h–012Ch; 0.1 s is raw 1.
//  - 12-10 gives the speed reduction as 1.00–9999.90 but 0064h–000F423Fh: 1.00–9999.99.
//  - "250(300)": the value in brackets is the DBU400's (2-2: 250–3000 vs 300–3000 r/min).
//  - 12-10 gives the speed display update time as "5 ~ 300" (0005h–012Ch); 7-1-4 says
//    0.5–30 s, so the register counts 0.1 s.
//  - 12-10 gives the speed increasing ratio 4 bytes but 0064h–0960h written with 06: one register.
#include "model/profile/ProfileRegistry.h"
#include "tests/model/profile/RegisterTable.h"

#include <gtest/gtest.h>

namespace opentop::manualcheck {
namespace {

const std::vector<Allowed> kZeroOne = {oneOf({0, 1})};
const std::vector<Allowed> kOne = {oneOf({1})};
// 12-2 acceleration time; also the speed display update time 0x0401 (7-1-4: 0.5–30 s).
const std::vector<Allowed> kAccel = {span(0.5, 30.0)};
const std::vector<Allowed> kDecel = {spans({{0.5, 0.5}, {2.0, 30.0}})};
const std::vector<Allowed> kRunSpeed = {spans({{0, 0}, {250, 3000}}).onVariant("dbu200"),
                                        spans({{0, 0}, {300, 3000}}).onVariant("dbu400")};
// 12-3: "0 250(300)~4000", 0000h, 00FAh(012Ch)–0FA0h.
const std::vector<Allowed> kLimitSpeed = {spans({{0, 0}, {250, 4000}}).onVariant("dbu200"),
                                          spans({{0, 0}, {300, 4000}}).onVariant("dbu400")};
// 12-4: the IN function codes differ with the control mode 0x2015 (0 = Mode1, 1 = Mode2);
// "--" in a column means the function does not exist in that mode.
const std::vector<Allowed> kInputCodes = {
    oneOf({0x00, 0x01, 0x02, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09})
        .when(0x2015, 0)
        .alsoRefusing({0x10, 0x11, 0x12, 0x14, 0x19}),
    oneOf({0x10, 0x11, 0x12, 0x14, 0x15, 0x16, 0x17, 0x18, 0x19})
        .when(0x2015, 1)
        .alsoRefusing({0x00, 0x01, 0x02, 0x04, 0x09})};
const std::vector<Allowed> kOutputCodes = {oneOf({0, 1, 2, 3, 4, 5, 6})};
const std::vector<Allowed> kDiameter = {span(0, 5999.9)};
const std::vector<Allowed> kCorrection = {span(-100, 100)};
// 12-5: FFFFh = group communication off ("Stop"), groups 1–247.
const std::vector<Allowed> kGroup = {span(1, 247).orCodes({0xFFFF})};
// 12-6: 9600, 14400, 19200, 28800, 38400, 57600, 115200 bit/s.
const std::vector<Allowed> kZeroToSix = {oneOf({0, 1, 2, 3, 4, 5, 6})};
// 12-11: running 1, direction 2, hold 4, M1–M3 8–10, alarm 11, mode 12.
const std::vector<int> kStatusBits = {1, 2, 4, 8, 9, 10, 11, 12};
// 12-13: inputs X0–X3 and outputs Y0–Y1, one bit each.
const std::vector<Allowed> kIn = {span(0, 15)};
const std::vector<int> kInBits = {0, 1, 2, 3};
const std::vector<Allowed> kOut = {span(0, 3)};
const std::vector<int> kOutBits = {0, 1};
// 12-12: SPno1–SPno8 are 0–7 (the manual prints 0008h for SPno8).
const std::vector<Allowed> kSpno = {oneOf({0, 1, 2, 3, 4, 5, 6, 7})};

} // namespace

const std::vector<Register>& dbuRegisters()
{
    static const std::vector<Register> table = {
        // 12-2 Running data SPno: acceleration time 0.5–30.0 s (0005h–012Ch), 03/06.
        {0x1303, 3, 6, u16, 1, 0.1, "SPno2 acceleration time (12-2)", kAccel},
        {0x1305, 3, 6, u16, 1, 0.1, "SPno3 acceleration time (12-2)", kAccel},
        {0x1307, 3, 6, u16, 1, 0.1, "SPno4 acceleration time (12-2)", kAccel},
        {0x1309, 3, 6, u16, 1, 0.1, "SPno5 acceleration time (12-2)", kAccel},
        {0x130B, 3, 6, u16, 1, 0.1, "SPno6 acceleration time (12-2)", kAccel},
        {0x130D, 3, 6, u16, 1, 0.1, "SPno7 acceleration time (12-2)", kAccel},
        {0x130F, 3, 6, u16, 1, 0.1, "SPno8 acceleration time (12-2)", kAccel},
        // 12-2 deceleration time 0.5 or 2.0–30.0 s (0005h, 0014h–012Ch), 03/06.
        {0x4503, 3, 6, u16, 1, 0.1, "SPno2 deceleration time (12-2)", kDecel},
        {0x4505, 3, 6, u16, 1, 0.1, "SPno3 deceleration time (12-2)", kDecel},
        {0x4507, 3, 6, u16, 1, 0.1, "SPno4 deceleration time (12-2)", kDecel},
        {0x4509, 3, 6, u16, 1, 0.1, "SPno5 deceleration time (12-2)", kDecel},
        {0x450B, 3, 6, u16, 1, 0.1, "SPno6 deceleration time (12-2)", kDecel},
        {0x450D, 3, 6, u16, 1, 0.1, "SPno7 deceleration time (12-2)", kDecel},
        {0x450F, 3, 6, u16, 1, 0.1, "SPno8 deceleration time (12-2)", kDecel},
        // 12-2 running speed: SPno1 is read only (set by the Ext-VR); SPno2–8 0 or 250(300)–3000
        // r/min.
        {0xCA01, 3, kNone, u16, 1, 1, "SPno1 speed, read only (12-2)"},
        {0xCA03, 3, 6, u16, 1, 1, "SPno2 speed (12-2)", kRunSpeed},
        {0xCA05, 3, 6, u16, 1, 1, "SPno3 speed (12-2)", kRunSpeed},
        {0xCA07, 3, 6, u16, 1, 1, "SPno4 speed (12-2)", kRunSpeed},
        {0xCA09, 3, 6, u16, 1, 1, "SPno5 speed (12-2)", kRunSpeed},
        {0xCA0B, 3, 6, u16, 1, 1, "SPno6 speed (12-2)", kRunSpeed},
        {0xCA0D, 3, 6, u16, 1, 1, "SPno7 speed (12-2)", kRunSpeed},
        {0xCA0F, 3, 6, u16, 1, 1, "SPno8 speed (12-2)", kRunSpeed},
        // 12-2 running direction 0 = CW, 1 = CCW, 03/06.
        {0x0311, 3, 6, u16, 1, 1, "SPno1 running direction (12-2)", kZeroOne},
        {0x0313, 3, 6, u16, 1, 1, "SPno2 running direction (12-2)", kZeroOne},
        {0x0315, 3, 6, u16, 1, 1, "SPno3 running direction (12-2)", kZeroOne},
        {0x0317, 3, 6, u16, 1, 1, "SPno4 running direction (12-2)", kZeroOne},
        {0x0319, 3, 6, u16, 1, 1, "SPno5 running direction (12-2)", kZeroOne},
        {0x031B, 3, 6, u16, 1, 1, "SPno6 running direction (12-2)", kZeroOne},
        {0x031D, 3, 6, u16, 1, 1, "SPno7 running direction (12-2)", kZeroOne},
        {0x031F, 3, 6, u16, 1, 1, "SPno8 running direction (12-2)", kZeroOne},
        // 12-2 initialization of one running data set: write 0001h with 06.
        {0x9E01, kNone, 6, u16, 1, 1, "SPno1 initialization (12-2)", kOne},
        {0x9E03, kNone, 6, u16, 1, 1, "SPno2 initialization (12-2)", kOne},
        {0x9E05, kNone, 6, u16, 1, 1, "SPno3 initialization (12-2)", kOne},
        {0x9E07, kNone, 6, u16, 1, 1, "SPno4 initialization (12-2)", kOne},
        {0x9E09, kNone, 6, u16, 1, 1, "SPno5 initialization (12-2)", kOne},
        {0x9E0B, kNone, 6, u16, 1, 1, "SPno6 initialization (12-2)", kOne},
        {0x9E0D, kNone, 6, u16, 1, 1, "SPno7 initialization (12-2)", kOne},
        {0x9E0F, kNone, 6, u16, 1, 1, "SPno8 initialization (12-2)", kOne},
        // 12-3 Core parameters, 03/06.
        {0x1001, 3, 6, u16, 1, 1, "panel initial display (12-3)", {oneOf({0, 1, 2, 3, 4})}},
        {0x1003, 3, 6, u16, 1, 1, "alarm protection method after power-on (12-3)", kZeroOne},
        {0x1005, 3, 6, u16, 1, 1, "alarm erase method (12-3)", kZeroOne},
        {0x1007, 3, 6, u16, 1, 1, "speed upper limit (12-3)", kLimitSpeed},
        {0x1009, 3, 6, u16, 1, 1, "speed lower limit (12-3)", kLimitSpeed},
        {0x100B, 3, 6, u16, 1, 1, "holding force while stopped (12-3)", kZeroOne},
        {0x100D, 3, 6, u16, 1, 1, "control priority I/O 1, comm. 2 (12-3)", {oneOf({1, 2})}},
        {0x2015, 3, 6, u16, 1, 1, "control mode Mode1 = 0, Mode2 = 1 (12-3)", kZeroOne},
        // 12-4 Input / output signal functions, 03/06.
        {0x2101, 3, 6, u16, 1, 1, "IN-1 function (12-4)", kInputCodes},
        {0x2103, 3, 6, u16, 1, 1, "IN-2 function (12-4)", kInputCodes},
        {0x2105, 3, 6, u16, 1, 1, "IN-3 function (12-4)", kInputCodes},
        {0x2107, 3, 6, u16, 1, 1, "IN-4 function (12-4)", kInputCodes},
        {0x2109, 3, 6, u16, 1, 1, "OUT-1 function (12-4)", kOutputCodes},
        {0x210B, 3, 6, u16, 1, 1, "OUT-2 function (12-4)", kOutputCodes},
        // 12-5 Value-added functions and communication group, 03/06.
        {0x100F, 3, 6, u16, 1, 1, "VA speed before target speed 0–400 (12-5)", {span(0, 400)}},
        {0x1017, 3, 6, u16, 1, 1, "each running time countdown stop/run (12-5)", kZeroOne},
        {0x1019, 3, 6, u16, 1, 1, "countdown days 0–30 (12-5)", {span(0, 30)}},
        {0x101B, 3, 6, u16, 1, 1, "countdown hours 0–23 (12-5)", {span(0, 23)}},
        {0x101D, 3, 6, u16, 1, 1, "countdown minutes 0–59 (12-5)", {span(0, 59)}},
        {0x101F, 3, 6, u16, 1, 1, "countdown seconds 0–59 (12-5)", {span(0, 59)}},
        {0x1023, 3, 6, u16, 1, 1, "HML input voltage 0–5 V / 0–10 V (12-5)", kZeroOne},
        {0x00F5, 3, 6, u16, 1, 1, "communication group (12-5)", kGroup},
        // 12-6 Communication rate and reset to defaults.
        {0x1021, 3, 6, u16, 1, 1, "communication rate (12-6)", kZeroToSix},
        {0x1025, kNone, 6, u16, 1, 1, "parameter initialization (12-6)", kOne},
        // 12-7 alarm records 1–15, read with 04, decoded by the alarm code table.
        {0x1C01, 4, kNone, u16, 1, 1, "alarm record 1 (12-7)", {}, "record", "alarm"},
        {0x1C03, 4, kNone, u16, 1, 1, "alarm record 2 (12-7)", {}, "record", "alarm"},
        {0x1C05, 4, kNone, u16, 1, 1, "alarm record 3 (12-7)", {}, "record", "alarm"},
        {0x1C07, 4, kNone, u16, 1, 1, "alarm record 4 (12-7)", {}, "record", "alarm"},
        {0x1C09, 4, kNone, u16, 1, 1, "alarm record 5 (12-7)", {}, "record", "alarm"},
        {0x1C0B, 4, kNone, u16, 1, 1, "alarm record 6 (12-7)", {}, "record", "alarm"},
        {0x1C0D, 4, kNone, u16, 1, 1, "alarm record 7 (12-7)", {}, "record", "alarm"},
        {0x1C0F, 4, kNone, u16, 1, 1, "alarm record 8 (12-7)", {}, "record", "alarm"},
        {0x1C11, 4, kNone, u16, 1, 1, "alarm record 9 (12-7)", {}, "record", "alarm"},
        {0x1C13, 4, kNone, u16, 1, 1, "alarm record 10 (12-7)", {}, "record", "alarm"},
        {0x1C15, 4, kNone, u16, 1, 1, "alarm record 11 (12-7)", {}, "record", "alarm"},
        {0x1C17, 4, kNone, u16, 1, 1, "alarm record 12 (12-7)", {}, "record", "alarm"},
        {0x1C19, 4, kNone, u16, 1, 1, "alarm record 13 (12-7)", {}, "record", "alarm"},
        {0x1C1B, 4, kNone, u16, 1, 1, "alarm record 14 (12-7)", {}, "record", "alarm"},
        {0x1C1D, 4, kNone, u16, 1, 1, "alarm record 15 (12-7)", {}, "record", "alarm"},
        // 12-8 warning records 1–15, read with 04, decoded by the warning code table.
        {0x1701, 4, kNone, u16, 1, 1, "warning record 1 (12-8)", {}, "record", "warning"},
        {0x1703, 4, kNone, u16, 1, 1, "warning record 2 (12-8)", {}, "record", "warning"},
        {0x1705, 4, kNone, u16, 1, 1, "warning record 3 (12-8)", {}, "record", "warning"},
        {0x1707, 4, kNone, u16, 1, 1, "warning record 4 (12-8)", {}, "record", "warning"},
        {0x1709, 4, kNone, u16, 1, 1, "warning record 5 (12-8)", {}, "record", "warning"},
        {0x170B, 4, kNone, u16, 1, 1, "warning record 6 (12-8)", {}, "record", "warning"},
        {0x170D, 4, kNone, u16, 1, 1, "warning record 7 (12-8)", {}, "record", "warning"},
        {0x170F, 4, kNone, u16, 1, 1, "warning record 8 (12-8)", {}, "record", "warning"},
        {0x1711, 4, kNone, u16, 1, 1, "warning record 9 (12-8)", {}, "record", "warning"},
        {0x1713, 4, kNone, u16, 1, 1, "warning record 10 (12-8)", {}, "record", "warning"},
        {0x1715, 4, kNone, u16, 1, 1, "warning record 11 (12-8)", {}, "record", "warning"},
        {0x1717, 4, kNone, u16, 1, 1, "warning record 12 (12-8)", {}, "record", "warning"},
        {0x1719, 4, kNone, u16, 1, 1, "warning record 13 (12-8)", {}, "record", "warning"},
        {0x171B, 4, kNone, u16, 1, 1, "warning record 14 (12-8)", {}, "record", "warning"},
        {0x171D, 4, kNone, u16, 1, 1, "warning record 15 (12-8)", {}, "record", "warning"},
        // 12-9 Alarm / warning parameters and commands.
        {0x1011, 3, 6, u16, 1, 0.1, "overload alarm output time (12-9)", {span(0.1, 30.0)}},
        {0x1013, 3, 6, u16, 1, 1, "overload warning level 50–120 % (12-9)", {span(50, 120)}},
        {0x1200, kNone, 6, u16, 1, 1, "alarm erase, write 0000h (12-9)", {oneOf({0})}},
        {0x3101, kNone, 6, u16, 1, 1, "erase alarm records (12-9)", kOne},
        {0x3171, kNone, 6, u16, 1, 1, "erase warning records (12-9)", kOne},
        {0x007B, 4, kNone, u16, 1, 1, "communication error code (12-9, 11-5)"},
        // 12-10 Speed unit parameters.
        {0x0403, 3, 16, u32, 2, 0.01, "speed reduction ratio (12-10)", {span(1.00, 9999.99)}},
        {0x0417, 3, 16, u32, 2, 1, "time unit: distance 0–99999 (12-10)", {span(0, 99999)}},
        {0x0405, 3, 6, u16, 1, 0.01, "speed increasing ratio (12-10)", {span(1.00, 24.00)}},
        {0x0409, 3, 6, u16, 1, 1, "speed unit (12-10)", {oneOf({0, 1, 2, 3})}},
        {0x040B, 3, 6, u16, 1, 0.1, "linear speed diameter in yard (12-10)", kDiameter},
        {0x040F, 3, 6, u16, 1, 0.1, "linear speed diameter in metre (12-10)", kDiameter},
        {0x0413, 3, 6, u16, 1, 0.1, "time unit: diameter (12-10)", kDiameter},
        {0x0415, 3, 6, u16, 1, 1, "time unit: distance unit metre / yard (12-10)", kZeroOne},
        {0x041B, 3, 6, u16, 1, 1, "time unit: minute / second (12-10)", kZeroOne},
        {0x0401, 3, 6, u16, 1, 0.1, "speed display update time (12-10)", kAccel},
        {0x0407, 3, 6, u16, 1, 1, "speed display decimals 0–3 (12-10)", {span(0, 3)}},
        {0x0421, 3, 6, s16, 1, 1, "speed display correction ro-0 (12-10)", kCorrection},
        {0x0423, 3, 6, s16, 1, 1, "speed display correction ro-1 (12-10)", kCorrection},
        {0x0425, 3, 6, s16, 1, 1, "speed display correction ro-2 (12-10)", kCorrection},
        {0x0427, 3, 6, s16, 1, 1, "speed display correction ro-3 (12-10)", kCorrection},
        // 12-11 Connection, offline, device information, driver status.
        {0x0003, kNone, 6, u16, 1, 1, "communication connection command (12-11)", kOne},
        {0x0005, kNone, 6, u16, 1, 1, "communication offline command (12-11)", kOne},
        {0x0007, 4, kNone, text, 4, 1, "device name, 8 ASCII bytes (12-11)"},
        {0x000B, 4, kNone, u16, 1, 1, "firmware version hi.lo (12-11)"},
        {0x0065, 4, kNone, bits, 2, 1, "driver status (12-11)", {}, nullptr, nullptr, kStatusBits},
        // 12-12 Running commands and running data selection.
        {0x2003, kNone, 6, u16, 1, 1, "start / stop (12-12)", kZeroOne},
        {0x2005, kNone, 6, u16, 1, 1, "CW / CCW (12-12)", kZeroOne},
        {0x2011, 3, 6, u16, 1, 1, "holding force (12-12)", kZeroOne},
        {0x200F, 3, 6, u16, 1, 1, "select running data (12-12)", kSpno},
        // 12-13 Input / output status, running status, read with 04.
        {0x2009, 4, kNone, bits, 1, 1, "IN status X0–X3 (12-13)", kIn, nullptr, nullptr, kInBits},
        {0x200B, 4, kNone, bits, 1, 1, "OUT status Y0–Y1 (12-13)", kOut, nullptr, nullptr,
         kOutBits},
        {0x200D, 4, kNone, u16, 1, 1, "load rate 0–200 % (12-13)", {span(0, 200)}},
        {0x0107, 4, kNone, u16, 1, 1, "target speed (12-13)"},
        {0x0109, 4, kNone, u16, 1, 1, "current speed (12-13)"},
    };
    return table;
}

namespace {

class DbuRegisterMap : public ::testing::TestWithParam<Register>
{
};

TEST_P(DbuRegisterMap, ProfileMatchesManual)
{
    const Profile* profile = ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    ASSERT_NE(profile, nullptr) << "no built-in profile for family dbu";
    checkRegister(*profile, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Chapter12, DbuRegisterMap, ::testing::ValuesIn(dbuRegisters()),
                         [](const ::testing::TestParamInfo<Register>& row) {
                             return testName(row.param);
                         });

} // namespace
} // namespace opentop::manualcheck
