#include "StackPoller.h"

#include "ModbusClient.h"
#include "profile/Profile.h"
#include "session/DeviceSession.h"
#include "session/ReadPlanner.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <functional>

namespace opentop {

QStringList StackPoller::fullBlock(const Profile& profile, int registers, int* address)
{
    QVector<const ParameterMeta*> readable;
    for (const ParameterMeta& p : profile.parameters) {
        if (p.isReadable())
            readable << &p;
    }
    for (const ReadBlockPlan& block : ReadPlanner::plan(profile, readable)) {
        if (block.count != registers)
            continue;
        QStringList names;
        for (const ParameterMeta* p : block.parameters)
            names << p->name;
        *address = block.address;
        return names;
    }
    return {};
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
