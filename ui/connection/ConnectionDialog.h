#pragma once

#include "transport/ConnectionSettings.h"

#include <QDialog>

class QButtonGroup;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QStackedWidget;
class QToolButton;

namespace opentop {

class DriveFormatsField;
class SerialLineFields;

// Chooses how to reach the bus: a serial port (USB–RS-485 adapter or a typed pty path), a
// Modbus TCP gateway, or a simulated bus. Starts with the settings used last time (QSettings,
// keys under "connection/") and remembers the accepted ones. Input is checked on OK; invalid
// input is explained and the dialog stays open.
class ConnectionDialog : public QDialog
{
    Q_OBJECT
public:
    explicit ConnectionDialog(QWidget* parent = nullptr);

    // The settings as entered (not validated).
    ConnectionSettings settings() const;
    void setSettings(const ConnectionSettings& settings);
    // Why the entered settings cannot be used; empty when they can.
    QString problem() const;
    // The message shown after the last refused OK.
    QString errorText() const;
    // Fills baud, parity and stop bits with a family's defaults (profile "serial").
    void applyFamilyDefaults(const QString& family);

    void accept() override;

    // Last accepted settings (defaults when none were stored); `found` says whether any were.
    static ConnectionSettings remembered(bool* found = nullptr);
    static void remember(const ConnectionSettings& settings);

    // An open failure (or timeouts right after opening) turned into what to check.
    static QString explainOpenError(const ConnectionSettings& settings, const QString& error);

private:
    QWidget* makeSerialPage();
    QWidget* makeTcpPage();
    QWidget* makeSimPage();
    QWidget* makeAdvanced();
    void refreshPorts();
    void kindChanged(int kind);
    void checkSimSpec();
    void showError(const QString& text);
    QString portFromText() const;

    QButtonGroup* m_kind = nullptr;
    QStackedWidget* m_pages = nullptr;
    QComboBox* m_port = nullptr;
    QComboBox* m_family = nullptr;
    QComboBox* m_baud = nullptr;
    QComboBox* m_parity = nullptr;
    QComboBox* m_stopBits = nullptr;
    DriveFormatsField* m_driveFormats = nullptr;
    SerialLineFields* m_line = nullptr; // RS-485 direction control and low latency
    QLineEdit* m_host = nullptr;
    QSpinBox* m_tcpPort = nullptr;
    QLineEdit* m_simSpec = nullptr;
    QLabel* m_simCheck = nullptr;
    QToolButton* m_advancedToggle = nullptr;
    QWidget* m_advanced = nullptr;
    QSpinBox* m_timeout = nullptr;
    QSpinBox* m_retries = nullptr;
    QLabel* m_error = nullptr;
};

} // namespace opentop
