#include "ui/pages/SpeedUnitsPage.h"

#include "model/profile/ValueCodec.h"
#include "model/session/DeviceParameters.h"
#include "ui/workspace/ParameterField.h"
#include "ui/workspace/PendingValues.h"

#include <QComboBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>

namespace opentop {

namespace {

QGroupBox* group(const QString& title, QFormLayout** form)
{
    auto* box = new QGroupBox(title);
    *form = new QFormLayout(box);
    (*form)->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    return box;
}

} // namespace

SpeedUnitsPage::SpeedUnitsPage(DeviceParameters* parameters, QWidget* parent)
    : ParameterPage(parameters, tr("Speed display"), parent)
    , m_names(SpeedDisplay::Names::withPrefix())
    , m_distanceUnit(new QLabel)
    , m_speed(new QSpinBox)
    , m_direction(new QComboBox)
    , m_display(new QLabel)
    , m_displayUnit(new QLabel)
    , m_previewNote(new QLabel)
{
    m_parameterNames = m_names.all();
    m_parameterNames.insert(4, QStringLiteral("unit.update_time"));

    auto* inner = new QWidget;
    auto* grid = new QGridLayout(inner);
    QFormLayout* form = nullptr;

    QGroupBox* unitBox = group(tr("Unit shown"), &form);
    addRow(form, m_names.mode, tr("&Unit:"));
    addRow(form, m_names.reduction, tr("Reduction r&atio:"));
    addRow(form, m_names.increase, tr("&Increasing ratio:"));
    grid->addWidget(unitBox, 0, 0);

    // The manual does not say in which unit diameters are entered; OpenTOP takes millimetres
    // (docs/errata.md DBU-23), shown at each field from the profile.
    QGroupBox* linearBox = group(tr("Linear speed"), &form);
    addRow(form, m_names.diameterYard, tr("Roller diameter for &yd/min:"));
    addRow(form, m_names.diameterMeter, tr("Roller diameter for &m/min:"));
    grid->addWidget(linearBox, 1, 0);

    QGroupBox* timeBox = group(tr("Time for a distance"), &form);
    addRow(form, m_names.timeDiameter, tr("Roller &diameter:"));
    addRow(form, m_names.distance, tr("Dis&tance:"), m_distanceUnit);
    addRow(form, m_names.distanceUnit, tr("Distance u&nit:"));
    addRow(form, m_names.timeUnit, tr("Time &format (min = m:ss):"));
    grid->addWidget(timeBox, 2, 0);

    QGroupBox* displayBox = group(tr("Display"), &form);
    addRow(form, m_names.decimals, tr("D&ecimals (0–3):"));
    addRow(form, QStringLiteral("unit.update_time"), tr("U&pdate time:"));
    grid->addWidget(displayBox, 0, 1);

    // Speed sections of the manual; the lowest speed is 250 r/min (DBU200) or 300 (DBU400).
    QGroupBox* correctionBox = group(tr("Display corrections (motor r/min)"), &form);
    const QStringList sections = {tr("ro-&0, 250 (300)–500 r/min:"), tr("ro-&1, 501–1000 r/min:"),
                                  tr("ro-&2, 1001–2000 r/min:"), tr("ro-&3, 2001–3000 r/min:")};
    for (int i = 0; i < m_names.corrections.size() && i < sections.size(); ++i)
        addRow(form, m_names.corrections.at(i), sections.at(i));
    grid->addWidget(correctionBox, 1, 1);

    QGroupBox* previewBox = group(tr("Preview of the drive's display"), &form);
    m_speed->setRange(0, 4000);
    m_speed->setValue(1500);
    m_speed->setSuffix(tr(" r/min"));
    m_speed->setAccessibleName(tr("Motor speed for the preview"));
    auto* speedLabel = new QLabel(tr("Motor &speed:"));
    speedLabel->setBuddy(m_speed);
    form->addRow(speedLabel, m_speed);
    m_direction->addItem(tr("Forward"));
    m_direction->addItem(tr("Reverse (shown with “-”)"));
    auto* directionLabel = new QLabel(tr("Dire&ction:"));
    directionLabel->setBuddy(m_direction);
    form->addRow(directionLabel, m_direction);
    QFont big = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    big.setPointSizeF(big.pointSizeF() * 2.2);
    big.setBold(true);
    m_display->setFont(big);
    m_display->setObjectName(QStringLiteral("preview.display"));
    m_display->setStyleSheet(
        QStringLiteral("background: #1b1b1b; color: #ff5a36; padding: 0.2em 0.5em;"));
    m_display->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_display->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* displayRow = new QHBoxLayout;
    displayRow->addWidget(m_display, 1);
    displayRow->addWidget(m_displayUnit);
    form->addRow(tr("Drive shows:"), displayRow);
    m_previewNote->setWordWrap(true);
    form->addRow(m_previewNote);
    grid->addWidget(previewBox, 2, 1);
    grid->setRowStretch(3, 1);

    auto* scroll = new QScrollArea(contentArea());
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(inner);
    auto* layout = new QVBoxLayout(contentArea());
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);

    connect(m_speed, qOverload<int>(&QSpinBox::valueChanged), this, &SpeedUnitsPage::updatePreview);
    connect(m_direction, qOverload<int>(&QComboBox::currentIndexChanged), this,
            &SpeedUnitsPage::updatePreview);
    updateEnabled();
    updatePreview();
}

QStringList SpeedUnitsPage::parameterNames() const
{
    return m_parameterNames;
}

void SpeedUnitsPage::addRow(QFormLayout* form, const QString& name, const QString& label,
                            QLabel* extraUnit)
{
    if (!parameters()->entry(name))
        return; // a profile without this setting: nothing to edit
    auto* field = new ParameterField(parameters(), name);
    auto* rowLabel = new QLabel(label);
    rowLabel->setBuddy(field->editor());
    m_fields.insert(name, field);
    m_labels.insert(name, rowLabel);
    if (auto* edit = qobject_cast<QLineEdit*>(field->editor())) {
        // The preview follows what is typed, before it is confirmed with Enter or Tab.
        connect(edit, &QLineEdit::textEdited, this, [this, name](const QString& text) {
            const ValueCodec::Encoded e = ValueCodec::encodeText(
                *parameters()->entry(name)->meta, text, PendingValues::context(parameters()));
            if (e.ok)
                m_typed.insert(name, e.registers);
            else
                m_typed.remove(name);
            updatePreview();
        });
        connect(edit, &QLineEdit::editingFinished, this, [this, name] {
            m_typed.remove(name);
            updatePreview();
        });
    }
    if (!extraUnit) {
        form->addRow(rowLabel, field);
        return;
    }
    auto* row = new QHBoxLayout;
    row->addWidget(field, 1);
    row->addWidget(extraUnit);
    m_labels.insert(name + QStringLiteral("#unit"), extraUnit);
    form->addRow(rowLabel, row);
}

void SpeedUnitsPage::parameterChanged(const QString& name)
{
    if (ParameterField* f = m_fields.value(name))
        f->sync();
    updatePreview();
}

std::optional<double> SpeedUnitsPage::valueAsWritten(const QString& name) const
{
    const auto typed = m_typed.constFind(name);
    if (typed != m_typed.cend()) {
        const ParameterMeta& meta = *parameters()->entry(name)->meta;
        const ParamValue v =
            ValueCodec::decode(meta, typed.value(), PendingValues::context(parameters()));
        if (v.valid)
            return v.number;
    }
    return PendingValues::number(parameters(), name);
}

void SpeedUnitsPage::updateEnabled()
{
    const std::optional<double> mode = valueAsWritten(m_names.mode);
    // Unknown unit (not read yet): nothing is irrelevant yet, so nothing is disabled.
    auto uses = [&mode](SpeedDisplay::Mode m) { return !mode || int(*mode) == int(m); };
    QHash<QString, bool> relevant;
    relevant.insert(m_names.diameterYard, uses(SpeedDisplay::Mode::LinearYard));
    relevant.insert(m_names.diameterMeter, uses(SpeedDisplay::Mode::LinearMeter));
    const bool time = uses(SpeedDisplay::Mode::Time);
    for (const QString& n :
         {m_names.timeDiameter, m_names.distance, m_names.distanceUnit, m_names.timeUnit})
        relevant.insert(n, time);
    for (auto it = m_fields.cbegin(); it != m_fields.cend(); ++it) {
        const bool on = relevant.value(it.key(), true);
        it.value()->setEnabled(on);
        m_labels.value(it.key())->setEnabled(on);
        if (QLabel* unit = m_labels.value(it.key() + QStringLiteral("#unit")))
            unit->setEnabled(on);
    }
    // The distance is in the distance unit (docs/speed-display.md).
    const bool yards = valueAsWritten(m_names.distanceUnit).value_or(0) == 1;
    m_distanceUnit->setText(yards ? tr("yd") : tr("m"));
}

void SpeedUnitsPage::setPreviewSpeed(int rpm, bool reverse)
{
    m_speed->setValue(rpm);
    m_direction->setCurrentIndex(reverse ? 1 : 0);
    updatePreview();
}

QString SpeedUnitsPage::previewText() const
{
    return m_display->text();
}

QString SpeedUnitsPage::previewUnit() const
{
    return m_displayUnit->text();
}

void SpeedUnitsPage::updatePreview()
{
    updateEnabled(); // typed values may change the unit or the distance unit
    const double rpm = m_direction->currentIndex() == 1 ? -m_speed->value() : m_speed->value();
    QString error;
    const std::optional<SpeedDisplay> display = SpeedDisplay::fromValues(
        m_names, [this](const QString& n) { return valueAsWritten(n); }, &error,
        [this](const QString& n) {
            const DeviceParameters::Entry* e = parameters()->entry(n);
            return e ? e->meta->label : n;
        });
    if (!display) {
        m_display->setText(QStringLiteral("-----"));
        m_displayUnit->clear();
        m_previewNote->setText(error);
        m_previewNote->setStyleSheet(QStringLiteral("color: #b01c1c;"));
        return;
    }
    const SpeedDisplay::Shown shown = display->show(rpm);
    m_display->setText(shown.panel); // what the 5-digit panel shows, as the monitor's mirror
    m_displayUnit->setText(shown.unit);
    m_display->setAccessibleName(tr("Drive shows %1 %2").arg(shown.panel, shown.unit));
    QStringList notes;
    const int section = SpeedDisplay::section(rpm);
    if (section >= 0)
        notes << tr("Section ro-%1: correction %2 r/min, shaft speed %3 r/min.")
                     .arg(section)
                     .arg(display->settings().corrections[section])
                     .arg(ValueCodec::formatNumber(display->shaftRpm(rpm), 2));
    if (shown.overflow)
        notes << tr("%1 has more digits than the drive's %2-digit display can show.")
                     .arg(shown.text)
                     .arg(SpeedDisplay::kPanelDigits);
    else if (shown.panel != shown.text)
        notes << tr("Computed %1 %2; the %3-digit display drops the decimals that do not fit.")
                     .arg(shown.text, shown.unit)
                     .arg(SpeedDisplay::kPanelDigits);
    const QStringList pending = parameters()->pendingNames();
    const bool edited = std::any_of(m_parameterNames.cbegin(), m_parameterNames.cend(),
                                    [&pending](const QString& n) { return pending.contains(n); });
    if (!m_typed.isEmpty() || edited)
        notes << tr("Includes edits not yet written.");
    m_previewNote->setText(notes.join(QLatin1Char(' ')));
    m_previewNote->setStyleSheet(QString());
}

} // namespace opentop
