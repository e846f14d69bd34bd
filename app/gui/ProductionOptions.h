#pragma once

#include <QString>

class QCommandLineParser;

namespace opentop {

class MainWindow;

// Command-line options of the GUI for an end-of-line station PC that starts straight into the
// operator screen: --production RECIPE (production mode with that recipe), --units CSV (the
// per-unit values), --results-db URL, --full-screen.
class ProductionOptions
{
public:
    static void addTo(QCommandLineParser& parser);
    // False and *error when the recipe, values or database cannot be used (nothing opened).
    static bool apply(const QCommandLineParser& parser, MainWindow* window, QString* error);
};

} // namespace opentop
