#include "ui/eol/SerialEntry.h"

#include "model/profile/ProfileRegistry.h"
#include "model/station/EolStation.h"
#include "ui/eol/VerdictLook.h"
#include "ui/widgets/PlainText.h"

#include <QApplication>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

SerialEntry::SerialEntry(EolStation* station, std::function<ModbusClient*()> client,
                         TrafficLog* traffic, QWidget* parent)
    : QWidget(parent)
    , m_station(station)
    , m_client(std::move(client))
    , m_traffic(traffic)
{
    m_serial = new QLineEdit(this);
    m_serial->setObjectName(QStringLiteral("serialField"));
    m_serial->setFont(VerdictLook::scaled(font(), 2.2));
    m_serial->setPlaceholderText(tr("Scan or type the serial number, then Enter"));
    m_cancel = new QPushButton(tr("Cancel unit (Esc)"), this);
    m_cancel->setFont(VerdictLook::scaled(font(), 1.4, true));
    m_cancel->setEnabled(false);
    auto* serialRow = new QHBoxLayout;
    serialRow->addWidget(m_serial, 1);
    serialRow->addWidget(m_cancel);
    m_scanNote = new QLabel(this);
    m_scanNote->setObjectName(QStringLiteral("scanNote"));
    m_scanNote->setWordWrap(true);
    m_scanNote->setTextFormat(Qt::PlainText); // scanned serials
    m_scanNote->setFont(VerdictLook::scaled(font(), 1.3, true));
    m_scanNote->setStyleSheet(QStringLiteral("QLabel { color: #b3261e; }"));
    m_scanNote->hide();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(serialRow);
    layout->addWidget(m_scanNote);

    connect(m_serial, &QLineEdit::returnPressed, this, &SerialEntry::start);
    connect(m_cancel, &QPushButton::clicked, this, [this] { m_station->cancel(); });
}

void SerialEntry::unitStarted()
{
    m_cancel->setEnabled(true);
    m_scanNote->hide();
    m_serial->clear(); // stays open: a serial scanned now is refused aloud (start)
}

void SerialEntry::start()
{
    // Exactly as scanned: "SN1 " is refused (SerialRule), never quietly made into "SN1".
    const QString serial = m_serial->text();
    if (serial.trimmed().isEmpty())
        return;
    if (m_station->isRunning() || m_station->isStarting()) {
        refuseWhileTesting(serial);
        return;
    }
    // Refused before the operator is asked for per-unit values; the field keeps the text to
    // correct (EolStation::start() asks the same rule).
    const QString refused = m_station->serialProblem(serial);
    if (!refused.isEmpty()) {
        QApplication::beep();
        emit notStarted(tr("Serial number NOT taken: %1.").arg(refused));
        m_serial->selectAll();
        return;
    }
    QHash<int, QHash<QString, double>> typed;
    if (!askOperatorValues(&typed))
        return;
    QString error;
    if (!m_station->start(m_client(), m_traffic, serial, typed, &error)) {
        emit notStarted(error);
        return;
    }
    if (!m_station->isRunning()) { // it starts once the station's drives are safe
        emit waitingForSafety(serial);
        m_serial->clear();
        m_cancel->setEnabled(true);
    }
}

void SerialEntry::refuseWhileTesting(const QString& serial)
{
    const QString current =
        m_station->isRunning() ? m_station->run()->record().serial : m_station->startingSerial();
    QApplication::beep();
    // A serial no recipe takes is not repeated on the screen (its control characters) and not
    // worth scanning again: the rule says why.
    const QString refused = m_station->serialProblem(serial);
    m_scanNote->setText(
        refused.isEmpty()
            ? tr("Serial %1 was NOT taken: unit %2 is being tested. Scan it again once its "
                 "verdict shows.")
                  .arg(serial, current.isEmpty() ? tr("another") : current)
            : tr("A serial number was NOT taken: %1. Unit %2 is being tested.")
                  .arg(refused, current.isEmpty() ? tr("another") : current));
    m_scanNote->show();
    m_serial->clear();
}

bool SerialEntry::askOperatorValues(QHash<int, QHash<QString, double>>* typed)
{
    const Profile* profile = nullptr;
    for (const auto& [machineNumber, value] : m_station->operatorValues()) {
        for (const RecipePosition& p : m_station->recipe().positions)
            if (p.machineNumber == machineNumber)
                profile = ProfileRegistry::builtIn().family(p.family);
        const ParameterMeta* meta = profile ? profile->parameter(value.name) : nullptr;
        bool ok = false;
        // The name and unit may be the recipe's.
        const double v =
            QInputDialog::getDouble(this, tr("Per-unit value"),
                                    PlainText::asWritten(tr("Drive %1: %2 (%3–%4 %5)")
                                                             .arg(machineNumber)
                                                             .arg(meta ? meta->label : value.name)
                                                             .arg(value.min)
                                                             .arg(value.max)
                                                             .arg(value.unit)),
                                    value.min, value.min, value.max, 3, &ok);
        if (!ok)
            return false;
        (*typed)[machineNumber][value.name] = v;
    }
    return true;
}

} // namespace opentop
