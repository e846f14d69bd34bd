#pragma once

#include "model/session/DeviceSession.h"
#include "model/session/ReachedResult.h"

#include <QCoreApplication>
#include <QPointer>
#include <QStringList>
#include <QVector>
#include <functional>

namespace opentop {

// A write's other drives: those that execute every frame sent to its target without replying
// (communication group children, GroupReach). Before the frame is built each of them validates
// the value by its own profile, variant and values (ValueCodec, DependentValues; a drive whose
// variant is not known must allow it for every variant of its family); after the target
// acknowledged it, each is read back and compared. DeviceSession::write does both, so no page,
// dialog or command writes around it. Reads go out with the target's session as their context:
// a reached drive removed meanwhile cannot leave the write unfinished.
class ReachedDrives
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ReachedDrives)
public:
    using Result = ReachedResult;

    ReachedDrives(DeviceSession* target, const QVector<DeviceSession*>& drives);

    bool isEmpty() const { return m_drives.isEmpty(); }
    QVector<int> slaves() const;

    // Why a reached drive would refuse `registers` written to the target's `meta`, naming the
    // drive, its model and what it allows; empty when every one allows them. Uses each drive's
    // values as known. `dependents` (after ensureKnown): also the settings that depend on this
    // one (DependentValues), except `companions` written in the same operation, and a value
    // whose allowed set is not known refuses; without it, only what is known is checked.
    QString problem(const ParameterMeta& meta, const QVector<quint16>& registers,
                    const QStringList& companions, bool dependents) const;
    // Reads on each reached drive what its allowed values of `metas` depend on and the settings
    // that depend on them (except `companions`) that it does not know yet; `then` gets the
    // first failure, or nothing.
    void ensureKnown(const QVector<const ParameterMeta*>& metas, const QStringList& companions,
                     std::function<void(const QString& problem)> then) const;
    // Before a write: ensureKnown, then problem(); `then` gets the refusal, or nothing (at once
    // when nothing else is reached).
    void check(const ParameterMeta& meta, const QVector<quint16>& registers,
               const QStringList& companions,
               std::function<void(const QString& refusal)> then) const;
    // `done` of a write, after the drives it reached have been read back: verified only when
    // every one holds the value; one holding another value fails the write (mismatch), one that
    // cannot be read leaves it not verified (Outcome::notVerified). A command is not read back.
    DeviceSession::Done verifying(const ParameterMeta* meta, const QVector<quint16>& registers,
                                  DeviceSession::Done done) const;
    // Reads `meta` back from each reached drive and compares it with `registers`, the value the
    // target acknowledged; `done` gets one result per drive, ascending.
    void verify(const ParameterMeta& meta, const QVector<quint16>& registers,
                std::function<void(const QVector<Result>&)> done) const;

private:
    struct Read
    {
        QPointer<DeviceSession> drive;
        QString name;
    };
    static void readNext(QPointer<DeviceSession> context, QVector<Read> queue,
                         std::function<void(const QString& problem)> then);
    // The drive's own setting at the address `meta` is written to, or nullptr.
    static const ParameterMeta* counterpart(const DeviceSession& drive, const ParameterMeta& meta);
    // "DBU400-D4"; the family's name and "variant not known" without a variant.
    static QString modelOf(const DeviceSession& drive);

    QPointer<DeviceSession> m_target;
    QVector<QPointer<DeviceSession>> m_drives;
};

} // namespace opentop
