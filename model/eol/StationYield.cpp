#include "model/eol/StationYield.h"

#include "model/eol/ResultQueries.h"
#include "model/eol/ResultWriter.h"

#include <QSettings>
#include <QTimeZone>
#include <memory>

namespace opentop {

StationYield::StationYield(ResultWriter* writer, QObject* parent)
    : QObject(parent)
    , m_writer(writer)
{
}

void StationYield::refresh(const QString& station, const QString& checksum)
{
    // The factory's shifts (Settings "eol/shifts", e.g. "06:00,14:00,22:00"): the screen's
    // figures are this shift's.
    const QString shifts = QSettings().value(QStringLiteral("eol/shifts")).toString();
    QString why;
    const auto configured = shifts.isEmpty()
                                ? std::nullopt
                                : ShiftPlan::parse(shifts, QTimeZone::systemTimeZone(), &why);
    m_plan = configured.value_or(ShiftPlan());
    if (station != m_station || checksum != m_checksum)
        m_known = false; // another recipe's or station's figures are not these
    m_station = station;
    m_checksum = checksum;
    ResultFilter filter;
    filter.station = station;
    filter.checksum = checksum;
    filter.from = m_plan.shiftStart(QDateTime::currentDateTime()).toUTC();
    struct Answer
    {
        std::optional<YieldReport::Tables> tables;
        QString error;
    };
    auto answer = std::make_shared<Answer>();
    const quint64 generation = ++m_generation;
    const ShiftPlan plan = m_plan;
    m_writer->run(
        this,
        [filter, plan, answer](ResultDatabase* db) {
            if (!db) {
                answer->error = tr("the results database is not open");
                return;
            }
            answer->tables = YieldReport::query(*db, filter, plan, &answer->error);
        },
        [this, answer, generation, since = filter.from] {
            if (generation != m_generation)
                return; // a newer question is on its way
            if (!answer->tables) {
                m_error = answer->error;
                emit changed();
                return;
            }
            m_error.clear();
            m_row = YieldReport::total(answer->tables->perRecipe);
            m_since = since;
            m_readAt = QDateTime::currentDateTimeUtc();
            m_known = true;
            emit changed();
        });
}

QString StationYield::commandLine() const
{
    auto quoted = [](const QString& s) {
        return s.contains(QLatin1Char(' ')) || s.isEmpty() ? QStringLiteral("\"%1\"").arg(s) : s;
    };
    return QStringLiteral("opentop-cli eol results --yield --station %1 --checksum %2 --since %3")
        .arg(quoted(m_station), quoted(m_checksum),
             m_since.toLocalTime().toString(QStringLiteral("yyyy-MM-ddTHH:mm")));
}

} // namespace opentop
