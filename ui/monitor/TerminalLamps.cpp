#include "monitor/TerminalLamps.h"

#include "profile/ParameterMeta.h"

#include <QGridLayout>
#include <QLabel>
#include <optional>

namespace opentop {

namespace {

const QString kOn = QStringLiteral(
    "QLabel { background: #2eb83c; border: 2px solid #1b6e24; border-radius: 9px; }");
const QString kOff = QStringLiteral(
    "QLabel { background: transparent; border: 2px solid #9e9e9e; border-radius: 9px; }");
const QString kUnknown = QStringLiteral(
    "QLabel { background: transparent; border: 2px dashed #9e9e9e; border-radius: 9px; }");

} // namespace

bool TerminalLamps::isLampField(const QStringList& values)
{
    return values.isEmpty() || (values.size() == 2 &&
                                values[0].compare(QLatin1String("OFF"), Qt::CaseInsensitive) == 0);
}

TerminalLamps::TerminalLamps(const ParameterMeta& meta, QWidget* parent)
    : QWidget(parent)
{
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setHorizontalSpacing(14);
    grid->setVerticalSpacing(2);
    for (const BitField& f : meta.bits) {
        if (f.width != 1 || !isLampField(f.values))
            continue;
        const int column = m_lamps.size();
        Lamp lamp{f.bit,
                  f.label.isEmpty() ? f.name : f.label,
                  new QLabel(this),
                  new QLabel(this),
                  f.function,
                  nullptr};
        lamp.lamp->setFixedSize(18, 18);
        lamp.lamp->setObjectName(QStringLiteral("lamp_%1").arg(f.name));
        auto* name = new QLabel(lamp.name, this);
        QFont bold = name->font();
        bold.setBold(true);
        name->setFont(bold);
        grid->addWidget(name, 0, column, Qt::AlignHCenter);
        grid->addWidget(lamp.lamp, 1, column, Qt::AlignHCenter);
        grid->addWidget(lamp.state, 2, column, Qt::AlignHCenter);
        if (!f.function.isEmpty()) {
            lamp.functionLabel = new QLabel(this);
            lamp.functionLabel->setEnabled(false); // secondary: what the terminal is for
            grid->addWidget(lamp.functionLabel, 3, column, Qt::AlignHCenter);
        }
        m_lamps << lamp;
    }
    grid->setColumnStretch(m_lamps.size(), 1);
    setRaw(std::nullopt);
}

void TerminalLamps::setRaw(std::optional<double> raw)
{
    // Style sheets are costly to apply; samples mostly repeat the state shown.
    if (m_shown && raw == *m_shown)
        return;
    m_shown = raw;
    for (Lamp& l : m_lamps) {
        if (!raw) {
            l.lamp->setStyleSheet(kUnknown);
            l.state->setText(tr("?"));
            l.lamp->setToolTip(tr("%1: not read").arg(l.name));
            continue;
        }
        const bool on = (quint64(*raw) >> l.bit) & 1U;
        l.lamp->setStyleSheet(on ? kOn : kOff);
        l.state->setText(on ? tr("ON") : tr("OFF"));
        l.lamp->setToolTip(on ? tr("%1 is ON").arg(l.name) : tr("%1 is OFF").arg(l.name));
        l.lamp->setAccessibleName(l.lamp->toolTip());
    }
}

QStringList TerminalLamps::functionParameters() const
{
    QStringList names;
    for (const Lamp& l : m_lamps) {
        if (!l.function.isEmpty())
            names << l.function;
    }
    return names;
}

void TerminalLamps::setFunctionText(const QString& parameter, const QString& text)
{
    for (Lamp& l : m_lamps) {
        if (l.function == parameter && l.functionLabel)
            l.functionLabel->setText(text);
    }
}

QString TerminalLamps::functionText(const QString& parameter) const
{
    for (const Lamp& l : m_lamps) {
        if (l.function == parameter && l.functionLabel)
            return l.functionLabel->text();
    }
    return QString();
}

QString TerminalLamps::stateText() const
{
    QStringList parts;
    for (const Lamp& l : m_lamps)
        parts << QStringLiteral("%1 %2").arg(l.name, l.state->text());
    return parts.join(QStringLiteral(", "));
}

} // namespace opentop
