#include "model/files/DriveBatchReader.h"

#include "model/session/DeviceSession.h"

#include <QTimer>

namespace opentop {

QStringList DriveBatchReader::Drive::problems() const
{
    QStringList lines;
    if (!attempted) {
        lines << tr("machine number %1: not read").arg(slave);
        return lines;
    }
    if (!error.isEmpty()) {
        lines << error;
        return lines;
    }
    const QString title = read.device.title();
    for (const QString& f : read.failures)
        lines << tr("%1: cannot read %2").arg(title, f);
    for (const QString& d : read.disallowed)
        lines << tr("%1 holds a value its profile does not allow, so the backup could not be "
                    "restored: %2")
                     .arg(title, d);
    return lines;
}

DriveBatchReader::DriveBatchReader(Sessions sessions, QObject* parent)
    : QObject(parent)
    , m_sessions(std::move(sessions))
{
}

void DriveBatchReader::start(const QVector<int>& slaves, const Options& options, Done done)
{
    m_slaves = slaves;
    m_options = options;
    m_drives.clear();
    m_cancel = false;
    m_done = std::move(done);
    // The first drive starts now, so that a cancel right after start() lets it finish; with
    // nothing to read, `done` still waits for the event loop.
    if (m_slaves.isEmpty())
        QTimer::singleShot(0, this, &DriveBatchReader::next);
    else
        next();
}

void DriveBatchReader::cancel()
{
    m_cancel = true; // the drive being read finishes: a half-read drive is worth nothing
}

void DriveBatchReader::finishDrive(const Drive& drive)
{
    m_drives << drive;
    emit driveFinished(drive);
    if (m_options.stopAtFailure && !drive.ok())
        m_cancel = true;
    QTimer::singleShot(0, this, &DriveBatchReader::next);
}

void DriveBatchReader::next()
{
    const int index = int(m_drives.size());
    if (index >= m_slaves.size() || m_cancel) {
        // Every drive not reached is reported, so that a cancelled read hides nothing.
        for (int i = index; i < m_slaves.size(); ++i) {
            Drive skipped;
            skipped.slave = m_slaves.at(i);
            m_drives << skipped;
            emit driveFinished(skipped);
        }
        auto done = std::move(m_done);
        m_done = nullptr;
        if (done)
            done(m_drives);
        return;
    }
    Drive drive;
    drive.slave = m_slaves.at(index);
    drive.attempted = true;
    emit driveStarted(drive.slave, index, int(m_slaves.size()));
    DeviceSession* session = m_sessions(drive.slave, &drive.error);
    if (!session) {
        if (drive.error.isEmpty())
            drive.error = tr("machine number %1 is not a drive on the bus").arg(drive.slave);
        finishDrive(drive);
        return;
    }
    auto read = [this, drive, session](const QString& error) mutable {
        if (!error.isEmpty()) {
            drive.error = error;
            finishDrive(drive);
            return;
        }
        m_reader = new BackupReader(session, this);
        m_reader->read([this, drive](const BackupReader::Result& r) mutable {
            m_reader->deleteLater();
            drive.read = r;
            finishDrive(drive);
        });
    };
    if (m_options.prepare)
        m_options.prepare(session, read);
    else
        read(QString());
}

} // namespace opentop
