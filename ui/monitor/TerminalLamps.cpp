#include "ui/monitor/TerminalLamps.h"

#include "model/profile/ParameterMeta.h"
#include "ui/widgets/StaleLook.h"

#include <QGridLayout>
#include <QLabel>
#include <QResizeEvent>
#include <QVBoxLayout>
#include <algorithm>
#include <optional>

namespace opentop {

namespace {

const QString kOn = QStringLiteral(
    "QLabel { background: #2eb83c; border: 2px solid #1b6e24; border-radius: 9px; }");
const QString kOff = QStringLiteral(
    "QLabel { background: transparent; border: 2px solid #9e9e9e; border-radius: 9px; }");
const QString kUnknown = QStringLiteral(
    "QLabel { background: transparent; border: 2px dashed #9e9e9e; border-radius: 9px; }");
// The last state read, no longer live: an ON lamp is filled grey, never green.
const QString kOnStale = QStringLiteral(
    "QLabel { background: #9e9e9e; border: 2px solid #6e6e6e; border-radius: 9px; }");
const QString kNotApplicable = QStringLiteral(
    "QLabel { background: transparent; border: 2px dotted #c8c8c8; border-radius: 9px; }");

} // namespace

bool TerminalLamps::isLampField(const QStringList& values)
{
    return values.isEmpty() || (values.size() == 2 &&
                                values[0].compare(QLatin1String("OFF"), Qt::CaseInsensitive) == 0);
}

TerminalLamps::TerminalLamps(const ParameterMeta& meta, QWidget* parent)
    : QWidget(parent)
    , m_grid(new QGridLayout(this))
{
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setHorizontalSpacing(kSpacing);
    m_grid->setVerticalSpacing(6);
    for (const BitField& f : meta.bits) {
        if (f.width != 1 || !isLampField(f.values))
            continue;
        // One cell per terminal: its name, the lamp, ON/OFF and what it is assigned to. The
        // cells wrap onto more rows when the width does not hold them side by side.
        auto* cell = new QWidget(this);
        auto* column = new QVBoxLayout(cell);
        column->setContentsMargins(0, 0, 0, 0);
        column->setSpacing(2);
        Lamp lamp;
        lamp.bit = f.bit;
        lamp.name = f.label.isEmpty() ? f.name : f.label;
        lamp.lamp = new QLabel(cell);
        lamp.state = new QLabel(cell);
        lamp.function = f.function;
        lamp.appliesParam = f.appliesParam;
        lamp.appliesRaw = f.appliesRaw;
        lamp.lamp->setFixedSize(18, 18);
        lamp.lamp->setObjectName(QStringLiteral("lamp_%1").arg(f.name));
        auto* name = new QLabel(lamp.name, cell);
        QFont bold = name->font();
        bold.setBold(true);
        name->setFont(bold);
        column->addWidget(name, 0, Qt::AlignHCenter);
        column->addWidget(lamp.lamp, 0, Qt::AlignHCenter);
        column->addWidget(lamp.state, 0, Qt::AlignHCenter);
        if (!f.function.isEmpty()) {
            lamp.functionLabel = new QLabel(cell);
            lamp.functionLabel->setEnabled(false); // secondary: what the terminal is for
            column->addWidget(lamp.functionLabel, 0, Qt::AlignHCenter);
        }
        m_cells << cell;
        m_lamps << lamp;
    }
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    setRaw(std::nullopt);
    arrange(int(m_cells.size()));
}

int TerminalLamps::cellWidth() const
{
    int width = 0;
    for (QWidget* cell : m_cells)
        width = std::max(width, cell->sizeHint().width());
    return width;
}

void TerminalLamps::arrange(int columns)
{
    columns = std::max(1, std::min(columns, int(m_cells.size())));
    if (columns == m_columns)
        return;
    m_columns = columns;
    for (QWidget* cell : m_cells)
        m_grid->removeWidget(cell);
    for (int i = 0; i < m_cells.size(); ++i)
        m_grid->addWidget(m_cells[i], i / columns, i % columns, Qt::AlignTop);
    const int cell = cellWidth(); // every terminal as wide: they line up as on the drive
    for (int c = 0; c <= int(m_cells.size()); ++c) {
        m_grid->setColumnStretch(c, c == columns ? 1 : 0);
        m_grid->setColumnMinimumWidth(c, c < columns ? cell : 0);
    }
    updateGeometry();
}

QSize TerminalLamps::minimumSizeHint() const
{
    // One terminal across at least; as high as the rows the terminals take at this width (a
    // resize that wraps them asks the parent for the height again).
    return QSize(cellWidth(), m_grid->minimumSize().height());
}

QSize TerminalLamps::sizeHint() const
{
    // Every terminal side by side, as on the drive, where the width allows it.
    const int count = int(m_cells.size());
    if (count == 0)
        return QSize(0, 0);
    return QSize(count * cellWidth() + (count - 1) * kSpacing,
                 m_cells.first()->sizeHint().height());
}

void TerminalLamps::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    arrange((width() + kSpacing) / (cellWidth() + kSpacing));
}

void TerminalLamps::setRaw(std::optional<double> raw)
{
    // Style sheets are costly to apply; samples mostly repeat the state shown.
    if (m_shown && raw == *m_shown)
        return;
    m_shown = raw;
    paint();
}

void TerminalLamps::setStale(bool stale)
{
    if (stale == m_stale)
        return;
    m_stale = stale;
    StaleLook::apply(this, stale);
    paint();
}

QStringList TerminalLamps::conditionParameters() const
{
    QStringList names;
    for (const Lamp& l : m_lamps) {
        if (!l.appliesParam.isEmpty() && !names.contains(l.appliesParam))
            names << l.appliesParam;
    }
    return names;
}

void TerminalLamps::setCondition(const QString& parameter, std::optional<double> raw,
                                 const QString& text)
{
    bool changed = false;
    for (Lamp& l : m_lamps) {
        if (l.appliesParam != parameter)
            continue;
        // Not read yet: the drive's own bit is shown.
        const bool applies = !raw || *raw == l.appliesRaw;
        changed = changed || applies != l.applies || text != l.conditionText;
        l.applies = applies;
        l.conditionText = text;
    }
    if (changed)
        paint();
}

void TerminalLamps::paint()
{
    const bool known = m_shown && m_shown->has_value();
    const quint64 bits = known ? quint64(m_shown->value()) : 0;
    for (Lamp& l : m_lamps) {
        if (!l.applies) {
            l.lamp->setStyleSheet(kNotApplicable);
            l.state->setText(tr("n/a"));
            l.lamp->setToolTip(tr("%1: not applicable (%2)").arg(l.name, l.conditionText));
        } else if (!known) {
            l.lamp->setStyleSheet(kUnknown);
            l.state->setText(tr("?"));
            l.lamp->setToolTip(tr("%1: not read").arg(l.name));
        } else {
            const bool on = (bits >> l.bit) & 1U;
            l.lamp->setStyleSheet(on ? (m_stale ? kOnStale : kOn) : kOff);
            l.state->setText(on ? tr("ON") : tr("OFF"));
            l.lamp->setToolTip(on ? tr("%1 is ON").arg(l.name) : tr("%1 is OFF").arg(l.name));
            if (m_stale)
                l.lamp->setToolTip(tr("%1 (last state read, not live)").arg(l.lamp->toolTip()));
        }
        l.lamp->setAccessibleName(l.lamp->toolTip());
        l.lamp->setProperty("stale", m_stale);
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
    // A longer text widens every cell: fewer may fit side by side.
    m_columns = 0;
    arrange(width() > 0 ? (width() + kSpacing) / (cellWidth() + kSpacing) : int(m_cells.size()));
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
