#pragma once

namespace opentop {

// opentop-cli's documented exit codes (README, `opentop-cli --help`).
enum ExitCode : int
{
    ExitOk = 0,
    ExitCommunication = 1, // timeout, port error, exception from a device, device not found
    ExitUsage = 2,         // wrong command line
    ExitInvalid = 3,       // a value or file refused by validation; nothing was written
    ExitMismatch = 4,      // a write read back differently, or a drive did not stop
    ExitFail = 5,          // eol run: the unit failed its end-of-line test (it is recorded)
    // eol run: the station could not test the unit (no answer, a motor already turning, an
    // alarm latched before the test); recorded as a station error, no verdict on the unit.
    ExitStation = 6,
    ExitInterrupted = 130, // Ctrl-C; what was done is reported
};

} // namespace opentop
