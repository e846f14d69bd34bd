#pragma once

#include "model/bus/BusDrives.h"
#include "ui/files/CompareSide.h"

#include <QDialog>
#include <QPointer>
#include <QSet>
#include <functional>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace opentop {

// Two sets of settings side by side: a drive on the bus (read fresh), a drive in a backup file,
// or (side B) the profile's factory defaults. Rows that differ are highlighted; "differences
// only" and a text filter narrow the table. The comparison itself is Comparer's.
class CompareDialog : public QDialog
{
    Q_OBJECT
public:
    enum Side
    {
        A,
        B
    };
    using Source = CompareSide::Source; // BusDrive, FileDrive, Defaults (side B only)
    enum Column
    {
        Label,
        Name,
        ValueA,
        ValueB,
        ColumnCount
    };

    explicit CompareDialog(BusDrives* drives, QWidget* parent = nullptr);

    void setDriveSide(Side side, int slave);
    // Loads the file; `slave` 0 takes its first drive. False when refused (errorText()).
    bool setFileSide(Side side, const QString& path, int slave = 0);
    void setDefaultsSide(); // side B
    void compare();         // asynchronous when a side is a drive; compareFinished() follows

    QString errorText() const { return m_error; }
    QString notesText() const;
    bool isBusy() const { return m_busy; }
    int rowCount() const;
    int visibleRowCount() const;
    QStringList differences() const { return m_differences; } // profile order
    bool isHighlighted(const QString& parameter) const;
    bool isRowShown(const QString& parameter) const;
    QString cellText(const QString& parameter, Column column) const;
    void setDifferencesOnly(bool on);
    void setFilterText(const QString& text);
    QTableWidget* table() const { return m_table; }

signals:
    void compareFinished(bool ok);

private:
    void resolve(Side side, const std::function<void(bool)>& next);
    void showError(const QString& error);
    void fill();
    void applyFilter();
    int rowOf(const QString& parameter) const;

    QPointer<BusDrives> m_drives;
    CompareSide* m_sides[2];
    QTableWidget* m_table;
    QCheckBox* m_differencesOnly;
    QLineEdit* m_filter;
    QLabel* m_summary;
    QLabel* m_notes;
    QPushButton* m_compare;
    QString m_error;
    QSet<QString> m_different;
    QStringList m_differences;
    bool m_busy = false;
    int m_generation = 0; // results of a superseded comparison are dropped
};

} // namespace opentop
