#include "app/gui/ProductionOptions.h"

#include "model/station/EolStation.h"
#include "ui/eol/ProductionMode.h"
#include "ui/eol/ProductionView.h"
#include "ui/main/MainWindow.h"

#include <QAction>
#include <QCommandLineParser>
#include <QCoreApplication>

namespace opentop {

namespace {

const QString kProduction = QStringLiteral("production");
const QString kUnits = QStringLiteral("units");
const QString kResultsDb = QStringLiteral("results-db");
const QString kFullScreen = QStringLiteral("full-screen");
const QString kStation = QStringLiteral("station");

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ProductionOptions", text);
}

} // namespace

void ProductionOptions::addTo(QCommandLineParser& parser)
{
    parser.addOptions({
        {kProduction, tr("Start in production mode (end-of-line station) with this recipe."),
         tr("RECIPE")},
        {kUnits, tr("Per-unit values (CSV by serial number) for production mode."), tr("CSV")},
        {kResultsDb,
         tr("Results database for production mode: an SQLite file or postgresql://user@host/db."),
         tr("URL")},
        {kStation,
         tr("This station's name in the results (default: as set in the program, else the "
            "computer's name); not saved."),
         tr("NAME")},
        {kFullScreen, tr("Start full screen.")},
    });
}

bool ProductionOptions::apply(const QCommandLineParser& parser, MainWindow* window, QString* error)
{
    if ((parser.isSet(kUnits) || parser.isSet(kResultsDb) || parser.isSet(kStation)) &&
        !parser.isSet(kProduction)) {
        *error = tr("--units, --results-db and --station go with --production RECIPE");
        return false;
    }
    if (parser.isSet(kFullScreen))
        window->production()->fullScreenAction()->setChecked(true);
    if (!parser.isSet(kProduction))
        return true;
    EolStation* station = window->production()->station();
    if (parser.isSet(kStation) && !station->setStation(parser.value(kStation))) {
        *error = tr("--station needs a name");
        return false;
    }
    QStringList problems;
    if (!station->loadRecipe(parser.value(kProduction), &problems)) {
        *error = tr("%1 cannot be run:\n  %2")
                     .arg(parser.value(kProduction), problems.join(QStringLiteral("\n  ")));
        return false;
    }
    if (parser.isSet(kUnits) && !station->loadUnitValues(parser.value(kUnits), error))
        return false;
    // On the results thread, the window shown meanwhile: a server that is down is said on the
    // screen and tried again by itself; no unit starts until the database is open.
    station->openDatabase(parser.value(kResultsDb));
    window->production()->setActive(true);
    return true;
}

} // namespace opentop
