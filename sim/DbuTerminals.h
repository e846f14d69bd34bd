#pragma once

#include <optional>

namespace opentop {

class SimDevice;

// The DBU's input and output terminals (manual 7-1, 12-4): the function assigned to each of
// X0..X3 and Y0/Y1, what the inputs command under I/O priority, and the output levels.
class DbuTerminals
{
public:
    // Input functions: the low nibble of an io.xN code (Mode2 codes add 0x10).
    enum Input
    {
        Run = 1,
        Direction = 2,
        AlarmReset = 4,
        M0 = 5,
        M1 = 6,
        M2 = 7,
        ExtError = 8
    };

    struct IoCommand
    {
        bool run = false;
        int spno = 0;            // 0..7
        std::optional<bool> ccw; // unset when no input gives the direction
    };
    // What the output functions look at.
    struct State
    {
        bool alarm = false;
        bool reach = false; // at the target speed
        bool va = false;    // within va.speed of the target
        bool warning = false;
        double speed = 0; // r/min, magnitude
        double revolutions = 0;
    };

    explicit DbuTerminals(const SimDevice& device);

    // Bit mask of the inputs assigned `function`.
    int assigned(int function) const;
    // The command given by the input levels (bit n: Xn on).
    IoCommand command(int inputs) const;
    // Bit 0: Y0, bit 1: Y1.
    int outputs(const State& state) const;

    static constexpr int kPulsesPerRevolution = 24; // Speed-out, manual 5-6

private:
    int level(int function, const State& state) const;

    const SimDevice& m_device;
};

} // namespace opentop
