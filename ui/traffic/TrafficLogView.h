#pragma once

#include "model/traffic/TrafficStatistics.h"

#include <QSet>
#include <QVector>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QPushButton;
class QTableView;
class QTableWidget;
class QTimer;

namespace opentop {

class TrafficLog;
class TrafficLogFilter;
class TrafficLogModel;
struct TrafficEntry;

// The frames on the bus as a table, with filters, pause, save and per-drive statistics. Takes
// the log's new frames ten times a second (the log appends from the bus thread).
class TrafficLogView : public QWidget
{
    Q_OBJECT
public:
    explicit TrafficLogView(TrafficLog* log, QWidget* parent = nullptr);

    // While paused the log keeps recording but the view stands still; resuming catches up.
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // Empties the view and the statistics (the log itself keeps its frames).
    void clear();
    // Writes the frames the filters show, one TrafficEntry::toLine per line.
    bool saveTo(const QString& path, QString* error = nullptr);

    TrafficLogModel* model() const { return m_model; }
    TrafficLogFilter* filter() const { return m_filter; }
    const TrafficStatistics& statistics() const { return m_statistics; }

protected:
    void showEvent(QShowEvent* event) override;

private:
    void addEntry(const TrafficEntry& entry);
    void takeNew(); // the log's frames after the last one taken
    void catchUp();
    void addDriveChoice(int slave);
    void setStatsCell(int row, int column, const QString& text);
    void applyFilters();
    void refreshSoon();
    void refresh();
    // Behind another dock's tab, or closed, in a shown window: rows wait until it is seen.
    bool outOfView() const;
    void flush(); // pending entries into the model
    void save();

    TrafficLog* m_log;
    TrafficLogModel* m_model;
    TrafficLogFilter* m_filter;
    TrafficStatistics m_statistics;
    quint64 m_lastSequence = 0; // the last frame taken (statistics, pending or in the log)
    quint64 m_shownUpTo = 0;    // the last frame given to the model, or cleared
    QVector<TrafficEntry> m_pending;
    bool m_rowsInLog = false; // frames taken out of view: their rows are read from the log
    bool m_paused = false;
    QComboBox* m_drive;
    QComboBox* m_direction;
    QCheckBox* m_errorsOnly;
    QPushButton* m_pause;
    QTableView* m_table;
    QTableWidget* m_stats;
    QSet<int> m_driveChoices; // the drives m_drive offers
    QTimer* m_refresh;
    QTimer* m_take; // takes the log's new frames
};

} // namespace opentop
