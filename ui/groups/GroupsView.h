#pragma once

#include <QHash>
#include <QSet>
#include <QWidget>
#include <optional>

class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace opentop {

class BusGroupTracker;
class GroupPlan;

// The communication groups of the bus (TROY manual 11-3): who follows whom, what is wrong
// (a child that is itself a parent, a group number no drive has), and a plan the engineer
// edits and writes. A written plan is proved by reading every drive's group setting back.
class GroupsView : public QWidget
{
    Q_OBJECT
public:
    enum Column
    {
        MachineNumber,
        Model,
        Group,
        Role,
        Problem,
        Plan,
        Result,
        ColumnCount
    };

    explicit GroupsView(BusGroupTracker* tracker, QWidget* parent = nullptr);

    QTableWidget* table() const { return m_table; }
    QString cellText(int slave, Column column) const;
    QString problemsText() const;
    QString resultText() const;
    bool busy() const { return m_busy; }
    // The planned group of `slave` (0: disabled), as if set in its Plan cell.
    void setPlanned(int slave, int group);
    // Writes the plan after asking (naming every drive each write reaches); then reads every
    // drive's group back and says whether the bus holds the plan.
    void writePlan();
    void readAgain();

signals:
    void planFinished(bool proved);

private:
    void rebuild();
    GroupPlan plan() const;
    QString groupText(std::optional<int> group) const;
    void step(int remaining);
    void prove();
    int rowOf(int slave) const;
    void setBusy(bool busy);

    BusGroupTracker* m_tracker;
    QLabel* m_problems;
    QTableWidget* m_table;
    QLabel* m_planText;
    QLabel* m_result;
    QPushButton* m_reread;
    QPushButton* m_write;
    QVector<int> m_rows;          // machine number of each row
    QHash<int, QSpinBox*> m_plan; // by machine number
    QSet<int> m_edited;           // plans the user changed (kept over a refresh)
    bool m_busy = false;
};

} // namespace opentop
