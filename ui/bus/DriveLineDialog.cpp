#include "ui/bus/DriveLineDialog.h"

#include "model/bus/BusDrives.h"
#include "model/bus/LineFormatHint.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceInfo.h"
#include "transport/ModbusClient.h"

#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QSpinBox>
#include <QStringList>
#include <QVBoxLayout>
#include <algorithm>

namespace opentop {

DriveLineDialog::DriveLineDialog(const ConnectionSettings& port, int slave,
                                 const LineFormat& current, const QString& family, QWidget* parent)
    : QDialog(parent)
    , m_port(port)
{
    setObjectName(QStringLiteral("driveLineDialog"));
    setWindowTitle(slave > 0 ? tr("Line format of machine number %1").arg(slave) : tr("Add drive"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    layout->addLayout(form);
    m_slave = new QSpinBox(this);
    m_slave->setRange(1, 247);
    m_slave->setValue(slave > 0 ? slave : 1);
    if (slave <= 0) {
        form->addRow(tr("&Machine number:"), m_slave);
        // The number as each family sets it on the device, to read it off the switches.
        auto* switches = new QLabel(DeviceInfo::switchHelp(), this);
        switches->setObjectName(QStringLiteral("switchHelp"));
        switches->setWordWrap(true);
        form->addRow(QString(), switches);
    } else {
        m_slave->hide();
    }

    m_format = new QComboBox(this);
    m_format->setObjectName(QStringLiteral("lineFormat"));
    m_format->setEditable(true);
    m_format->setInsertPolicy(QComboBox::NoInsert);
    m_format->addItem(tr("The port's (%1)").arg(port.line().text()), QString());
    for (const LineFormatHint::Candidate& c :
         LineFormatHint::otherFormats(ProfileRegistry::builtIn(), port))
        m_format->addItem(c.format.text(), c.format.token());
    if (current.isSet() && current != port.line()) {
        int at = m_format->findData(current.token());
        if (at < 0) {
            m_format->addItem(current.text(), current.token());
            at = m_format->count() - 1;
        }
        m_format->setCurrentIndex(at);
    }
    m_format->setToolTip(tr("The baud rate and format the drive is set to: requests to it "
                            "switch the port to it and back between transactions. Type another "
                            "as 38400 8E1."));
    form->addRow(tr("&Line format:"), m_format);

    // How a drive is changed to the bus's format: the profile's own words.
    QStringList help;
    for (const Profile& p : ProfileRegistry::builtIn().profiles()) {
        if (p.serial.formatHelp.isEmpty() || (!family.isEmpty() && p.family != family))
            continue;
        const QString steps = LineFormatHint::asSteps(p.serial.formatHelp);
        help << (family.isEmpty() ? tr("%1: %2").arg(p.name, steps) : steps);
    }
    if (!help.isEmpty()) {
        auto* text = new QLabel(help.join(QStringLiteral("\n\n")), this);
        text->setObjectName(QStringLiteral("formatHelp"));
        text->setWordWrap(true);
        text->setTextInteractionFlags(Qt::TextSelectableByMouse);
        layout->addWidget(text);
    }
    m_error = new QLabel(this);
    m_error->setStyleSheet(QStringLiteral("color: #b01c1c;"));
    m_error->setWordWrap(true);
    m_error->hide();
    layout->addWidget(m_error);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &DriveLineDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    setMinimumWidth(520);
}

int DriveLineDialog::slave() const
{
    return m_slave->value();
}

LineFormat DriveLineDialog::line() const
{
    const int at = m_format->findText(m_format->currentText());
    const QString token = at >= 0 ? m_format->itemData(at).toString() : m_format->currentText();
    if (token.isEmpty())
        return LineFormat();
    return LineFormat::parse(token, m_port.baud).value_or(LineFormat());
}

QString DriveLineDialog::problem() const
{
    const int at = m_format->findText(m_format->currentText());
    if (at >= 0)
        return QString();
    QString error;
    LineFormat::parse(m_format->currentText(), m_port.baud, &error);
    return error;
}

void DriveLineDialog::accept()
{
    const QString error = problem();
    m_error->setText(error);
    m_error->setVisible(!error.isEmpty());
    if (error.isEmpty())
        QDialog::accept();
}

DriveLineDialog* DriveLineDialog::askToAdd(QWidget* parent, BusDrives* drives, int suggested,
                                           std::function<void(int)> add)
{
    const int from = std::clamp(suggested, 1, 247);
    auto* dialog = new DriveLineDialog(drives->client()->settings(), 0,
                                       drives->client()->driveLine(from), QString(), parent);
    dialog->slaveBox()->setValue(from);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, parent, [dialog, drives, add] {
        drives->setLine(dialog->slave(), dialog->line());
        add(dialog->slave());
    });
    dialog->open();
    return dialog;
}

QAction* DriveLineDialog::addMenuAction(QMenu* menu, BusDrives* drives, int slave,
                                        std::function<void(int)> identify)
{
    QAction* action = menu->addAction(tr("Line &format…"));
    action->setObjectName(QStringLiteral("lineFormat"));
    const ModbusClient* client = drives->client();
    action->setToolTip(
        client->hasOwnLine(slave)
            ? tr("Machine number %1 talks %2, not the port's %3")
                  .arg(slave)
                  .arg(client->driveLine(slave).text(), client->settings().line().text())
            : tr("Machine number %1 talks the port's %2")
                  .arg(slave)
                  .arg(client->settings().line().text()));
    action->setEnabled(client->settings().kind != ConnectionSettings::Kind::Tcp);
    QWidget* parent = menu->parentWidget();
    connect(action, &QAction::triggered, parent, [parent, drives, slave, identify] {
        auto* dialog = new DriveLineDialog(drives->client()->settings(), slave,
                                           drives->client()->driveLine(slave),
                                           drives->info(slave).family, parent);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        connect(dialog, &QDialog::accepted, parent, [dialog, drives, slave, identify] {
            drives->setLine(slave, dialog->line());
            identify(slave);
        });
        dialog->open();
    });
    return action;
}

} // namespace opentop
