#pragma once

#include <QCoreApplication>
#include <QString>
#include <functional>

namespace opentop {

class DeviceSession;

// The communication-loss stop a drive supports (the "commLossTime" role: the DC controller),
// armed while a station's unit runs so that a killed station leaves no motor turning: the
// drive brakes by itself kSeconds after the station's last frame. Disarming writes back what
// the drive held (in its working memory only: the product's stored value is never changed).
class CommLossArm
{
    Q_DECLARE_TR_FUNCTIONS(opentop::CommLossArm)
public:
    // Long enough for a retried request on a busy bus (the station asks every drive every
    // ~100 ms).
    static constexpr double kSeconds = 2.0;

    explicit CommLossArm(DeviceSession* session);

    bool applies() const; // the family has the role
    // `done` with an empty string when armed, else why not (the motor is then not started).
    void arm(std::function<void(const QString& error)> done);
    // Back to the drive's own value when it was armed; `then` runs in any case.
    void disarm(std::function<void()> then);

private:
    DeviceSession* m_session;
    QString m_before; // the drive's own value while the station's is armed
};

} // namespace opentop
