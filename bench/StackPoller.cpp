#include "bench/StackPoller.h"

#include "model/files/BackupReader.h"
#include "model/profile/Profile.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <functional>

namespace opentop {

QStringList StackPoller::backupSettings(const Profile& profile, QVector<ReadBlockPlan>* blocks)
{
    const QStringList names = BackupReader::settingNames(profile);
    QVector<const ParameterMeta*> metas;
    for (const QString& name : names)
        metas << profile.parameter(name);
    *blocks = ReadPlanner::plan(profile, metas);
    return names;
}

StackPoller::Result StackPoller::run(ModbusClient* client, const Profile& profile, int slave,
                                     const QStringList& names, double seconds)
{
    DeviceSession session(client, profile, slave, QString());
    Result result;
    QElapsedTimer timer;
    timer.start();
    bool counting = false;
    QEventLoop loop;
    std::function<void()> next;
    next = [&] {
        session.readMany(names, [&](const DeviceSession::ReadManyOutcome& outcome) {
            // The first 0.3 s warm up (thread start, first-exchange checks) and are not counted.
            if (!counting && timer.elapsed() >= 300) {
                counting = true;
                timer.restart();
            } else if (counting) {
                result.transactions += outcome.requests;
                result.failures += outcome.failed;
            }
            if (counting && double(timer.nsecsElapsed()) / 1e9 >= seconds) {
                result.seconds = double(timer.nsecsElapsed()) / 1e9;
                loop.quit();
                return;
            }
            next();
        });
    };
    next();
    QTimer::singleShot(int(seconds * 1000) + 30000, &loop, &QEventLoop::quit);
    loop.exec();
    return result;
}

} // namespace opentop
