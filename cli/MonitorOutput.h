#pragma once

#include <QDateTime>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QVector>

namespace opentop {

class DeviceMonitor;
struct MonitorSample;

// The columns of `monitor` for one drive and their text, CSV and JSON forms. Columns follow the
// profile's "monitor" role: a column per value, per bit field, a display-unit column after the
// current and target speed when the drive has a speed display, and the active alarm.
class MonitorOutput
{
public:
    struct Column
    {
        enum class Kind
        {
            Value,   // a parameter's value
            Field,   // a bit field of a parameter
            Display, // currentSpeed / targetSpeed in the drive's display unit
            Alarm    // the active alarm, from the "alarm" code table
        };
        Kind kind = Kind::Value;
        QString parameter;
        QString field;       // Field: the bit field's name
        bool target = false; // Display: target instead of current speed
        QString header;      // for people
        QString key;         // CSV column, with the unit: "status.current_speed [r/min]"
        int width = 0;       // text column width
        bool number = false;
    };

    explicit MonitorOutput(const DeviceMonitor& monitor);

    const QVector<Column>& columns() const { return m_columns; }
    QString family() const { return m_family; }

    QString headerLine() const; // "Time          ID  Current speed ..."
    QString line(const MonitorSample& sample) const;
    // One CSV cell per column (numbers without unit; enumerations and fields as labels).
    QStringList csvCells(const MonitorSample& sample) const;
    QJsonObject json(const MonitorSample& sample) const;

    static QString timeText(const MonitorSample& sample);
    // ISO 8601 with milliseconds and the UTC offset: "2024-05-01T14:03:07.250+02:00".
    static QString isoTime(const QDateTime& time);
    // A CSV cell: DisplayText::csvCell(), quoted when it holds a comma or a quote.
    static QString csvEscape(const QString& text);

private:
    QString text(const Column& column, const MonitorSample& sample) const;

    const DeviceMonitor& m_monitor;
    QString m_family;
    QVector<Column> m_columns;
};

} // namespace opentop
