#include "ui/eol/StationFigures.h"

#include "model/eol/StationYield.h"
#include "model/eol/YieldReport.h"
#include "model/station/EolStation.h"
#include "ui/widgets/PlainText.h"

#include <QDateTime>

namespace opentop {

StationFigures::StationFigures(EolStation* station, QWidget* parent)
    : QLabel(parent)
    , m_station(station)
{
    setObjectName(QStringLiteral("stationFigures"));
    setTextFormat(Qt::PlainText); // the results database's error
    connect(m_station->yield(), &StationYield::changed, this, &StationFigures::refresh);
    refresh();
}

void StationFigures::refresh()
{
    const StationYield* y = m_station->yield();
    const YieldRow& r = y->row();
    if (!y->known()) {
        setText(tr("This shift: no figures yet (%1)")
                    .arg(y->error().isEmpty() ? tr("results database not read") : y->error()));
        return;
    }
    setText(tr("This shift: tested %1 · passed %2 · failed %3 · station errors %4 · %5")
                .arg(r.verdicts)
                .arg(r.passed)
                .arg(r.failed)
                .arg(r.stationErrors)
                .arg(YieldReport::yieldText(r)));
    // The command line names the station and the recipe.
    setToolTip(PlainText::asWritten(
        tr("This station, this recipe version, since %1 (read %2). The same figures: %3")
            .arg(y->shiftStart().toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm")),
                 y->readAt().toLocalTime().toString(QStringLiteral("HH:mm:ss")),
                 y->commandLine())));
}

} // namespace opentop
