#include "ui/files/BackupDialog.h"

#include "model/bus/BusDrives.h"
#include "model/files/BackupFile.h"
#include "model/files/DriveBatchReader.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "ui/bus/VariantQuestion.h"
#include "ui/widgets/ClearOfStopAll.h"

#include <QDateTime>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace opentop {

BackupDialog::BackupDialog(BusDrives* drives, const ConnectionSettings& connection, QWidget* parent)
    : QDialog(parent)
    , m_drives(drives)
    , m_connection(connection)
    , m_table(new QTableWidget(0, ColumnCount))
    , m_total(new QProgressBar)
    , m_message(new QLabel)
    , m_cancelButton(new QPushButton(tr("&Cancel")))
    , m_saveRead(new QPushButton(tr("&Save the drives read")))
    , m_close(new QPushButton(tr("C&lose")))
{
    m_reader = new DriveBatchReader(
        [this](int slave, QString* error) -> DeviceSession* {
            DeviceSession* session = m_drives ? m_drives->session(slave) : nullptr;
            if (!session)
                *error = tr("drive %1: not identified, nothing read").arg(slave);
            return session;
        },
        this);
    connect(m_reader, &DriveBatchReader::driveStarted, this,
            [this](int slave, int, int) { driveStarted(slave); });
    connect(m_reader, &DriveBatchReader::driveFinished, this, &BackupDialog::driveFinished);
    setWindowTitle(tr("Back up drives"));
    m_table->setHorizontalHeaderLabels(
        {tr("Machine number"), tr("Model"), tr("Progress"), tr("Result")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText); // paths, drives' names, errors
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_saveRead->setToolTip(tr("Save only the drives that were read; the others are left out"));
    m_saveRead->setEnabled(false);
    m_cancelButton->setToolTip(tr("Stop after the drive being read"));

    auto* buttons = new QHBoxLayout;
    buttons->addStretch();
    buttons->addWidget(m_saveRead);
    buttons->addWidget(m_cancelButton);
    buttons->addWidget(m_close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(m_total);
    layout->addWidget(m_message);
    layout->addLayout(buttons);
    resize(640, 360);
    ClearOfStopAll::keep(this);

    connect(m_cancelButton, &QPushButton::clicked, this, &BackupDialog::cancel);
    connect(m_saveRead, &QPushButton::clicked, this, &BackupDialog::saveReadDrives);
    connect(m_close, &QPushButton::clicked, this, &BackupDialog::reject);
}

void BackupDialog::startBackup(const QVector<int>& slaves, const QString& path)
{
    if (m_running)
        return;
    // The file records each drive's variant: a drive that does not report it is asked now.
    if (const QString stop =
            VariantQuestion::ensureEach(this, m_drives, slaves, VariantNeed::Purpose::Backup);
        !stop.isEmpty()) {
        showMessage(tr("Nothing was read: %1.").arg(stop), true);
        return;
    }
    m_slaves = slaves;
    m_path = path;
    m_read.clear();
    m_failed.clear();
    m_problems.clear();
    m_saved = false;
    m_running = true;
    m_saveRead->setEnabled(false);
    m_cancelButton->setEnabled(true);
    m_table->setRowCount(int(slaves.size()));
    for (int row = 0; row < slaves.size(); ++row) {
        const int slave = slaves.at(row);
        const DeviceInfo info = m_drives ? m_drives->info(slave) : DeviceInfo();
        m_table->setItem(row, MachineNumber, new QTableWidgetItem(QString::number(slave)));
        m_table->setItem(row, Model, new QTableWidgetItem(info.model));
        auto* bar = new QProgressBar;
        bar->setRange(0, 1);
        bar->setValue(0);
        bar->setTextVisible(false);
        m_table->setCellWidget(row, Progress, bar);
        m_table->setItem(row, Result, new QTableWidgetItem(tr("Waiting")));
    }
    m_total->setRange(0, int(slaves.size()));
    m_total->setValue(0);
    m_total->setFormat(tr("%v of %m drives"));
    showMessage(tr("Reading the settings of %n drive(s)…", nullptr, int(slaves.size())), false);
    m_reader->start(slaves, {},
                    [this](const QVector<DriveBatchReader::Drive>&) { finishReading(); });
}

void BackupDialog::cancel()
{
    if (!m_running)
        return;
    m_reader->cancel();
    m_cancelButton->setEnabled(false);
    showMessage(tr("Stopping after the drive being read…"), false);
}

void BackupDialog::reject()
{
    if (m_running)
        cancel();
    else
        QDialog::reject();
}

void BackupDialog::driveStarted(int slave)
{
    const int row = rowOf(slave);
    if (auto* bar = qobject_cast<QProgressBar*>(m_table->cellWidget(row, Progress)))
        bar->setRange(0, 0); // busy: the reader reports no steps
    setResult(slave, tr("Reading…"), false);
}

void BackupDialog::driveFinished(const DriveBatchReader::Drive& drive)
{
    const int slave = drive.slave;
    if (auto* bar = qobject_cast<QProgressBar*>(m_table->cellWidget(rowOf(slave), Progress))) {
        bar->setRange(0, 1);
        bar->setValue(drive.ok() ? 1 : 0);
    }
    m_total->setValue(m_total->value() + 1);
    if (drive.ok()) {
        m_read << drive.read.device;
        setResult(slave,
                  tr("%n setting(s) read in %1 ms", nullptr, drive.read.parameters)
                      .arg(drive.read.elapsedMs),
                  false);
        return;
    }
    m_failed << slave;
    // Every drive not reached is reported, so that a cancelled backup hides nothing.
    if (!drive.attempted) {
        setResult(slave, tr("Not read (cancelled)"), true);
        return;
    }
    m_problems << drive.problems();
    setResult(slave,
              !drive.error.isEmpty()          ? tr("Not identified")
              : drive.read.failures.isEmpty() ? tr("Value not allowed")
                                              : tr("Read failed"),
              true);
}

void BackupDialog::finishReading()
{
    m_running = false;
    m_cancelButton->setEnabled(false);
    emit readFinished();
    if (m_failed.isEmpty()) {
        emit backupFinished(save());
        return;
    }
    QStringList names;
    for (int slave : m_failed)
        names << QString::number(slave);
    QString text = tr("Not read: drive(s) %1. Nothing has been saved yet.")
                       .arg(names.join(QStringLiteral(", ")));
    if (!m_problems.isEmpty())
        text += QLatin1Char('\n') + m_problems.join(QLatin1Char('\n'));
    if (!m_read.isEmpty())
        text += QLatin1Char('\n') +
                tr("Save the %n drive(s) that were read?", nullptr, int(m_read.size()));
    showMessage(text, true);
    m_saveRead->setEnabled(!m_read.isEmpty());
    emit backupFinished(false);
}

bool BackupDialog::saveReadDrives()
{
    if (m_running || m_read.isEmpty())
        return false;
    m_saveRead->setEnabled(false);
    return save();
}

bool BackupDialog::save()
{
    BackupFile file;
    file.tool = BackupFile::toolName();
    file.created = QDateTime::currentDateTimeUtc();
    file.connection = BackupFile::connectionOf(m_connection);
    file.devices = m_read;
    QString error;
    m_saved = file.save(m_path, ProfileRegistry::builtIn(), &error);
    if (m_saved) {
        QString text = tr("Saved %n drive(s) to %1.", nullptr, int(m_read.size())).arg(m_path);
        if (!m_failed.isEmpty()) {
            QStringList names;
            for (int slave : m_failed)
                names << QString::number(slave);
            text += QLatin1Char(' ') +
                    tr("Left out (not read): drive(s) %1.").arg(names.join(QStringLiteral(", ")));
        }
        showMessage(text, false);
    } else {
        showMessage(tr("Could not save %1: %2").arg(m_path, error), true);
    }
    return m_saved;
}

QVector<int> BackupDialog::notRead() const
{
    return m_failed;
}

QVector<int> BackupDialog::readSlaves() const
{
    QVector<int> slaves;
    for (const BackupDevice& d : m_read)
        slaves << d.slave;
    return slaves;
}

QString BackupDialog::message() const
{
    return m_message->text();
}

QString BackupDialog::cellText(int slave, Column column) const
{
    const QTableWidgetItem* item = m_table->item(rowOf(slave), column);
    return item ? item->text() : QString();
}

int BackupDialog::rowOf(int slave) const
{
    return int(m_slaves.indexOf(slave));
}

void BackupDialog::setResult(int slave, const QString& text, bool error)
{
    QTableWidgetItem* item = m_table->item(rowOf(slave), Result);
    if (!item)
        return;
    item->setText(text);
    item->setForeground(error ? QColor(Qt::red) : palette().color(QPalette::Text));
}

void BackupDialog::showMessage(const QString& text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("color: #c00000;") : QString());
}

} // namespace opentop
