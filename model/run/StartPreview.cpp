#include "model/run/StartPreview.h"

#include "model/bus/BusDrives.h"
#include "model/bus/BusGroups.h"
#include "model/bus/DriveName.h"
#include "model/profile/RoleEvaluator.h"
#include "model/profile/RunningData.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceSession.h"

#include <QPointer>

namespace opentop {

struct StartPreview::Job
{
    Result result;
    std::optional<bool> commandedCcw;
    Done done;
    QVector<int> groupQueue;
    BusGroups groups;
};

StartPreview::StartPreview(BusDrives* drives, QObject* parent)
    : QObject(parent)
    , m_drives(drives)
{
}

void StartPreview::read(int slave, std::optional<bool> commandedCcw, Done done)
{
    auto job = std::make_shared<Job>();
    job->result.slave = slave;
    job->result.drive = DriveName::listed(slave, m_drives->name(slave));
    job->groups.setNames(m_drives->names());
    job->commandedCcw = commandedCcw;
    job->done = std::move(done);
    readSelection(job);
}

void StartPreview::readSelection(const std::shared_ptr<Job>& job)
{
    DeviceSession* session = m_drives->session(job->result.slave);
    const ParameterMeta* select =
        session ? RoleEvaluator::parameter(session->profile(), QStringLiteral("select")) : nullptr;
    if (!select || !select->isReadable()) {
        readGroups(job);
        return;
    }
    QPointer<StartPreview> self(this);
    const QString name = select->name;
    session->readMany({name}, [self, job, name, select](const DeviceSession::ReadManyOutcome& o) {
        if (!self)
            return;
        const DeviceSession::Outcome r = o.results.value(name);
        if (r.value.valid)
            job->result.spno = int(r.value.raw) + 1; // running data N is code N-1
        else
            job->result.unread << select->label;
        self->readSpno(job);
    });
}

void StartPreview::readSpno(const std::shared_ptr<Job>& job)
{
    DeviceSession* session = m_drives->session(job->result.slave);
    const int spno = job->result.spno;
    if (!session || spno == 0) {
        readGroups(job);
        return;
    }
    const Profile& profile = session->profile();
    QStringList names;
    for (const char* field : {"speed", "direction", "decel"}) {
        const QString n = RunningData::parameter(profile, spno, QLatin1String(field));
        if (!n.isEmpty() && profile.parameter(n)->isReadable())
            names << n;
    }
    if (names.isEmpty()) {
        readGroups(job);
        return;
    }
    QPointer<StartPreview> self(this);
    session->readMany(names, [self, job, session, spno](const DeviceSession::ReadManyOutcome& o) {
        if (!self)
            return;
        const Profile& prof = session->profile();
        std::optional<double> speed;
        std::optional<double> decel;
        for (auto it = o.results.cbegin(); it != o.results.cend(); ++it) {
            const ParameterMeta* meta = prof.parameter(it.key());
            QString field;
            RunningData::spnoOf(it.key(), &field);
            if (!meta || !it.value().value.valid) {
                if (meta)
                    job->result.unread << meta->label;
                continue;
            }
            const QString text = ValueCodec::format(*meta, it.value().value, session->context());
            if (field == QLatin1String("speed")) {
                job->result.speed = text;
                speed = it.value().value.number;
            } else if (field == QLatin1String("direction")) {
                job->result.direction = text;
            } else if (field == QLatin1String("decel")) {
                decel = it.value().value.number;
            }
        }
        if (job->commandedCcw) {
            job->result.direction = *job->commandedCcw ? tr("CCW") : tr("CW");
            job->result.directionFromCommand = true;
        }
        job->result.warning = RunningData::decelerationWarning(spno, speed, decel);
        self->readGroups(job);
    });
}

void StartPreview::readGroups(const std::shared_ptr<Job>& job)
{
    if (job->groupQueue.isEmpty() && !job->groups.contains(job->result.slave)) {
        // The first call: every known drive whose family has groups is asked.
        for (int s : m_drives->slaves()) {
            DeviceSession* session = m_drives->session(s);
            if (session && !BusGroups::groupParameter(session->profile()).isEmpty()) {
                job->groups.addDrive(s);
                job->groupQueue << s;
            }
        }
        job->groups.addDrive(job->result.slave);
    }
    if (job->groupQueue.isEmpty()) {
        job->result.alsoReaches = job->groups.childrenOf(job->result.slave);
        for (int child : job->result.alsoReaches)
            job->result.alsoReachesNames << DriveName::listed(child, m_drives->name(child));
        job->result.reach = job->groups.reachText(job->result.slave);
        readFollowers(job);
        return;
    }
    const int slave = job->groupQueue.takeFirst();
    DeviceSession* session = m_drives->session(slave);
    if (!session) { // removed meanwhile
        readGroups(job);
        return;
    }
    const QString name = BusGroups::groupParameter(session->profile());
    QPointer<StartPreview> self(this);
    session->readMany({name}, [self, job, slave, name](const DeviceSession::ReadManyOutcome& o) {
        if (!self)
            return;
        const DeviceSession::Outcome r = o.results.value(name);
        if (r.value.valid)
            job->groups.setGroupRaw(slave, qint64(r.value.raw));
        else if (slave != job->result.slave)
            job->result.unread << tr("communication group of %1").arg(slave);
        self->readGroups(job);
    });
}

void StartPreview::readFollowers(const std::shared_ptr<Job>& job)
{
    QVector<DeviceSession*> children;
    for (int child : job->result.alsoReaches)
        if (DeviceSession* session = m_drives->session(child))
            children << session;
    if (children.isEmpty()) {
        job->done(job->result);
        return;
    }
    QPointer<StartPreview> self(this);
    GroupFollowers::readBefore(children, [self, job](const QVector<GroupFollowers::Drive>& d) {
        if (!self)
            return;
        job->result.followers = d;
        job->done(job->result);
    });
}

QString StartPreview::Result::text() const
{
    QStringList lines;
    if (spno > 0) {
        QString what = tr("It runs with running data SPno%1").arg(spno);
        if (!speed.isEmpty())
            what += tr(" at %1").arg(speed);
        if (!direction.isEmpty())
            what += directionFromCommand
                        ? tr(", direction %1 (the direction command sent since)").arg(direction)
                        : tr(", direction %1").arg(direction);
        lines << what + QLatin1Char('.');
    } else {
        lines << tr("Which running data it runs with could not be read.");
    }
    if (!warning.isEmpty())
        lines << tr("Warning: %1").arg(warning);
    if (!alsoReaches.isEmpty())
        lines << tr("The start also reaches machine number(s) %1: %2.")
                     .arg(alsoReachesNames.isEmpty() ? BusGroups::listText(alsoReaches)
                                                     : alsoReachesNames.join(QStringLiteral(", ")),
                          reach);
    lines += GroupFollowers::beforeLines(followers);
    if (!unread.isEmpty())
        lines << tr("Not read: %1.").arg(unread.join(QStringLiteral(", ")));
    return lines.join(QLatin1Char('\n'));
}

} // namespace opentop

namespace opentop {

QString StartPreview::Result::named() const
{
    return drive.isEmpty() ? QString::number(slave) : drive;
}

QString StartPreview::Result::question(const QString& speedCommand) const
{
    QString text =
        speedCommand.isEmpty()
            ? tr("This starts the motor of machine number %1.").arg(named()) + QLatin1Char('\n') +
                  this->text()
            : tr("This sets the speed command of machine number %1 to %2: its motor runs.")
                  .arg(named())
                  .arg(speedCommand);
    text += QStringLiteral("\n\n") +
            tr("Make sure that nobody is near the machine and that it may move. STOP ALL stops "
               "every drive at any time.");
    if (alsoReaches.isEmpty())
        text += QStringLiteral("\n\n") + tr("You are asked once per drive while the program runs.");
    return text;
}

} // namespace opentop
