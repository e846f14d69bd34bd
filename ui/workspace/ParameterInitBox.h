#pragma once

#include "model/session/ParameterInitialiser.h"
#include "transport/ConnectionSettings.h"

#include <QGroupBox>
#include <QPointer>
#include <functional>

class QLabel;
class QPushButton;

namespace opentop {

class DeviceParameters;

// Parameter initialisation of the whole drive from its page (ParameterInitialiser): what it
// does in words, a button that first reads what the consequences depend on, then asks for a
// confirmation that names the drive and spells them out (Cancel is the default); after the
// command the drive's values are read again and unwritten edits are dropped. When the drive's
// line settings return to factory values that differ from the connection's, it says what to do
// and offers to reconnect at them (after the profile's power-on delay).
class ParameterInitBox : public QGroupBox
{
    Q_OBJECT
public:
    explicit ParameterInitBox(DeviceParameters* parameters, QWidget* parent = nullptr);

    // Whether the drive's profile has parameter initialisation.
    static bool supported(const DeviceParameters* parameters);
    QPushButton* button() const { return m_button; }
    QString statusText() const;
    void start(); // as if the button were clicked
    // Offered after an initialisation that changes the line settings; hidden otherwise.
    QPushButton* reconnectButton() const { return m_reconnect; }
    // The settings a reconnect opens: the connection's with the profile's factory line settings.
    ConnectionSettings reconnectSettings() const;
    void reconnect(); // as if the reconnect button were clicked

    // Who opens a connection (the main window); `owner` going away clears it.
    using ReconnectHandler = std::function<void(const ConnectionSettings&)>;
    static void setReconnectHandler(QObject* owner, ReconnectHandler handler);

signals:
    void finished(); // the check was refused or cancelled, or the command and re-read are done

private:
    void ask(const ParameterInitialiser::Plan& plan);
    void send();
    void setStatus(const QString& text, bool error);

    DeviceParameters* m_parameters;
    ParameterInitialiser* m_initialiser;
    QLabel* m_status;
    QPushButton* m_button;
    QPushButton* m_reconnect;
    ParameterInitialiser::Plan m_plan;
    bool m_confirmed = false;
};

} // namespace opentop
