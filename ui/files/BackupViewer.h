#pragma once

#include "model/files/BackupFile.h"

#include <QDialog>
#include <optional>

class QLabel;
class QTreeWidget;

namespace opentop {

// Shows what a backup file holds: where and when it was written, and each drive's settings
// with their labels, values with units and raw registers. A file that is refused (not JSON,
// changed after it was written, values the profile does not allow) shows why, and nothing of
// its content.
class BackupViewer : public QDialog
{
    Q_OBJECT
public:
    enum Column
    {
        Name,
        Label,
        Value,
        Registers,
        ColumnCount
    };

    explicit BackupViewer(QWidget* parent = nullptr);

    bool open(const QString& path); // false: refused, errorText() says why
    QString errorText() const { return m_error; }
    QString headerText() const;
    const std::optional<BackupFile>& file() const { return m_file; }
    // The text of a parameter's cell; empty when the file does not hold it.
    QString cellText(int slave, const QString& parameter, Column column) const;
    QTreeWidget* tree() const { return m_tree; }

    static QString registersText(const QVector<quint16>& registers); // "25 (0x0019)"

private:
    void chooseFile(); // modal file dialog, then open()
    void fill();

    std::optional<BackupFile> m_file;
    QString m_path;
    QString m_error;
    QLabel* m_header;
    QLabel* m_errorLabel;
    QTreeWidget* m_tree;
};

} // namespace opentop
