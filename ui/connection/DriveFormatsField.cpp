#include "ui/connection/DriveFormatsField.h"

#include "model/bus/LineFormatHint.h"
#include "model/profile/ProfileRegistry.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QSettings>
#include <QToolButton>

namespace opentop {

namespace {

const QString kKey = QStringLiteral("connection/driveFormats");

} // namespace

DriveFormatsField::DriveFormatsField(QWidget* page, QFormLayout* form)
    : QObject(page)
{
    auto* row = new QHBoxLayout;
    m_edit = new QLineEdit(page);
    m_edit->setObjectName(QStringLiteral("driveFormats"));
    m_edit->setPlaceholderText(tr("none: every drive at the port's format"));
    m_edit->setToolTip(
        tr("Drives set to another line format than the port's, e.g. 7=9600:8E1 or 7=8N2 (the "
           "baud rate may be left out): requests to them switch the line to their format and "
           "back between transactions. A DBU works only at 8N1; a DC controller at 8E1, 8O1 or "
           "8N2. The bus list's context menu sets them too."));
    m_help = new QToolButton(page);
    m_help->setObjectName(QStringLiteral("driveFormatsHelp"));
    m_help->setText(tr("&Mixed bus…"));
    m_help->setToolTip(tr("How a drive of another format joins this bus"));
    connect(m_help, &QToolButton::clicked, page, [page] {
        QMessageBox box(QMessageBox::Information, tr("Drives of different line formats"),
                        guidance(), QMessageBox::Ok, page);
        box.setObjectName(QStringLiteral("mixedBusGuidance"));
        box.exec();
    });
    row->addWidget(m_edit, 1);
    row->addWidget(m_help);
    // A row holding a layout gets no buddy from QFormLayout, and "&" would show.
    auto* label = new QLabel(tr("Drive f&ormats:"), page);
    label->setBuddy(m_edit);
    form->addRow(label, row);
}

void DriveFormatsField::setSettings(const ConnectionSettings& settings)
{
    m_edit->setText(LineFormat::tableText(settings.driveLines));
}

void DriveFormatsField::applyTo(ConnectionSettings* settings) const
{
    settings->driveLines =
        LineFormat::parseTable(m_edit->text(), settings->baud).value_or(QMap<int, LineFormat>());
}

QString DriveFormatsField::problem(int portBaud) const
{
    QString error;
    if (LineFormat::parseTable(m_edit->text(), portBaud, &error))
        return QString();
    return tr("Drive formats: %1").arg(error);
}

QString DriveFormatsField::guidance()
{
    QString text =
        tr("Every drive hears only frames sent in its own line format: a DBU works only at "
           "8N1 (19200 bit/s from the factory), a DC controller at 8E1 (9600 bit/s from the "
           "factory), 8O1 or 8N2. OpenTOP can talk to drives of different formats on one port: "
           "give each drive that is not at the port's format its own (Drive formats here, or "
           "Line format… in the bus list's context menu); the port is switched between "
           "transactions. To put all drives at one format for good, change the drives:");
    for (const Profile& p : ProfileRegistry::builtIn().profiles())
        if (!p.serial.formatHelp.isEmpty())
            text += QStringLiteral("\n\n") + LineFormatHint::asSteps(p.serial.formatHelp);
    return text;
}

void DriveFormatsField::recall(const QSettings& stored, ConnectionSettings* settings)
{
    settings->driveLines = LineFormat::parseTable(stored.value(kKey).toString(), settings->baud)
                               .value_or(QMap<int, LineFormat>());
}

void DriveFormatsField::remember(QSettings& stored, const ConnectionSettings& settings)
{
    stored.setValue(kKey, LineFormat::tableText(settings.driveLines));
}

} // namespace opentop
