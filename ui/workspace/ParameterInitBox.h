#pragma once

#include <QGroupBox>

class QLabel;
class QPushButton;

namespace opentop {

class DeviceParameters;
class ParameterInitialiser;

// Parameter initialisation of the whole drive from its page (ParameterInitialiser): what it
// does in words, a button that first reads what the consequences depend on, then asks for a
// confirmation that names the drive and spells them out (Cancel is the default); after the
// command the drive's values are read again and unwritten edits are dropped.
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

signals:
    void finished(); // the check was refused or cancelled, or the command and re-read are done

private:
    void ask(const QStringList& consequences, const QString& command);
    void send();
    void setStatus(const QString& text, bool error);

    DeviceParameters* m_parameters;
    ParameterInitialiser* m_initialiser;
    QLabel* m_status;
    QPushButton* m_button;
    bool m_confirmed = false;
};

} // namespace opentop
