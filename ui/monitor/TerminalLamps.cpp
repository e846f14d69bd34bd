#include "monitor/TerminalLamps.h"

#include "profile/ParameterMeta.h"

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
        Lamp lamp{f.bit,
                  f.label.isEmpty() ? f.name : f.label,
                  new QLabel(cell),
                  new QLabel(cell),
                  f.function,
                  nullptr};
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
