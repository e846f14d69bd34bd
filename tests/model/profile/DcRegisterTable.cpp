// The register map of the DC motor PID controller, 003_e17f880ddc4c624e.txt section 1.3, read
// independently of model/profiles/*.json, checked register by register against the built-in
// "dcpid" profile.
//
// Readings where the manual is unclear:
//  - "0.1" in the Ranges column of level and direction registers is "0,1".
//  - 0x008A/0x008B (baud, "four-byte integer") is one u32, high word first; 0x0090–0x0095 are
//    three f32 values, high word first. A two-register value is written with 0x10, whatever
//    the function code column says for its halves.
//  - The PID coefficient range 0.001–1 is only "proposed": values inside must be accepted,
//    values outside are not checked.
//  - 0x0040 depends on the speed mode 0x0080; the preset speeds 0x00A2/0x00A3 ("greater than 0
//    and within the 0x0040 range") depend on the preset speed mode 0x00A0.
//  - 0x0041 (no function code), 0x0043 ("can not access") and 0x0054 ("can not access alone")
//    are not rows here; ProfileCompletenessTest checks that 0x0043 and 0x0054 are not accessible.
#include "model/profile/ProfileRegistry.h"
#include "tests/model/profile/RegisterTable.h"

#include <gtest/gtest.h>

namespace opentop::manualcheck {
namespace {

const std::vector<Allowed> kZeroOne = {oneOf({0, 1})};
const std::vector<Allowed> kOne = {oneOf({1})};
const std::vector<Allowed> kSpeedMode = {oneOf({0, 1, 2, 3})};
const std::vector<Allowed> kZeroOneTwo = {oneOf({0, 1, 2})};
const std::vector<Allowed> kDuty1000 = {span(0, 100.0)};   // 0–1000 x 0.1 %
const std::vector<Allowed> kDiff500 = {span(-5.00, 5.00)}; // -500–500 x 0.01 V
const std::vector<Allowed> kBaud = {span(1200, 115200)};
const std::vector<Allowed> kCurrent2000 = {span(0, 20.00)};
const std::vector<Allowed> kVoltage500 = {span(0, 5.00)};
const std::vector<Allowed> kTenths255 = {span(0, 25.5)};
const std::vector<Allowed> kCoefficient = {span(0.001, 1).advisory()};
// 1.3.3: the set speed in each speed mode (0x0080): 0 PWM duty 0.1 %, 1 torque current 0.01 A,
// 2 commutation frequency in cycles/s, 3 tachogenerator feedback 0.01 V. 0 brakes.
const std::vector<Allowed> kSetSpeed = {span(-100.0, 100.0).when(0x0080, 0).withScale(0.1),
                                        span(-20.00, 20.00).when(0x0080, 1).withScale(0.01),
                                        span(-1000, 1000).when(0x0080, 2).withScale(1),
                                        span(-5.00, 5.00).when(0x0080, 3).withScale(0.01)};
// 1.3.7: greater than 0 and within the 0x0040 range of the preset speed mode (0x00A0).
const std::vector<Allowed> kPresetSpeed = {span(0.1, 100.0).when(0x00A0, 0).withScale(0.1),
                                           span(0.01, 20.00).when(0x00A0, 1).withScale(0.01),
                                           span(1, 1000).when(0x00A0, 2).withScale(1),
                                           span(0.01, 5.00).when(0x00A0, 3).withScale(0.01)};

} // namespace

const std::vector<Register>& dcRegisters()
{
    static const std::vector<Register> table = {
        // 1.3.1 Device description information, read with 03.
        {0x0000, 3, kNone, u16, 1, 1, "device identification (1.3.1)"},
        {0x0001, 3, kNone, u16, 1, 1, "version, high byte major, low byte minor (1.3.1)"},
        {0x0002, 3, kNone, text, 8, 1, "device name 0x0002–0x0009, '\\0' ended (1.3.1)"},
        {0x000A, 3, kNone, u16, 1, 1, "PWM resolution reciprocal (1.3.1)"},
        {0x000B, 3, kNone, u16, 1, 1, "PWM frequency in Hz (1.3.1)"},
        {0x000C, 3, kNone, u16, 1, 0.01, "maximum output current 0.01 A (1.3.1)"},
        {0x000D, 3, kNone, u16, 1, 1, "current resolution reciprocal in mA (1.3.1)"},
        {0x000E, 3, kUnchecked, u16, 1, 1, "retention (1.3.1)", {}, "reserved"},
        {0x000F, 3, kUnchecked, u16, 1, 1, "retention (1.3.1)", {}, "reserved"},
        // 1.3.2 Real-time status, read with 03.
        {0x0010, 3, kNone, u16, 1, 0.1, "real-time PWM duty (1.3.2)", kDuty1000},
        {0x0011, 3, kNone, u16, 1, 0.01, "real-time current 0–2000 x 0.01 A (1.3.2)", kCurrent2000},
        {0x0012, 3, kNone, u16, 1, 1, "commutation frequency 0–2000 /s (1.3.2)", {span(0, 2000)}},
        {0x0013, 3, kUnchecked, u16, 1, 1, "retention (1.3.2)", {}, "reserved"},
        {0x0014, 3, kNone, u16, 1, 0.01, "AI1 voltage 0–500 x 0.01 V (1.3.2)", kVoltage500},
        {0x0015, 3, kNone, u16, 1, 0.01, "AI2 voltage 0–500 x 0.01 V (1.3.2)", kVoltage500},
        {0x0016, 3, kNone, s16, 1, 0.01, "AI1–AI2 differential voltage (1.3.2)", kDiff500},
        {0x0017, 3, kUnchecked, u16, 1, 1, "retention (1.3.2)", {}, "reserved"},
        {0x0018, 3, kNone, u16, 1, 1, "SQ1 level (1.3.2)", kZeroOne},
        {0x0019, 3, kNone, u16, 1, 1, "SQ2 level (1.3.2)", kZeroOne},
        {0x001A, 3, kNone, u16, 1, 1, "DE level (1.3.2)", kZeroOne},
        // 1.3.3 Speed control, written with 06 only.
        {0x0040, kNone, 6, s16, 1, 0, "set speed, sign = direction (1.3.3)", kSetSpeed},
        {0x0042, kNone, 6, u16, 1, 0.1, "stop and self-lock duty (1.3.3)", kDuty1000},
        {0x0044, kNone, 6, u16, 1, 1, "natural stop / release self-lock, write 1 (1.3.3)", kOne},
        // 1.3.4 AI1 and AI2 as GPIO.
        {0x0050, 3, 6, u16, 1, 1, "AI1 port direction (1.3.4)", kZeroOne},
        {0x0051, 3, 6, u16, 1, 1, "AI2 port direction (1.3.4)", kZeroOne},
        {0x0052, 3, 6, u16, 1, 1, "AI1 port level (1.3.4)", kZeroOne},
        {0x0053, 3, 6, u16, 1, 1, "AI2 port level (1.3.4)", kZeroOne},
        // 1.3.5 System parameter configuration, 03/06.
        {0x0080, 3, 6, u16, 1, 1, "speed mode (1.3.5)", kSpeedMode},
        {0x0081, 3, 6, u16, 1, 0.1, "stall stop time 0–255 x 0.1 s (1.3.5)", kTenths255},
        {0x0082, 3, 6, u16, 1, 1, "limit enable (1.3.5)", kZeroOne},
        {0x0083, 3, 6, u16, 1, 1, "SQ1 forward limit action level (1.3.5)", kZeroOne},
        {0x0084, 3, 6, u16, 1, 1, "SQ2 reverse limit action level (1.3.5)", kZeroOne},
        {0x0085, 3, kUnchecked, u16, 1, 1, "retention (1.3.5)", {}, "reserved"},
        {0x0086, 3, 6, u16, 1, 0.01, "motor rated current 0–2000 x 0.01 A (1.3.5)", kCurrent2000},
        {0x0087, 3, 6, u16, 1, 0.01, "maximum start / load current (1.3.5)", kCurrent2000},
        {0x0088, 3, 6, u16, 1, 0.01, "brake current 0–600 x 0.01 A (1.3.5)", {span(0, 6.00)}},
        {0x0089, 3, kUnchecked, u16, 1, 1, "retention (1.3.5)", {}, "reserved"},
        {0x008A, 3, 16, u32, 2, 1, "baud rate, high word first (1.3.5)", kBaud},
        {0x008C, 3, 6, u16, 1, 1, "check mode (1.3.5)", kZeroOneTwo},
        {0x008D, 3, 6, u16, 1, 1, "ban serial communication configuration (1.3.5)", kZeroOne},
        {0x008E, 3, 6, u16, 1, 0.1, "communication interruption stop time 0–255 x 0.1 s (1.3.5)",
         kTenths255},
        {0x008F, 3, kUnchecked, u16, 1, 1, "retention (1.3.5)", {}, "reserved"},
        // 1.3.6 Closed-loop speed PID parameters.
        {0x0090, 3, 16, f32, 2, 1, "P coefficient, f32 high word first (1.3.6)", kCoefficient},
        {0x0092, 3, 16, f32, 2, 1, "I coefficient, f32 high word first (1.3.6)", kCoefficient},
        {0x0094, 3, 16, f32, 2, 1, "D coefficient, f32 high word first (1.3.6)", kCoefficient},
        {0x0096, 3, kUnchecked, u16, 1, 1, "retention (1.3.6)", {}, "reserved"},
        {0x0097, 3, 6, u16, 1, 1, "D beat cycle 1–1000 ms (1.3.6)", {span(1, 1000)}},
        // 1.3.7 Preset speed parameters (potentiometer / analog control).
        {0x00A0, 3, 6, u16, 1, 1, "preset speed mode (1.3.7)", kSpeedMode},
        {0x00A1, 3, 6, u16, 1, 1, "trigger self-hold / jog / level (1.3.7)", kZeroOneTwo},
        {0x00A2, 3, 6, u16, 1, 0, "preset forward speed (1.3.7)", kPresetSpeed},
        {0x00A3, 3, 6, u16, 1, 0, "preset reverse speed (1.3.7)", kPresetSpeed},
        // 1.3.8 Storing configuration parameters, written with 06.
        {0x0180, kNone, 6, u16, 1, 1, "reload (0) / store (1) system configuration (1.3.8)",
         kZeroOne},
        {0x0190, kNone, 6, u16, 1, 1, "store PID parameters (1.3.8)", kOne},
        {0x01A0, kNone, 6, u16, 1, 1, "store preset speed parameters (1.3.8)", kOne},
    };
    return table;
}

namespace {

class DcRegisterMap : public ::testing::TestWithParam<Register>
{
};

TEST_P(DcRegisterMap, ProfileMatchesManual)
{
    const Profile* profile = ProfileRegistry::builtIn().family(QStringLiteral("dcpid"));
    ASSERT_NE(profile, nullptr) << "no built-in profile for family dcpid";
    checkRegister(*profile, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Section13, DcRegisterMap, ::testing::ValuesIn(dcRegisters()),
                         [](const ::testing::TestParamInfo<Register>& row) {
                             return testName(row.param);
                         });

} // namespace
} // namespace opentop::manualcheck
