#include "ui/monitor/MonitorDetails.h"

#include "model/monitor/DeviceMonitor.h"
#include "model/profile/RoleEvaluator.h"
#include "model/session/DeviceParameters.h"
#include "ui/monitor/TerminalLamps.h"
#include "ui/widgets/StaleLook.h"

#include <QFormLayout>
#include <QLabel>

namespace opentop {

MonitorDetails::MonitorDetails(DeviceParameters* parameters, QWidget* parent)
    : QWidget(parent)
    , m_parameters(parameters)
    , m_form(new QFormLayout(this))
{
    m_form->setContentsMargins(0, 0, 0, 0);
}

QLabel* MonitorDetails::addTextRow(const QString& key, const QString& label)
{
    auto* value = new QLabel(this);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_values.insert(key, value);
    m_form->addRow(label + QLatin1Char(':'), value);
    return value;
}

void MonitorDetails::build(const MonitorSample& sample, const QStringList& shownElsewhere)
{
    for (const MonitorValue& v : sample.values) {
        if (!v.meta || shownElsewhere.contains(v.meta->name))
            continue;
        if (v.meta->type == DataType::Bits) {
            bool lamps = false;
            for (const BitField& f : v.meta->bits) {
                if (f.width == 1 && TerminalLamps::isLampField(f.values)) {
                    lamps = true;
                    continue;
                }
                // A field with named states ("CCW", "SPno2", "Mode2") is a text row.
                addTextRow(v.meta->name + QLatin1Char('.') + f.name, f.label);
            }
            if (lamps) {
                auto* row = new TerminalLamps(*v.meta, this);
                m_lamps.insert(v.meta->name, row);
                // Lamps under their caption, across the whole width: side by side as on the
                // drive where it allows, wrapped onto more rows where not.
                auto* caption = new QLabel(v.meta->label + QLatin1Char(':'), this);
                caption->setBuddy(row);
                m_form->addRow(caption);
                m_form->addRow(row);
                for (const QString& f : row->functionParameters())
                    row->setFunctionText(f, m_parameters->deviceText(f));
                row->setStale(m_stale);
                // What a lamp means may depend on a setting: read it if nobody has yet.
                QStringList unread;
                for (const QString& c : row->conditionParameters()) {
                    showCondition(row, c);
                    const DeviceParameters::Entry* e = m_parameters->entry(c);
                    if (e && !e->device.valid)
                        unread << c;
                }
                if (!unread.isEmpty())
                    m_parameters->refresh(unread);
            }
            continue;
        }
        addTextRow(v.meta->name, v.meta->label);
    }
}

void MonitorDetails::showSample(const MonitorSample& s)
{
    for (const MonitorValue& v : s.values) {
        if (!v.meta)
            continue;
        if (QLabel* l = m_values.value(v.meta->name))
            l->setText(v.value.valid ? v.text : tr("not read"));
        if (TerminalLamps* lamps = m_lamps.value(v.meta->name))
            lamps->setRaw(v.value.valid ? std::optional<double>(v.value.raw) : std::nullopt);
        for (const BitField& f : v.meta->bits) {
            if (QLabel* l = m_values.value(v.meta->name + QLatin1Char('.') + f.name))
                l->setText(v.value.valid ? RoleEvaluator::fieldText(
                                               f, RoleEvaluator::fieldValue(f, v.value.raw))
                                         : tr("not read"));
        }
    }
}

void MonitorDetails::parameterChanged(const QString& name)
{
    for (TerminalLamps* lamps : std::as_const(m_lamps)) {
        if (lamps->functionParameters().contains(name))
            lamps->setFunctionText(name, m_parameters->deviceText(name));
        if (lamps->conditionParameters().contains(name))
            showCondition(lamps, name);
    }
}

void MonitorDetails::showCondition(TerminalLamps* lamps, const QString& parameter)
{
    const DeviceParameters::Entry* e = m_parameters->entry(parameter);
    const ParameterMeta* meta = m_parameters->profile().parameter(parameter);
    const bool known = e && e->device.valid;
    lamps->setCondition(
        parameter, known ? std::optional<double>(e->device.raw) : std::nullopt,
        tr("%1: %2").arg(meta ? meta->label : parameter, m_parameters->deviceText(parameter)));
}

void MonitorDetails::setStale(bool stale)
{
    m_stale = stale;
    StaleLook::apply(this, stale);
    for (TerminalLamps* lamps : std::as_const(m_lamps))
        lamps->setStale(stale);
}

} // namespace opentop
