#pragma once

#include "transport/ConnectionSettings.h"

#include <QFrame>
#include <QHash>

class QLabel;
class QPushButton;

namespace opentop {

class BusDrives;

// A bar above the drive's pages after connecting: remembers the drives (machine numbers,
// hand-set variants) seen on this connection and, on the next connection to it (also after a
// restart), offers them back — "Restore the 4 drives last seen on /dev/ttyUSB0" — or a scan.
// Nothing is sent until the user chooses. It also keeps the machines' names of this bus:
// given them at connection, stores a new one at once.
class BusRecallBar : public QFrame
{
    Q_OBJECT
public:
    // `offer`: whether to offer what was remembered (not when the drives are already given).
    BusRecallBar(BusDrives* drives, const ConnectionSettings& settings, bool offer,
                 QWidget* parent = nullptr);

    QString text() const;
    QPushButton* restoreButton() const { return m_restore; }
    QPushButton* scanButton() const { return m_scan; }

signals:
    // The remembered drives: identify these types at these machine numbers.
    void restoreRequested(const QHash<int, QString>& types);
    void scanRequested();

private:
    void save();

    BusDrives* m_drives;
    QString m_key;
    QLabel* m_text;
    QPushButton* m_restore;
    QPushButton* m_scan;
};

} // namespace opentop
