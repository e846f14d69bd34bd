#pragma once

#include <QString>
#include <QStringList>
#include <optional>

namespace opentop::soak {

// The soak's command line.
struct SoakOptions
{
    // 247 drives, machine numbers 1..247: the three families the project simulates.
    static QString defaultDevices();

    double minutes = 60;         // how long every drive is monitored (after all answer)
    double intervalSeconds = 60; // between figure lines
    double warmupSeconds = -1;   // before the baseline; negative: SoakGoals::warmupS()
    QString devices = defaultDevices();
    int baud = 115200;
    // The monitor's interval per drive (MonitorHub). A DBU sample is 4 transactions, a DC
    // controller's 1 (docs/monitor.md): a round of the 247 drives is about 870 transactions,
    // about 5 s of a 115200 bit/s line (measured: at most about 50 samples/s). 10 s per drive
    // uses half of the line, so the rate shows the program, not a saturated line; a figure line
    // interval that is a multiple of it counts whole polling rounds.
    int pollMs = 10000;
    bool gui = true;   // also the opentop program with the bus overview open
    bool model = true; // the model's monitor hub in this process
    QString binDir;    // where opentop and opentop-sim are

    static QString usage();
    // nullopt with *error when an argument is wrong; *help when --help was asked.
    static std::optional<SoakOptions> parse(const QStringList& arguments, QString* error,
                                            bool* help);
};

} // namespace opentop::soak
