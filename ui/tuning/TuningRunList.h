#pragma once

#include "ui/tuning/TuningRun.h"

#include <QTreeWidget>

namespace opentop {

// The runs on the tuning page, newest last: each with its colour, what it stepped and the gains
// it ran with, and a check box that shows or hides it on the chart (before/after comparisons).
class TuningRunList : public QTreeWidget
{
    Q_OBJECT
public:
    explicit TuningRunList(QWidget* parent = nullptr);

    void addRun(const TuningRun& run);
    void updateRun(const TuningRun& run);
    void removeRun(int id);
    // The selected run's id, -1 when none.
    int selectedRun() const;
    void selectRun(int id);

signals:
    void visibilityChanged(int id, bool visible);
    void runSelected(int id);

private:
    QTreeWidgetItem* itemOf(int id) const;
    static void fill(QTreeWidgetItem* item, const TuningRun& run);
};

} // namespace opentop
