#include "ui/pages/IoTerminalsPage.h"

#include "model/profile/ValueCodec.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "ui/workspace/ParameterField.h"
#include "ui/workspace/PendingValues.h"

#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

namespace {

const QString kMode = QStringLiteral("core.control_mode");
const QString kPriority = QStringLiteral("core.control_priority");

// What an input function does (manual 7-1-1, 7-2, 7-3, 9-1); the code carries its mode
// (Mode1 0x00–0x09, Mode2 0x10–0x19).
QString inputFunctionText(qint64 code)
{
    switch (code) {
    case 0x00:
    case 0x10:
        return IoTerminalsPage::tr("Not functioning: the drive ignores this input.");
    case 0x01:
        return IoTerminalsPage::tr("RUN/STOP: ON runs the motor, OFF stops it.");
    case 0x02:
        return IoTerminalsPage::tr("CW/CCW: the running direction, OFF clockwise, ON "
                                   "counter-clockwise.");
    case 0x11:
        return IoTerminalsPage::tr("CW/STOP: ON runs the motor clockwise, OFF stops it.");
    case 0x12:
        return IoTerminalsPage::tr("CCW/STOP: ON runs the motor counter-clockwise, OFF stops it.");
    case 0x04:
    case 0x14:
        return IoTerminalsPage::tr("Alarm-Reset: clears an alarm (alarm erase method "
                                   "Alarm-Reset).");
    case 0x05:
    case 0x15:
    case 0x06:
    case 0x16:
    case 0x07:
    case 0x17:
        return IoTerminalsPage::tr("M%1: bit %1 of the running data selection (M2 M1 M0 = "
                                   "000–111 select SPno1–SPno8).")
            .arg((code & 0x0F) - 5);
    case 0x08:
    case 0x18:
        return IoTerminalsPage::tr("Ext-Error (EX-Er): an external interrupt that stops the "
                                   "motor; the only input still active in communication "
                                   "priority.");
    case 0x09:
    case 0x19:
        return IoTerminalsPage::tr("H-Free: releases the motor's holding force while stopped.");
    default:
        return IoTerminalsPage::tr("Code %1 is not a known input function.").arg(code);
    }
}

QString outputFunctionText(qint64 code)
{
    switch (code) {
    case 0:
        return IoTerminalsPage::tr("Not functioning: the output stays off.");
    case 1:
        return IoTerminalsPage::tr("Alarm-Out: switches when an alarm stops the motor.");
    case 2:
        return IoTerminalsPage::tr("Reach Speed-Out: switches when the motor reaches the "
                                   "target speed.");
    case 3:
        return IoTerminalsPage::tr("VA-Out: switches before the target speed, at the target "
                                   "speed minus the VA speed.");
    case 4:
        return IoTerminalsPage::tr("Speed-Out: speed pulses, 24 per motor revolution.");
    case 5:
        return IoTerminalsPage::tr("Warning-Out: switches on a warning; the motor keeps "
                                   "running.");
    case 6:
        return IoTerminalsPage::tr("Move-Out: switches while the motor is turning.");
    default:
        return IoTerminalsPage::tr("Code %1 is not a known output function.").arg(code);
    }
}

QLabel* wrapped(const QString& text, QWidget* parent)
{
    auto* label = new QLabel(text, parent);
    label->setWordWrap(true);
    return label;
}

} // namespace

IoTerminalsPage::IoTerminalsPage(DeviceParameters* parameters, QWidget* parent)
    : ParameterPage(parameters, tr("I/O terminals"), parent)
{
    for (const QString& n : {kMode, kPriority})
        if (parameters->entry(n))
            m_names << n;
    for (int x = 0; x < 4; ++x) {
        const QString n = QStringLiteral("io.x%1").arg(x);
        if (parameters->entry(n))
            m_inputs << n;
    }
    m_names += m_inputs;
    for (const QString& n : {QStringLiteral("io.y0"), QStringLiteral("io.y1")})
        if (parameters->entry(n))
            m_names << n;

    auto* layout = new QVBoxLayout(contentArea());
    auto* control = new QGroupBox(tr("Control"), contentArea());
    auto* form = new QFormLayout(control);
    if (parameters->entry(kMode)) {
        auto* mode = new ParameterField(parameters, kMode, control);
        m_fields.insert(kMode, mode);
        form->addRow(tr("Control &mode:"), mode);
        form->addRow(wrapped(tr("Mode1 uses RUN/STOP and CW/CCW inputs (like UBD, SBD, DBD); "
                                "Mode2 uses CW/STOP and CCW/STOP inputs (like DB, BMD). The "
                                "input function codes differ: switching the mode disables the "
                                "other mode's input functions, so every input X0–X3 needs a "
                                "function of the new mode."),
                             control));
        m_modeNote = wrapped(QString(), control);
        form->addRow(m_modeNote);
    }
    if (parameters->entry(kPriority)) {
        auto* priority = new ParameterField(parameters, kPriority, control);
        m_fields.insert(kPriority, priority);
        form->addRow(tr("Control &priority:"), priority);
        form->addRow(wrapped(tr("In I/O priority the input terminals run the motor. In "
                                "communication priority the drive runs from bus commands and of "
                                "the inputs only EX-Er (external error) acts."),
                             control));
    }
    layout->addWidget(control);

    // The connectors in pin order, as on the drive (manual 4: CN5 and CN6).
    auto* connectors = new QHBoxLayout;
    auto* inputs = new QGroupBox(tr("Inputs — CN5"), contentArea());
    auto* in = new QGridLayout(inputs);
    addCommon(in, 0, 1, QStringLiteral("C0"), tr("COM0: input common (external supply)"));
    addTerminal(in, 1, QStringLiteral("2"), QStringLiteral("X0"), QStringLiteral("io.x0"));
    addTerminal(in, 3, QStringLiteral("3"), QStringLiteral("X1"), QStringLiteral("io.x1"));
    addCommon(in, 5, 4, QStringLiteral("C1"), tr("COM1: input common (internal supply)"));
    addTerminal(in, 6, QStringLiteral("5"), QStringLiteral("X2"), QStringLiteral("io.x2"));
    addTerminal(in, 8, QStringLiteral("6"), QStringLiteral("X3"), QStringLiteral("io.x3"));
    in->setColumnStretch(2, 1);
    in->setRowStretch(10, 1);
    auto* outputs = new QGroupBox(tr("Outputs — CN6"), contentArea());
    auto* out = new QGridLayout(outputs);
    addTerminal(out, 0, QStringLiteral("1–2"), QStringLiteral("Y0+ / Y0−"),
                QStringLiteral("io.y0"));
    addTerminal(out, 2, QStringLiteral("3–4"), QStringLiteral("Y1+ / Y1−"),
                QStringLiteral("io.y1"));
    out->setColumnStretch(2, 1);
    out->setRowStretch(4, 1);
    connectors->addWidget(inputs, 1);
    connectors->addWidget(outputs, 1);
    layout->addLayout(connectors);

    auto* flagRow = new QHBoxLayout;
    m_flag = wrapped(QString(), contentArea());
    m_flag->setStyleSheet(QStringLiteral("color: #b01c1c;"));
    m_flag->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_useDefaults = new QPushButton(contentArea());
    m_useDefaults->setToolTip(
        tr("Give each flagged input the default function of the new mode (pending, not written)"));
    connect(m_useDefaults, &QPushButton::clicked, this, &IoTerminalsPage::useModeDefaults);
    flagRow->addWidget(m_flag, 1);
    flagRow->addWidget(m_useDefaults);
    layout->addLayout(flagRow);
    layout->addStretch(1);

    // The choosers offer what is valid once the pending edits (a new mode) are written.
    for (const QString& n : m_inputs)
        m_fields.value(n)->setContextProvider([this] { return editContext(); });
    updateMode();
}

void IoTerminalsPage::addCommon(QGridLayout* grid, int row, int pin, const QString& terminal,
                                const QString& text)
{
    QWidget* box = grid->parentWidget();
    grid->addWidget(new QLabel(QString::number(pin), box), row, 0);
    grid->addWidget(new QLabel(QStringLiteral("<b>%1</b>").arg(terminal), box), row, 1);
    grid->addWidget(new QLabel(text, box), row, 2);
}

void IoTerminalsPage::addTerminal(QGridLayout* grid, int row, const QString& pins,
                                  const QString& terminal, const QString& name)
{
    if (!parameters()->entry(name))
        return;
    QWidget* box = grid->parentWidget();
    auto* pinLabel = new QLabel(pins, box);
    pinLabel->setToolTip(tr("Connector pin %1").arg(pins));
    grid->addWidget(pinLabel, row, 0);
    auto* label = new QLabel(QStringLiteral("<b>%1</b>").arg(terminal.toHtmlEscaped()), box);
    grid->addWidget(label, row, 1);
    auto* f = new ParameterField(parameters(), name, box);
    f->editor()->setAccessibleName(tr("Terminal %1 function").arg(terminal));
    label->setBuddy(f->editor());
    m_fields.insert(name, f);
    grid->addWidget(f, row, 2);
    auto* description = wrapped(QString(), box); // wraps: the page fits a laptop's screen
    m_descriptions.insert(name, description);
    grid->addWidget(description, row + 1, 2);
    updateDescription(name);
}

ValueContext IoTerminalsPage::editContext() const
{
    return PendingValues::context(parameters());
}

std::optional<qint64> IoTerminalsPage::shownRaw(const QString& name) const
{
    const QVector<quint16> registers = PendingValues::registers(parameters(), name);
    if (registers.isEmpty())
        return std::nullopt;
    return qint64(ValueCodec::registersToRaw(*parameters()->entry(name)->meta, registers));
}

QString IoTerminalsPage::modeLabel(std::optional<qint64> raw) const
{
    const DeviceParameters::Entry* e = parameters()->entry(kMode);
    if (!e || !raw)
        return tr("unknown");
    for (const EnumOption& o : e->meta->spec.options) {
        if (o.value == *raw)
            return o.label;
    }
    return QString::number(*raw);
}

QString IoTerminalsPage::description(const QString& name) const
{
    const QLabel* label = m_descriptions.value(name);
    return label ? label->text() : QString();
}

QString IoTerminalsPage::flagText() const
{
    return m_flag->text();
}

void IoTerminalsPage::updateDescription(const QString& name)
{
    QLabel* label = m_descriptions.value(name);
    if (!label)
        return;
    const std::optional<qint64> raw = shownRaw(name);
    if (!raw) {
        label->setText(tr("Not read yet."));
        return;
    }
    const bool input = m_inputs.contains(name);
    const QString text = input ? inputFunctionText(*raw) : outputFunctionText(*raw);
    const bool invalid = m_invalid.contains(name);
    label->setText(
        invalid ? tr("Not valid in %1: choose again").arg(modeLabel(editContext().rawOf(kMode)))
                : text);
    label->setToolTip(text);
    label->setStyleSheet(invalid ? QStringLiteral("color: #b01c1c;") : QString());
}

void IoTerminalsPage::updateMode()
{
    const ValueContext context = editContext();
    const std::optional<qint64> mode = context.rawOf(kMode);
    m_invalid.clear();
    QStringList terminals;
    for (const QString& n : m_inputs) {
        const std::optional<qint64> raw = shownRaw(n);
        // Only a known mode can make a code invalid; an unread mode leaves nothing to judge.
        if (mode && raw &&
            !ValueCodec::checkRaw(*parameters()->entry(n)->meta, double(*raw), context).isEmpty()) {
            m_invalid << n;
            terminals << n.mid(3).toUpper();
        }
    }
    for (const QString& n : m_inputs)
        updateDescription(n);

    const DeviceParameters::Entry* e = parameters()->entry(kMode);
    if (m_modeNote && e) {
        const bool changing = !e->pendingRegisters.isEmpty();
        m_modeNote->setText(
            changing ? tr("The mode changes from %1 to %2 when written; Write page writes the "
                          "mode first, then the terminals.")
                           .arg(modeLabel(e->device.valid ? std::optional<qint64>(e->device.raw)
                                                          : std::nullopt),
                                modeLabel(mode))
                     : QString());
        m_modeNote->setVisible(changing);
    }
    m_flag->setText(terminals.isEmpty()
                        ? QString()
                        : tr("Not valid in %1: %2. Choose their functions again before writing.")
                              .arg(modeLabel(mode), terminals.join(QStringLiteral(", "))));
    m_flag->setVisible(!terminals.isEmpty());
    m_useDefaults->setText(tr("Use %1 defaults").arg(modeLabel(mode)));
    m_useDefaults->setVisible(!terminals.isEmpty());
}

QString IoTerminalsPage::writeBlocker() const
{
    return m_flag ? m_flag->text() : QString();
}

void IoTerminalsPage::useModeDefaults()
{
    const ValueContext context = editContext();
    for (const QString& n : QStringList(m_invalid)) {
        const ValueSpec& spec = parameters()->entry(n)->meta->specFor(context);
        if (spec.defaultRaw)
            parameters()->setPending(n, QString::number(qint64(*spec.defaultRaw)));
    }
}

void IoTerminalsPage::parameterChanged(const QString& name)
{
    if (name == kMode) {
        // Every chooser's options follow the mode, pending or read.
        for (const QString& n : m_inputs)
            m_fields.value(n)->sync();
    }
    if (ParameterField* f = m_fields.value(name))
        f->sync();
    updateDescription(name);
    updateMode();
}

} // namespace opentop
