#pragma once

#include <QString>

class QCommandLineParser;

namespace opentop {

class MainWindow;

// Command-line options of the GUI for monitoring and for measuring it: --monitor-all opens the
// bus overview and the trends of every drive, --poll-ms sets the poll interval, --quit-after
// quits after a time and prints what the monitor reached (scripts/measure-gui.sh reads it).
class MonitorOptions
{
public:
    static void addTo(QCommandLineParser& parser);
    // Arranges what the options ask for; false and *error when a value is not usable.
    static bool apply(const QCommandLineParser& parser, MainWindow* window, QString* error);
};

} // namespace opentop
