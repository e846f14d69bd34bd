#include "ui/groups/GroupsView.h"

#include "model/bus/BusDrives.h"
#include "model/bus/BusGroupTracker.h"
#include "model/bus/GroupPlan.h"
#include "model/session/DeviceSession.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace opentop {

namespace {

const QString kDisabled = QStringLiteral("Disabled"); // the profile's label, typed as a value

} // namespace

GroupsView::GroupsView(BusGroupTracker* tracker, QWidget* parent)
    : QWidget(parent)
    , m_tracker(tracker)
    , m_problems(new QLabel(this))
    , m_table(new QTableWidget(0, ColumnCount, this))
    , m_planText(new QLabel(this))
    , m_result(new QLabel(this))
    , m_reread(new QPushButton(tr("Read &groups again"), this))
    , m_write(new QPushButton(tr("&Write plan…"), this))
{
    auto* intro = new QLabel(
        tr("A drive whose communication group is another drive's machine number is that "
           "drive's child: it executes every write and command sent to its parent, without "
           "replying. Plan the groups in the last column and write them; every drive's group is "
           "then read back."),
        this);
    intro->setWordWrap(true);
    m_problems->setWordWrap(true);
    m_problems->setObjectName(QStringLiteral("groupProblems"));
    m_planText->setWordWrap(true);
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_table->setHorizontalHeaderLabels({tr("Machine number"), tr("Model"), tr("Group"),
                                        tr("Follows / followed by"), tr("Problem"), tr("Plan"),
                                        tr("Read back")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_reread->setToolTip(tr("Read every drive's communication group from the drive"));
    m_write->setToolTip(tr("Write the planned groups (asks first), then read every drive's "
                           "group back"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_result, 1);
    buttons->addWidget(m_reread);
    buttons->addWidget(m_write);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(m_problems);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_planText);
    layout->addLayout(buttons);
    connect(m_reread, &QPushButton::clicked, this, &GroupsView::readAgain);
    connect(m_write, &QPushButton::clicked, this, &GroupsView::writePlan);
    connect(tracker, &BusGroupTracker::groupsChanged, this, &GroupsView::rebuild);
    connect(tracker->drives(), &BusDrives::driveChanged, this, &GroupsView::rebuild);
    rebuild();
}

QString GroupsView::groupText(std::optional<int> group) const
{
    return group ? QString::number(*group) : tr("Disabled");
}

int GroupsView::rowOf(int slave) const
{
    return int(m_rows.indexOf(slave));
}

QString GroupsView::cellText(int slave, Column column) const
{
    const int row = rowOf(slave);
    if (row < 0)
        return {};
    if (column == Plan) {
        const QSpinBox* box = m_plan.value(slave);
        return box ? box->text() : QString();
    }
    const QTableWidgetItem* item = m_table->item(row, column);
    return item ? item->text() : QString();
}

QString GroupsView::problemsText() const
{
    return m_problems->text();
}

QString GroupsView::resultText() const
{
    return m_result->text();
}

void GroupsView::setPlanned(int slave, int group)
{
    if (QSpinBox* box = m_plan.value(slave))
        box->setValue(group);
}

void GroupsView::rebuild()
{
    const BusGroups& groups = m_tracker->groups();
    BusDrives* drives = m_tracker->drives();
    QVector<int> rows;
    for (int slave : groups.drives()) {
        if (!m_tracker->groupParameterOf(slave).isEmpty())
            rows << slave;
    }
    QHash<int, QString> results;
    for (int slave : m_rows)
        results.insert(slave, cellText(slave, Result));
    if (rows != m_rows) {
        // New rows: plans follow the drives' settings unless the user changed them.
        QHash<int, int> kept;
        for (int slave : m_edited)
            if (m_plan.contains(slave))
                kept.insert(slave, m_plan.value(slave)->value());
        m_table->setRowCount(0);
        m_plan.clear();
        m_rows = rows;
        m_table->setRowCount(int(rows.size()));
        for (int row = 0; row < rows.size(); ++row) {
            const int slave = rows.at(row);
            for (int c = 0; c < ColumnCount; ++c)
                if (c != Plan)
                    m_table->setItem(row, c, new QTableWidgetItem);
            auto* box = new QSpinBox(m_table);
            box->setRange(0, 247);
            box->setSpecialValueText(tr("Disabled"));
            box->setAccessibleName(tr("Planned group of machine number %1").arg(slave));
            box->setToolTip(tr("The group machine number %1 should have: its own number makes "
                               "it a parent, another drive's number its child; Disabled: no "
                               "group")
                                .arg(slave));
            box->setValue(kept.contains(slave) ? kept.value(slave)
                                               : groups.groupOf(slave).value_or(0));
            connect(box, qOverload<int>(&QSpinBox::valueChanged), this, [this, slave] {
                m_edited.insert(slave);
                rebuild();
            });
            m_table->setCellWidget(row, Plan, box);
            m_plan.insert(slave, box);
        }
    }
    QStringList problems;
    QHash<int, QString> problemOf;
    for (const BusGroups::Problem& p : groups.problems()) {
        problems << BusGroups::describe(p);
        problemOf.insert(p.slave, p.kind == BusGroups::ProblemKind::Chain
                                      ? tr("child and parent")
                                      : tr("no drive %1").arg(p.group));
    }
    for (int row = 0; row < m_rows.size(); ++row) {
        const int slave = m_rows.at(row);
        const DeviceInfo info = drives->info(slave);
        m_table->item(row, MachineNumber)->setText(QString::number(slave));
        m_table->item(row, Model)->setText(info.model);
        m_table->item(row, Group)
            ->setText(m_tracker->isKnown(slave) ? groupText(groups.groupOf(slave))
                                                : tr("not read"));
        m_table->item(row, Role)->setText(groups.roleText(slave));
        QTableWidgetItem* problem = m_table->item(row, Problem);
        problem->setText(problemOf.value(slave));
        problem->setToolTip(problemOf.contains(slave) ? problems.join(QLatin1Char('\n'))
                                                      : QString());
        problem->setBackground(problemOf.contains(slave) ? QBrush(QColor(0xfd, 0xec, 0xea))
                                                         : QBrush());
        problem->setForeground(problemOf.contains(slave) ? QBrush(QColor(0xb0, 0x1c, 0x1c))
                                                         : QBrush());
        m_table->item(row, Result)->setText(results.value(slave));
        if (QSpinBox* box = m_plan.value(slave); box && !m_edited.contains(slave)) {
            const QSignalBlocker block(box);
            box->setValue(groups.groupOf(slave).value_or(0));
        }
    }
    // Every row readable with its plan box; the table scrolls (a laptop's height is short).
    m_table->resizeRowsToContents();
    m_table->setMinimumHeight(m_table->horizontalHeader()->sizeHint().height() +
                              2 * m_table->frameWidth() +
                              (m_rows.isEmpty() ? 0 : m_table->rowHeight(0)));
    m_problems->setText(problems.isEmpty()
                            ? tr("No problem found in the groups as read from the drives.")
                            : tr("Problems:") + QStringLiteral("\n• ") +
                                  problems.join(QStringLiteral(".\n• ")) + QLatin1Char('.'));
    m_problems->setStyleSheet(problems.isEmpty() ? QString() : QStringLiteral("color: #b01c1c;"));
    // What the plan changes, and what would be wrong with it.
    const GroupPlan p = plan();
    QStringList changes;
    for (int slave : p.differences(groups))
        changes << tr("%1: %2 → %3")
                       .arg(slave)
                       .arg(groupText(groups.groupOf(slave)), groupText(p.wanted(slave)));
    QStringList planProblems;
    for (const BusGroups::Problem& problem : p.result(groups).problems())
        planProblems << BusGroups::describe(problem);
    QString text = changes.isEmpty()
                       ? tr("The plan is what the drives hold.")
                       : tr("Plan changes: %1.").arg(changes.join(QStringLiteral("; ")));
    if (!planProblems.isEmpty())
        text += QLatin1Char(' ') + tr("After it: %1").arg(planProblems.join(QLatin1Char(' ')));
    m_planText->setText(text);
    m_write->setEnabled(!m_busy && !m_rows.isEmpty());
    m_reread->setEnabled(!m_busy && !m_rows.isEmpty());
}

GroupPlan GroupsView::plan() const
{
    GroupPlan p;
    for (auto it = m_plan.cbegin(); it != m_plan.cend(); ++it)
        p.want(it.key(),
               it.value()->value() == 0 ? std::nullopt : std::optional<int>(it.value()->value()));
    return p;
}

void GroupsView::setBusy(bool busy)
{
    m_busy = busy;
    for (QSpinBox* box : std::as_const(m_plan))
        box->setEnabled(!busy);
    rebuild();
}

void GroupsView::readAgain()
{
    setBusy(true);
    m_result->setText(tr("Reading every drive's group…"));
    QPointer<GroupsView> self(this);
    m_tracker->readAll([self](int failed) {
        if (!self)
            return;
        self->setBusy(false);
        self->m_result->setText(failed ? tr("%n drive(s) did not answer", nullptr, failed)
                                       : QString());
    });
}

void GroupsView::writePlan()
{
    if (m_busy)
        return;
    const BusGroups& groups = m_tracker->groups();
    const GroupPlan p = plan();
    const QVector<int> differ = p.differences(groups);
    // Each write in the order it will be sent, with the drives it also reaches.
    QStringList lines;
    for (const GroupPlan::Step& st : p.steps(groups)) {
        QString line = tr("Machine number %1: group %2 → %3.")
                           .arg(st.slave)
                           .arg(groupText(groups.groupOf(st.slave)), groupText(st.group));
        if (!st.reaches.isEmpty())
            line += QLatin1Char(' ') +
                    tr("This also reaches %1 (its children), which are written again after it.")
                        .arg(BusGroups::andListText(st.reaches));
        lines << line;
    }
    if (differ.isEmpty()) {
        prove(); // nothing to write: the plan is proved as it stands
        return;
    }
    for (const BusGroups::Problem& problem : p.result(groups).problems())
        lines << tr("Warning: %1").arg(BusGroups::describe(problem));
    QMessageBox box(
        QMessageBox::Question, tr("Write communication groups"),
        tr("Write the planned communication group to %n drive(s)?", nullptr, int(differ.size())),
        QMessageBox::NoButton, this);
    box.setObjectName(QStringLiteral("groupPlanQuestion"));
    box.setInformativeText(lines.join(QLatin1Char('\n')) + QLatin1Char('\n') +
                           tr("Drives with children are written last; every drive's group is "
                              "read back afterwards."));
    QPushButton* yes = box.addButton(tr("&Write groups"), QMessageBox::AcceptRole);
    yes->setObjectName(QStringLiteral("groupPlanYes"));
    QPushButton* cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(cancel);
    box.exec();
    if (box.clickedButton() != yes)
        return;
    for (int slave : m_rows) {
        m_table->item(rowOf(slave), Result)->setText(QString());
        m_edited.insert(slave); // the plan stays as confirmed while children change
    }
    setBusy(true);
    step(int(2 * m_rows.size() + 2));
}

void GroupsView::step(int remaining)
{
    const GroupPlan p = plan();
    const std::optional<int> next = p.nextWrite(m_tracker->groups());
    if (!next || remaining <= 0) {
        prove();
        return;
    }
    const int slave = *next;
    DeviceSession* session = m_tracker->drives()->session(slave);
    if (!session) {
        prove();
        return;
    }
    const std::optional<int> wanted = p.wanted(slave);
    m_result->setText(
        tr("Writing group %1 to machine number %2…").arg(groupText(wanted)).arg(slave));
    QPointer<GroupsView> self(this);
    session->write(m_tracker->groupParameterOf(slave),
                   wanted ? QString::number(*wanted) : kDisabled, DeviceSession::WriteOptions{},
                   [self, slave, remaining](const DeviceSession::Outcome& o) {
                       if (!self)
                           return;
                       if (!o.ok) {
                           self->m_table->item(self->rowOf(slave), Result)
                               ->setText(tr("write failed: %1").arg(o.error));
                           self->prove();
                           return;
                       }
                       // Children of the drive just written executed it too: read them all.
                       self->m_tracker->readAll([self, remaining](int) {
                           if (self)
                               self->step(remaining - 1);
                       });
                   });
}

void GroupsView::prove()
{
    m_result->setText(tr("Reading every drive's group back…"));
    QPointer<GroupsView> self(this);
    m_tracker->readAll([self](int failed) {
        if (!self)
            return;
        const GroupPlan p = self->plan();
        const BusGroups& groups = self->m_tracker->groups();
        QVector<int> wrong;
        for (int slave : self->m_rows) {
            QTableWidgetItem* item = self->m_table->item(self->rowOf(slave), Result);
            const bool ok = groups.groupOf(slave) == p.wanted(slave);
            if (!ok)
                wrong << slave;
            if (!item->text().startsWith(tr("write failed")))
                item->setText(ok ? tr("✓ %1").arg(self->groupText(groups.groupOf(slave)))
                                 : tr("✗ %1, planned %2")
                                       .arg(self->groupText(groups.groupOf(slave)),
                                            self->groupText(p.wanted(slave))));
            item->setForeground(ok ? QBrush() : QBrush(QColor(0xb0, 0x1c, 0x1c)));
        }
        const bool proved = wrong.isEmpty() && failed == 0;
        self->m_edited.clear();
        self->setBusy(false);
        self->m_result->setText(
            proved
                ? tr("Proved: every drive read back holds its planned group.")
                : tr("Not as planned: %1 (read back; %n drive(s) did not answer).", nullptr, failed)
                      .arg(BusGroups::listText(wrong)));
        self->m_result->setStyleSheet(proved ? QString() : QStringLiteral("color: #b01c1c;"));
        emit self->planFinished(proved);
    });
}

} // namespace opentop
