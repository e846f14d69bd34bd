#pragma once

#include <QDialog>
#include <QVector>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace opentop {

class BusDrives;
class DeviceSession;
struct ParameterMeta;

// One setting written to several drives of a family at once: the chosen setting's value on
// each drive side by side (read fresh), one input that must suit every drive's profile and
// variant, and "Write to all", which writes and verifies on each drive and says per drive
// whether it worked. A value one drive does not allow is refused before anything is sent.
class MultiDriveWriteDialog : public QDialog
{
    Q_OBJECT
public:
    enum Column
    {
        MachineNumber,
        Model,
        CurrentValue,
        Result,
        ColumnCount
    };

    MultiDriveWriteDialog(BusDrives* drives, QVector<int> slaves, QString parameterName,
                          QWidget* parent = nullptr);

    QString parameterName() const;
    void setParameter(const QString& name); // as if chosen, reads the values again
    void setValueText(const QString& text); // as if typed
    // Why the input is refused (naming the drive and the allowed values); empty when accepted.
    QString problem() const { return m_problem; }
    // What the dialog says below the value: the problem, a warning, or the allowed values.
    QString messageText() const;
    bool busy() const { return m_reading > 0 || m_writing; }
    QString cellText(int slave, Column column) const;
    // Writes the value to every drive (asking first when it sets a serial lock, and when a
    // group parent's children would execute it too).
    void writeToAll();

signals:
    void readFinished();
    void writeFinished(int failed);

private:
    const ParameterMeta* meta(int slave) const;
    void readValues();
    void check();
    // SerialLock::warning for writing `text` to `slave`; empty when it does not lock.
    QString lockWarning(int slave, const QString& text) const;
    void writeConfirmed(const QString& text);
    void writeNext(QVector<int> queue, const QString& text, int failed);
    void setCell(int slave, Column column, const QString& text, bool error = false);
    void updateButtons();

    BusDrives* m_drives;
    QVector<int> m_slaves;   // every selected drive, one table row each
    QVector<int> m_writable; // those with a session of the chosen family
    QString m_family;
    QComboBox* m_parameter;
    QTableWidget* m_table;
    QLineEdit* m_value;
    QLabel* m_unit;
    QLabel* m_message;
    QPushButton* m_write;
    QString m_problem;
    int m_reading = 0;
    int m_generation = 0; // results of reads for an earlier choice are ignored
    bool m_writing = false;
};

} // namespace opentop
