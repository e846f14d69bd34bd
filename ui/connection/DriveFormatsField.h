#pragma once

#include "transport/ConnectionSettings.h"

#include <QObject>

class QFormLayout;
class QLineEdit;
class QSettings;
class QToolButton;

namespace opentop {

// The serial page's "Drive formats" row: the drives that talk another line format than the
// port's ("7=9600:8E1"; ConnectionSettings::driveLines), and a button that tells how a drive
// is re-configured to join the bus's format (each profile's serial.formatHelp: which setting,
// how it is stored, when it takes effect, the order of the steps).
class DriveFormatsField : public QObject
{
    Q_OBJECT
public:
    DriveFormatsField(QWidget* page, QFormLayout* form);

    void setSettings(const ConnectionSettings& settings);
    // The table as typed, read at the port's baud rate; left empty when it does not parse.
    void applyTo(ConnectionSettings* settings) const;
    // Why the typed table cannot be used; empty when it can.
    QString problem(int portBaud) const;
    // The guidance the button shows.
    static QString guidance();

    QLineEdit* edit() const { return m_edit; }
    QToolButton* helpButton() const { return m_help; }

    static void recall(const QSettings& stored, ConnectionSettings* settings);
    static void remember(QSettings& stored, const ConnectionSettings& settings);

private:
    QLineEdit* m_edit = nullptr;
    QToolButton* m_help = nullptr;
};

} // namespace opentop
