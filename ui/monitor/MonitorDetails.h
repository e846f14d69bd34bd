#pragma once

#include <QHash>
#include <QStringList>
#include <QWidget>

class QFormLayout;
class QLabel;

namespace opentop {

class DeviceParameters;
class TerminalLamps;
struct MonitorSample;

// The monitor page's rows of every other value of a sample: one text row per value or named
// bit field, terminals as lamps with what their function means. Laid out from the first sample.
class MonitorDetails : public QWidget
{
    Q_OBJECT
public:
    explicit MonitorDetails(DeviceParameters* parameters, QWidget* parent = nullptr);

    bool isBuilt() const { return !m_values.isEmpty() || !m_lamps.isEmpty(); }
    // Rows for the values of `sample`, except the parameters in `shownElsewhere`.
    void build(const MonitorSample& sample, const QStringList& shownElsewhere);
    void showSample(const MonitorSample& sample);
    // A terminal's function was read or written: what its lamp means; a setting a lamp's
    // meaning depends on: whether it applies.
    void parameterChanged(const QString& name);
    // Every value and lamp greyed as no longer live (monitor/Freshness).
    void setStale(bool stale);

    QLabel* value(const QString& parameter) const { return m_values.value(parameter); }
    TerminalLamps* lamps(const QString& parameter) const { return m_lamps.value(parameter); }

private:
    QLabel* addTextRow(const QString& key, const QString& label);
    void showCondition(TerminalLamps* lamps, const QString& parameter);

    DeviceParameters* m_parameters;
    QFormLayout* m_form;
    QHash<QString, QLabel*> m_values; // by parameter, or "parameter.field" for a bit field
    QHash<QString, TerminalLamps*> m_lamps;
    bool m_stale = false;
};

} // namespace opentop
