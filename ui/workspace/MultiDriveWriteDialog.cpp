#include "ui/workspace/MultiDriveWriteDialog.h"

#include "model/bus/BusDrives.h"
#include "model/bus/BusGroupTracker.h"
#include "model/profile/RunningData.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"
#include "model/session/SettingCheck.h"
#include "ui/bus/VariantQuestion.h"
#include "ui/groups/GroupWriteCheck.h"
#include "ui/widgets/ConfirmBox.h"
#include "ui/widgets/PlainText.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QPushButton>
#include <QSet>
#include <QTableWidget>
#include <QVBoxLayout>

namespace opentop {

MultiDriveWriteDialog::MultiDriveWriteDialog(BusDrives* drives, QVector<int> slaves,
                                             QString parameterName, QWidget* parent)
    : QDialog(parent)
    , m_drives(drives)
    , m_slaves(std::move(slaves))
    , m_parameter(new QComboBox)
    , m_table(new QTableWidget(int(m_slaves.size()), ColumnCount))
    , m_value(new QLineEdit)
    , m_unit(new QLabel)
    , m_message(new QLabel)
    , m_write(new QPushButton(tr("&Write to all")))
{
    setWindowTitle(tr("Write one setting to several drives"));
    // The first identified drive sets the family; the others must be of the same one.
    for (int slave : m_slaves) {
        DeviceSession* s = m_drives->session(slave);
        if (s && m_family.isEmpty())
            m_family = s->profile().family;
        if (s && s->profile().family == m_family)
            m_writable << slave;
    }
    if (!m_writable.isEmpty()) {
        for (const ParameterMeta& m : m_drives->session(m_writable.first())->profile().parameters) {
            if (m.kind == QLatin1String("setting") && m.isWritable() && m.safety.isEmpty())
                m_parameter->addItem(QStringLiteral("%1 (%2)").arg(m.label, m.name), m.name);
        }
    }
    m_parameter->setCurrentIndex(std::max(0, m_parameter->findData(parameterName)));

    const QStringList headers = {tr("Machine number"), tr("Model"), tr("Current value"),
                                 tr("Result")};
    m_table->setHorizontalHeaderLabels(headers);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    for (int row = 0; row < m_slaves.size(); ++row) {
        const int slave = m_slaves.at(row);
        const DeviceInfo info = m_drives->info(slave);
        for (int c = 0; c < ColumnCount; ++c)
            m_table->setItem(row, c, new QTableWidgetItem);
        setCell(slave, MachineNumber, m_drives->listed(slave)); // with the machine's name
        setCell(slave, Model, info.model);
        if (!m_writable.contains(slave))
            setCell(
                slave, Result,
                m_drives->session(slave)
                    ? tr("Not written: another family (%1)").arg(info.family)
                    : tr("Not written: not identified (%1)").arg(DeviceInfo::stateText(info.state)),
                true);
    }

    auto* form = new QFormLayout;
    auto* parameterLabel = new QLabel(tr("&Setting:"));
    parameterLabel->setBuddy(m_parameter);
    form->addRow(parameterLabel, m_parameter);
    auto* valueRow = new QHBoxLayout;
    valueRow->addWidget(m_value, 1);
    valueRow->addWidget(m_unit);
    auto* valueLabel = new QLabel(tr("New &value:"));
    valueLabel->setBuddy(m_value);
    form->addRow(valueLabel, valueRow);
    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText); // drives' names and models
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    buttons->addButton(m_write, QDialogButtonBox::ActionRole);
    m_write->setAutoDefault(false);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_message);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_write, &QPushButton::clicked, this, &MultiDriveWriteDialog::writeToAll);
    connect(m_value, &QLineEdit::textChanged, this, &MultiDriveWriteDialog::check);
    connect(m_value, &QLineEdit::returnPressed, this, &MultiDriveWriteDialog::writeToAll);
    connect(m_parameter, qOverload<int>(&QComboBox::currentIndexChanged), this,
            &MultiDriveWriteDialog::readValues);
    readValues();
}

QString MultiDriveWriteDialog::parameterName() const
{
    return m_parameter->currentData().toString();
}

void MultiDriveWriteDialog::setParameter(const QString& name)
{
    const int index = m_parameter->findData(name);
    if (index >= 0)
        m_parameter->setCurrentIndex(index);
}

void MultiDriveWriteDialog::setValueText(const QString& text)
{
    m_value->setText(text);
}

const ParameterMeta* MultiDriveWriteDialog::meta(int slave) const
{
    const DeviceSession* s = m_drives->session(slave);
    return s ? s->profile().parameter(parameterName()) : nullptr;
}

QString MultiDriveWriteDialog::cellText(int slave, Column column) const
{
    const int row = m_slaves.indexOf(slave);
    return row < 0 ? QString() : m_table->item(row, column)->text();
}

void MultiDriveWriteDialog::setCell(int slave, Column column, const QString& text, bool error)
{
    const int row = m_slaves.indexOf(slave);
    if (row < 0)
        return;
    QTableWidgetItem* item = m_table->item(row, column);
    item->setText(text);
    item->setToolTip(PlainText::asWritten(text)); // a name or model as the drive has it
    item->setForeground(error ? QBrush(QColor(0xb0, 0x1c, 0x1c)) : QBrush());
}

void MultiDriveWriteDialog::readValues()
{
    const int generation = ++m_generation;
    m_reading = 0;
    const QString name = parameterName();
    for (int slave : m_writable) {
        setCell(slave, Result, QString());
        const ParameterMeta* m = meta(slave);
        if (!m || !m->isReadable()) {
            setCell(slave, CurrentValue, tr("cannot be read"));
            continue;
        }
        setCell(slave, CurrentValue, tr("reading…"));
        ++m_reading;
        DeviceSession* session = m_drives->session(slave);
        // What the allowed values depend on is read too, for checking the input.
        QStringList names = QStringList{name} + m->controllingParameters();
        // And an SPno's speed and deceleration, for the model's deceleration advice.
        QString field;
        if (const int spno = RunningData::spnoOf(name, &field); spno > 0) {
            for (const char* other : {"speed", "decel"}) {
                const QString n =
                    RunningData::parameter(session->profile(), spno, QLatin1String(other));
                if (!n.isEmpty() && !names.contains(n) &&
                    session->profile().parameter(n)->isReadable())
                    names << n;
            }
        }
        QPointer<MultiDriveWriteDialog> self(this);
        session->readMany(
            names,
            [self, session, slave, name, generation](const DeviceSession::ReadManyOutcome& o) {
                if (!self || generation != self->m_generation)
                    return;
                const DeviceSession::Outcome r = o.results.value(name);
                const ParameterMeta* read = session->profile().parameter(name);
                if (r.ok)
                    self->setCell(slave, CurrentValue,
                                  ValueCodec::format(*read, r.value, session->context()));
                else
                    self->setCell(slave, CurrentValue, tr("read failed: %1").arg(r.error), true);
                --self->m_reading;
                self->check();
                if (self->m_reading == 0)
                    emit self->readFinished();
            },
            ModbusRequest::Priority::Poll);
    }
    check();
    if (m_reading == 0)
        emit readFinished();
}

void MultiDriveWriteDialog::check()
{
    const QString text = m_value->text().trimmed();
    m_problem.clear();
    QSet<QString> units;
    QStringList allowed;
    for (int slave : m_writable) {
        const ParameterMeta* m = meta(slave);
        const ValueContext context = m_drives->session(slave)->context();
        QString unresolved;
        const ValueSpec& spec = m->specFor(context, &unresolved);
        if (!unresolved.isEmpty() && m_problem.isEmpty())
            m_problem = tr("Drive %1: %2 is not known yet, and the allowed values depend on it.")
                            .arg(m_drives->listed(slave))
                            .arg(unresolved);
        units.insert(spec.unit);
        allowed << tr("drive %1: %2")
                       .arg(m_drives->listed(slave))
                       .arg(ValueCodec::allowedText(*m, context));
    }
    // The same number would mean different things on drives whose unit differs.
    if (m_problem.isEmpty() && units.size() > 1)
        m_problem = tr("The unit differs between the drives (%1); write them one at a time.")
                        .arg(QStringList(units.values()).join(QStringLiteral(", ")));
    for (int slave : m_writable) {
        if (!m_problem.isEmpty() || text.isEmpty())
            break;
        const DeviceSession* session = m_drives->session(slave);
        const SettingCheck e =
            SettingCheck::of(session->profile(), *meta(slave), text, session->context(), {});
        if (!e.ok)
            m_problem = tr("Not allowed on drive %1 (%2): %3")
                            .arg(m_drives->listed(slave))
                            .arg(m_drives->info(slave).model, e.error);
        // A group parent's children execute it too, even unselected ones: they must allow it.
        else if (const QString refused =
                     m_drives->session(slave)->reachedProblem(meta(slave)->name, e.registers);
                 !refused.isEmpty())
            m_problem = tr("Not allowed on the communication group of drive %1: %2")
                            .arg(slave)
                            .arg(refused);
    }
    if (m_writable.isEmpty())
        m_problem = tr("None of the selected drives is identified.");
    // Advice, not a refusal (the model's rule, as for a page or the command line).
    QStringList advice;
    for (int slave : m_writable) {
        if (!m_problem.isEmpty() || text.isEmpty())
            break;
        const ValueContext context = m_drives->session(slave)->context();
        const Profile& profile = m_drives->session(slave)->profile();
        const SettingCheck e = SettingCheck::of(profile, *meta(slave), text, context, {});
        // Outside the recommended range, a short deceleration, the serial lock: each said.
        for (const QString& w :
             {e.warning, RunningData::warningFor(profile, meta(slave)->name, e.raw, context),
              e.lock})
            if (!w.isEmpty())
                advice << tr("Drive %1: %2").arg(m_drives->listed(slave)).arg(w);
    }
    m_unit->setText(units.size() == 1 ? *units.cbegin() : QString());
    m_value->setToolTip(tr("Allowed on %1").arg(allowed.join(QStringLiteral("; "))));
    const bool refused = !m_problem.isEmpty() && !text.isEmpty();
    m_value->setStyleSheet(
        refused ? QStringLiteral("border: 2px solid #c62828; background: #fdecea;") : QString());
    m_value->setAccessibleDescription(m_problem);
    if (!m_writing) {
        m_message->setText(!m_problem.isEmpty() ? m_problem
                           : !advice.isEmpty()
                               ? tr("Warning: %1").arg(advice.join(QLatin1Char('\n')))
                               : tr("Allowed on %1.").arg(allowed.join(QStringLiteral("; "))));
        m_message->setStyleSheet(refused             ? QStringLiteral("color: #b01c1c;")
                                 : !advice.isEmpty() ? QStringLiteral("color: #a05000;")
                                                     : QString());
    }
    updateButtons();
}

QString MultiDriveWriteDialog::messageText() const
{
    return m_message->text();
}

void MultiDriveWriteDialog::updateButtons()
{
    const bool ready = m_problem.isEmpty() && !m_value->text().trimmed().isEmpty();
    m_write->setEnabled(ready && !busy());
    m_parameter->setEnabled(!m_writing);
    m_value->setReadOnly(m_writing);
}

void MultiDriveWriteDialog::writeToAll()
{
    if (busy())
        return;
    // Drives that do not report their variant, where the setting's allowed values depend on it:
    // asked once each, before the value is judged against them.
    for (int slave : m_writable) {
        if (!VariantQuestion::ensure(this, m_drives, slave, VariantNeed::Purpose::Write,
                                     {meta(slave)->name}))
            return; // nothing is sent
    }
    check(); // against the drives' state now, not when the text was typed
    const QString text = m_value->text().trimmed();
    if (!m_problem.isEmpty() || text.isEmpty())
        return; // nothing is sent
    // It can shut this program out of the drives' configuration: asked, as on a page.
    QStringList locks;
    for (int slave : m_writable)
        if (const QString w = lockWarning(slave, text); !w.isEmpty())
            locks << tr("Drive %1: %2").arg(m_drives->listed(slave)).arg(w);
    if (locks.isEmpty()) {
        writeConfirmed(text);
        return;
    }
    QPointer<MultiDriveWriteDialog> self(this);
    ConfirmBox::ask(this, meta(m_writable.first())->label,
                    locks.join(QStringLiteral("\n\n")) + QStringLiteral("\n\n") +
                        tr("Set it on %n drive(s) anyway?", nullptr, int(locks.size())),
                    tr("&Set it"), [self, text] {
                        if (self && !self->busy() && self->m_value->text().trimmed() == text)
                            self->writeConfirmed(text);
                    });
}

QString MultiDriveWriteDialog::lockWarning(int slave, const QString& text) const
{
    const DeviceSession* session = m_drives->session(slave);
    return SettingCheck::of(session->profile(), *meta(slave), text, session->context(), {}).lock;
}

void MultiDriveWriteDialog::writeConfirmed(const QString& text)
{
    check();
    if (!m_problem.isEmpty())
        return;
    // A group parent among them: its children execute the write too (even unselected ones).
    if (!GroupWriteCheck::confirm(
            this, BusGroupTracker::of(m_drives->session(m_writable.first())), m_writable,
            tr("Write %1 to machine number(s) %2")
                .arg(meta(m_writable.first())->label, BusGroups::listText(m_writable)))) {
        m_message->setText(tr("Nothing was written."));
        return;
    }
    m_writing = true;
    for (int slave : m_writable)
        setCell(slave, Result, tr("waiting…"));
    m_message->setText(
        tr("Writing %1 to %n drive(s)…", nullptr, int(m_writable.size())).arg(parameterName()));
    m_message->setStyleSheet(QString());
    updateButtons();
    writeNext(m_writable, text, 0);
}

void MultiDriveWriteDialog::writeNext(QVector<int> queue, const QString& text, int failed)
{
    if (queue.isEmpty()) {
        m_writing = false;
        const int total = int(m_writable.size());
        m_message->setText(
            tr("Written and verified on %1 of %n drive(s).", nullptr, total).arg(total - failed));
        m_message->setStyleSheet(failed ? QStringLiteral("color: #b01c1c;") : QString());
        updateButtons();
        emit writeFinished(failed);
        return;
    }
    const int slave = queue.takeFirst();
    DeviceSession* session = m_drives->session(slave);
    const QString name = parameterName();
    setCell(slave, Result, tr("writing…"));
    QPointer<MultiDriveWriteDialog> self(this);
    session->write(
        name, text, DeviceSession::WriteOptions{},
        [self, session, slave, name, queue, text, failed](const DeviceSession::Outcome& o) {
            if (!self)
                return;
            const bool ok = o.ok && o.verified;
            if (o.value.valid)
                self->setCell(slave, CurrentValue,
                              ValueCodec::format(*session->profile().parameter(name), o.value,
                                                 session->context()));
            // The drives of its communication group were read back too: named when not all
            // hold the value. A device's error code comes with what it means.
            const QString why =
                o.explanation.isEmpty() ? o.error : o.error + QLatin1Char('\n') + o.explanation;
            self->setCell(slave, Result,
                          ok ? tr("Written and verified")
                          : o.ok && !o.notVerified.isEmpty()
                              ? tr("Written, not verified: %1").arg(o.notVerified)
                          : o.ok ? tr("Written, not verified (cannot be read back)")
                                 : tr("Failed: %1").arg(why),
                          !ok);
            self->writeNext(queue, text, failed + (ok ? 0 : 1));
        });
}

} // namespace opentop
