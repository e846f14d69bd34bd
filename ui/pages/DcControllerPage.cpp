#include "ui/pages/DcControllerPage.h"

#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"
#include "model/session/SerialLock.h"
#include "model/session/StoreTracker.h"
#include "ui/run/RunLiveState.h"
#include "ui/workspace/ParameterField.h"
#include "ui/workspace/PendingValues.h"

#include <QFormLayout>
#include <QFrame>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QStyle>
#include <QVBoxLayout>

namespace opentop {

namespace {

const QString kConfig = QStringLiteral("store.config");
const QString kPid = QStringLiteral("store.pid");
const QString kPreset = QStringLiteral("store.preset");
const QString kPresetMode = QStringLiteral("preset.speed_mode");
const QString kForward = QStringLiteral("preset.forward_speed");
const QString kCommLoss = QStringLiteral("config.comm_loss_time");

QString withoutMnemonic(QString text)
{
    return text.remove(QLatin1Char('&'));
}

} // namespace

DcControllerPage::DcControllerPage(DeviceParameters* parameters, QWidget* parent)
    : ParameterPage(parameters, tr("DC controller"), parent)
    , m_banner(new QFrame)
    , m_bannerText(new QLabel)
    , m_reload(new QPushButton(tr("Re&load stored configuration")))
{
    m_confirm = [this](const QString& title, const QString& text) {
        return QMessageBox::question(this, title, text, QMessageBox::Yes | QMessageBox::Cancel,
                                     QMessageBox::Cancel) == QMessageBox::Yes;
    };

    // The banner: prominent, above everything, only while something is not stored.
    m_banner->setObjectName(QStringLiteral("storeBanner"));
    m_banner->setStyleSheet(QStringLiteral(
        "QFrame#storeBanner { background: #fff4de; border: 2px solid #ef8f00; border-radius: 4px; }"
        "QFrame#storeBanner QLabel { color: #3d2a00; }"));
    auto* bannerLayout = new QHBoxLayout(m_banner);
    auto* icon = new QLabel;
    const int iconSize = style()->pixelMetric(QStyle::PM_MessageBoxIconSize);
    // QIcon::pixmap(QSize) picks the application's device pixel ratio (HiDPI).
    icon->setPixmap(
        style()->standardIcon(QStyle::SP_MessageBoxWarning).pixmap(QSize(iconSize, iconSize)));
    bannerLayout->addWidget(icon);
    m_bannerText->setWordWrap(true);
    m_bannerText->setTextFormat(Qt::RichText);
    bannerLayout->addWidget(m_bannerText, 1);
    const QVector<QPair<QString, QString>> buttons = {{kConfig, tr("Store &configuration")},
                                                      {kPid, tr("Store P&ID")},
                                                      {kPreset, tr("Store pre&set")}};
    for (const auto& b : buttons) {
        auto* button = new QPushButton(b.second);
        button->setToolTip(tr("Writes %1 = 1: %2").arg(b.first, storedWhat(b.first)));
        connect(button, &QPushButton::clicked, this, [this, command = b.first] { store(command); });
        m_storeButtons.insert(b.first, button);
        bannerLayout->addWidget(button);
    }
    m_reload->setToolTip(tr("Writes store.config = 0: the controller reloads the stored "
                            "configuration; unstored configuration changes are discarded"));
    connect(m_reload, &QPushButton::clicked, this, &DcControllerPage::reloadStoredConfiguration);
    bannerLayout->addWidget(m_reload);

    auto* inner = new QWidget;
    auto* grid = new QGridLayout(inner);
    addGroup(grid, 0, 0, tr("Speed mode and motor currents"),
             {{QStringLiteral("config.speed_mode"), tr("Speed &mode:")},
              {QStringLiteral("config.rated_current"), tr("Rated current:")},
              {QStringLiteral("config.max_current"), tr("Maximum start/load current:")},
              {QStringLiteral("config.brake_current"), tr("Brake current:")}},
             storeNote(kConfig));
    addGroup(grid, 1, 0, tr("Limit switches"),
             {{QStringLiteral("config.limit_enable"), tr("Limits:")},
              {QStringLiteral("config.sq1_level"), tr("SQ1 active level (forward):")},
              {QStringLiteral("config.sq2_level"), tr("SQ2 active level (reverse):")}},
             storeNote(kConfig));
    addGroup(grid, 2, 0, tr("Protective stops (0 = off)"),
             {{QStringLiteral("config.stall_time"), tr("S&tall stop time:")},
              {kCommLoss, tr("Communication loss stop time:")}},
             storeNote(kConfig));
    // Off, a lost connection leaves the motor running at its last speed command.
    m_commLossNote = new QLabel;
    m_commLossNote->setObjectName(QStringLiteral("commLossNote"));
    m_commLossNote->setWordWrap(true);
    m_commLossNote->setStyleSheet(QStringLiteral("color: #a05000;"));
    m_commLossNote->hide();
    addGroup(grid, 3, 0, tr("Serial port (used from the next power-up)"),
             {{QStringLiteral("config.baud"), tr("Baud rate:")},
              {QStringLiteral("config.parity"), tr("Parity and stop bits:")},
              {QStringLiteral("config.serial_lock"), tr("Configuration over serial:")}},
             // The line changes at power-up, not while this connection runs (errata DC-18).
             tr("Baud rate and parity are written as one 15-register block from 0x0080 that "
                "also stores the configuration; the controller uses them from the next "
                "power-up on: switch it off and on, then reconnect with them. The lock is lost "
                "at power-off until stored (Store configuration)."));
    addGroup(grid, 0, 1, tr("Speed loop PID"),
             {{QStringLiteral("pid.p"), tr("&P coefficient:")},
              {QStringLiteral("pid.i"), tr("I coefficient:")},
              {QStringLiteral("pid.d"), tr("&D coefficient:")},
              {QStringLiteral("pid.d_period"), tr("D period:")}},
             storeNote(kPid));
    addGroup(grid, 1, 1, tr("Preset speed (potentiometer/analog control)"),
             {{kPresetMode, tr("Preset speed mo&de:")},
              {QStringLiteral("preset.trigger"), tr("Trigger:")},
              {kForward, tr("&Forward speed:")},
              {QStringLiteral("preset.reverse_speed"), tr("Reverse speed:")}},
             storeNote(kPreset));
    addGroup(grid, 2, 1, tr("AI1/AI2 as digital ports"),
             {{QStringLiteral("gpio.ai1_direction"), tr("AI1 direction:")},
              {QStringLiteral("gpio.ai2_direction"), tr("AI2 direction:")},
              {QStringLiteral("gpio.ai1_level"), tr("AI1 level:")},
              {QStringLiteral("gpio.ai2_level"), tr("AI2 level:")}},
             // Only a 5-register block write from 0x0050 stores them (errata DC-12, DC-18).
             tr("Takes effect now and is kept over power-off: each change is written as one "
                "5-register block from 0x0050 that also stores the port states."));
    grid->setRowStretch(4, 1);

    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(inner);
    auto* layout = new QVBoxLayout(contentArea());
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_banner);
    layout->addWidget(m_commLossNote);
    layout->addWidget(scroll, 1);

    // Writes from anywhere (this page, a parameter table, a restore, the command line's earlier
    // run) leave settings unstored: the model keeps count (StoreTracker).
    m_tracker = StoreTracker::of(parameters->session());
    connect(m_tracker, &StoreTracker::changed, this, &DcControllerPage::updateBanner);
    updatePresetRange();
    updateBanner();
    updateCommLossNote();
}

void DcControllerPage::setMonitorHub(MonitorHub* hub)
{
    if (m_live || !hub)
        return;
    m_live = new RunLiveState(hub, parameters()->session()->slave(), contentArea());
    static_cast<QVBoxLayout*>(contentArea()->layout())->insertWidget(0, m_live);
}

QString DcControllerPage::commLossNote() const
{
    return m_commLossNote->isHidden() ? QString() : m_commLossNote->text();
}

void DcControllerPage::updateCommLossNote()
{
    const DeviceParameters::Entry* e = parameters()->entry(kCommLoss);
    const bool off = e && e->device.valid && e->device.raw == 0;
    m_commLossNote->setText(
        // The manual does not say what 0 does; OpenTOP assumes off (errata DC-16).
        off ? tr("The communication loss stop time is 0 s (%1): the manual does not say what 0 "
                 "does, and OpenTOP assumes the stop is then off: if the connection is lost while "
                 "the motor runs, the controller keeps it running at the last speed command. Set "
                 "a time so that it brakes when the bus goes quiet.")
                  .arg(e->meta->label)
            : QString());
    m_commLossNote->setVisible(off);
}

QStringList DcControllerPage::parameterNames() const
{
    return m_names;
}

QString DcControllerPage::storeNote(const QString& command) const
{
    return tr("Takes effect now, lost at power-off until stored (%1).")
        .arg(withoutMnemonic(m_storeButtons.value(command)->text()));
}

void DcControllerPage::addGroup(QGridLayout* grid, int row, int column, const QString& title,
                                const QVector<Row>& rows, const QString& note)
{
    auto* box = new QGroupBox(title);
    auto* form = new QFormLayout(box);
    form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    auto* noteLabel = new QLabel(QStringLiteral("<i>%1</i>").arg(note.toHtmlEscaped()));
    noteLabel->setWordWrap(true);
    form->addRow(noteLabel);
    for (const Row& r : rows) {
        if (!parameters()->entry(r.name))
            continue;
        auto* field = new ParameterField(parameters(), r.name);
        auto* label = new QLabel(r.label);
        label->setBuddy(field->editor());
        field->editor()->setAccessibleDescription(note);
        form->addRow(label, field);
        m_fields.insert(r.name, field);
        m_names << r.name;
        if (r.name.startsWith(QLatin1String("preset.")) && r.name.endsWith(QLatin1String("_speed")))
            field->setContextProvider([this] { return PendingValues::context(parameters()); });
        if (r.name == kForward) {
            // The preset speeds' unit and range follow the preset speed mode being written.
            m_presetRange = new QLabel;
            m_presetRange->setWordWrap(true);
            form->addRow(m_presetRange);
        }
    }
    grid->addWidget(box, row, column);
}

void DcControllerPage::parameterChanged(const QString& name)
{
    if (ParameterField* f = m_fields.value(name))
        f->sync();
    if (name == kCommLoss)
        updateCommLossNote();
    if (name != kPresetMode)
        return;
    // The speeds' unit and range follow the preset speed mode as it will be written.
    for (const QString& speed : {kForward, QStringLiteral("preset.reverse_speed")}) {
        if (ParameterField* f = m_fields.value(speed))
            f->sync();
    }
    updatePresetRange();
}

bool DcControllerPage::confirmWrite(const QStringList& pending)
{
    for (const QString& name : pending) {
        const DeviceParameters::Entry* e = parameters()->entry(name);
        if (!e || e->pendingRegisters.isEmpty())
            continue;
        const qint64 raw = qint64(ValueCodec::registersToRaw(*e->meta, e->pendingRegisters));
        const QString warning = SerialLock::warning(parameters()->profile(), *e->meta, raw,
                                                    parameters()->session()->context());
        if (!warning.isEmpty() &&
            !m_confirm(e->meta->label, warning + QStringLiteral("\n\n") + tr("Set it anyway?")))
            return false;
    }
    return true;
}

void DcControllerPage::updatePresetRange()
{
    const DeviceParameters::Entry* e = parameters()->entry(kForward);
    if (!m_presetRange || !e)
        return;
    const ValueContext context = PendingValues::context(parameters());
    QString unresolved;
    const ValueSpec& spec = e->meta->specFor(context, &unresolved);
    m_presetRange->setText(
        unresolved.isEmpty()
            ? tr("Forward and reverse speed in this mode (%1): %2")
                  .arg(spec.note, ValueCodec::allowedText(*e->meta, context))
            : tr("The unit and range of the speeds follow the preset speed mode (not read yet)."));
}

QStringList DcControllerPage::unstored() const
{
    return m_tracker->unstored();
}

bool DcControllerPage::bannerShown() const
{
    return !m_banner->isHidden();
}

void DcControllerPage::updateBanner()
{
    QStringList what;
    for (auto it = m_storeButtons.cbegin(); it != m_storeButtons.cend(); ++it) {
        it.value()->setVisible(m_tracker->isUnstored(it.key()));
        it.value()->setEnabled(!m_storing);
    }
    for (const QString& c : m_tracker->unstored())
        what << withoutMnemonic(m_storeButtons.contains(c) ? m_storeButtons.value(c)->text() : c);
    m_reload->setVisible(m_tracker->isUnstored(kConfig));
    m_reload->setEnabled(!m_storing);
    m_bannerText->setText(tr("<b>Written but not stored:</b> %1. These values act now and are "
                             "lost when the controller is switched off.")
                              .arg(what.join(QStringLiteral(" / ")).toHtmlEscaped()));
    m_banner->setAccessibleName(withoutMnemonic(m_bannerText->text()));
    m_banner->setVisible(!m_tracker->unstored().isEmpty());
}

QString DcControllerPage::storedWhat(const QString& command) const
{
    QStringList labels;
    for (const ParameterMeta& m : parameters()->profile().parameters) {
        if (m.storeWith == command)
            labels << m.label;
    }
    return labels.join(QStringLiteral(", "));
}

void DcControllerPage::store(const QString& command)
{
    if (m_storing || !m_storeButtons.contains(command))
        return;
    const QString what = withoutMnemonic(m_storeButtons.value(command)->text());
    QString text = tr("%1: the controller writes the values now in effect to its memory and "
                      "uses them from the next power-up on.\n\nStored: %2.")
                       .arg(what, storedWhat(command));
    QStringList notWritten;
    for (const QString& n : parameters()->pendingNames()) {
        if (parameters()->entry(n)->meta->storeWith == command)
            notWritten << parameters()->entry(n)->meta->label;
    }
    if (!notWritten.isEmpty())
        text +=
            QStringLiteral("\n\n") +
            tr("Not written yet, so not stored: %1.").arg(notWritten.join(QStringLiteral(", ")));
    if (!m_confirm(what, text))
        return;
    sendStore(command, QStringLiteral("1"), tr("%1: done, kept over power-off.").arg(what));
}

void DcControllerPage::reloadStoredConfiguration()
{
    if (m_storing)
        return;
    const QString title = withoutMnemonic(m_reload->text());
    const QString text = tr("The controller replaces its configuration (%1) with the one stored "
                            "in its memory.\n\nConfiguration changes written but not stored are "
                            "discarded.")
                             .arg(storedWhat(kConfig));
    if (!m_confirm(title, text))
        return;
    sendStore(kConfig, QStringLiteral("0"), tr("Stored configuration reloaded."));
}

void DcControllerPage::sendStore(const QString& command, const QString& value,
                                 const QString& doneText)
{
    m_storing = true;
    updateBanner();
    setStatus(tr("Writing %1 = %2…").arg(command, value));
    DeviceSession::WriteOptions options;
    options.explicitCommand = true; // the user confirmed exactly this command
    QPointer<DcControllerPage> self(this);
    parameters()->session()->write(
        command, value, options, [self, command, value, doneText](const DeviceSession::Outcome& o) {
            if (!self)
                return;
            self->m_storing = false;
            if (!o.ok) {
                self->setStatus(tr("%1 = %2 failed: %3").arg(command, value, o.error), true);
                self->updateBanner();
                emit self->storeFinished(false);
                return;
            }
            self->updateBanner(); // the tracker saw the store (or reload) go through
            self->setStatus(doneText);
            if (command != kConfig || value != QLatin1String("0")) {
                emit self->storeFinished(true);
                return;
            }
            // After a reload the configuration in effect changed: show it.
            QStringList config;
            for (const ParameterMeta& m : self->parameters()->profile().parameters) {
                if (m.storeWith == kConfig && m.isReadable())
                    config << m.name;
            }
            self->parameters()->refresh(config, [self](int failed) {
                if (self)
                    emit self->storeFinished(failed == 0);
            });
        });
}

} // namespace opentop
