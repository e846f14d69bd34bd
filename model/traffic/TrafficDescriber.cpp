#include "model/traffic/TrafficDescriber.h"

#include "model/bus/BusDrives.h"
#include "model/bus/BusGroups.h"
#include "model/profile/Profile.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include "transport/ModbusRequest.h"

#include <QCoreApplication>
#include <QHash>
#include <QMutex>
#include <QMutexLocker>
#include <QStringList>

namespace opentop {

namespace {

constexpr int kMaxNames = 4; // names listed for a block read before "…"
// Modbus limits a read to 125 registers and a 0x10 write to 123; a frame asking more (a garbled
// one, or a hand-made raw request) reads or writes no parameter, and naming its registers one by
// one would cost up to 65535 profile look-ups per frame (found by tests/fuzz/FuzzTrafficLog).
constexpr int kMaxReadCount = 125;
constexpr int kMaxWriteCount = 123;

// The registers of a read reply (RTU or TCP ADU); empty when the bytes do not carry them.
QVector<quint16> replyRegisters(const TrafficEntry& entry, const ModbusRequest& request)
{
    const QByteArray& b = entry.bytes;
    for (int offset : {0, 6}) { // RTU: slave first; TCP: 6 bytes of MBAP header before it
        if (b.size() < offset + 3 || quint8(b[offset]) != request.slave ||
            quint8(b[offset + 1]) != request.function)
            continue;
        const int byteCount = quint8(b[offset + 2]);
        if (byteCount != 2 * request.count || b.size() < offset + 3 + byteCount)
            continue;
        QVector<quint16> registers;
        for (int i = 0; i < request.count; ++i)
            registers << quint16((quint8(b[offset + 3 + 2 * i]) << 8) |
                                 quint8(b[offset + 4 + 2 * i]));
        return registers;
    }
    return {};
}

// "name = value unit" when `registers` (starting at `first`) cover the parameter, else the name.
QString nameAndValue(const ParameterMeta& p, quint16 first, const QVector<quint16>& registers)
{
    const int start = int(p.address) - int(first);
    if (start < 0 || start + p.registerCount > registers.size())
        return p.name;
    const ParamValue value = ValueCodec::decode(p, registers.mid(start, p.registerCount));
    if (!value.valid)
        return p.name;
    return QStringLiteral("%1 = %2").arg(p.name, ValueCodec::format(p, value));
}

// The parameters a request touches, described with `registers` (values) when known.
QString parameterText(const Profile& profile, const ModbusRequest& request,
                      const QVector<quint16>& registers)
{
    const int count = request.function == ModbusRequest::WriteSingle ? 1 : request.count;
    if (count > (request.isRead() ? kMaxReadCount : kMaxWriteCount))
        return QString();
    QStringList names;
    const ParameterMeta* last = nullptr;
    bool more = false;
    for (int i = 0; i < count; ++i) {
        const ParameterMeta* p =
            profile.parameterAt(request.function, quint16(request.address + i));
        if (!p || p == last)
            continue;
        last = p;
        if (names.size() == kMaxNames) {
            more = true;
            break;
        }
        names << nameAndValue(*p, request.address, registers);
    }
    if (names.isEmpty())
        return QString();
    if (more)
        names << QStringLiteral("…");
    return names.join(QStringLiteral(", "));
}

} // namespace

struct TrafficDescriber::State
{
    ProfileLookup lookup;
    QMutex mutex; // guards profiles (BusDrives mode) and children
    QHash<int, const Profile*> profiles;
    QHash<int, QVector<int>> children; // group parent → its children
};

TrafficDescriber::TrafficDescriber(ProfileLookup lookup)
    : m_state(std::make_shared<State>())
{
    m_state->lookup = std::move(lookup);
}

TrafficDescriber::TrafficDescriber(BusDrives* drives, const ProfileRegistry& registry)
    : m_state(std::make_shared<State>())
{
    std::weak_ptr<State> weak = m_state;
    m_state->lookup = [weak](int slave) -> const Profile* {
        const std::shared_ptr<State> state = weak.lock();
        if (!state)
            return nullptr;
        QMutexLocker lock(&state->mutex);
        return state->profiles.value(slave);
    };
    const std::shared_ptr<State> state = m_state;
    const ProfileRegistry* reg = &registry;
    auto update = [state, drives, reg](int slave) {
        const Profile* profile =
            drives->contains(slave) ? reg->family(drives->info(slave).family) : nullptr;
        QMutexLocker lock(&state->mutex);
        if (profile)
            state->profiles.insert(slave, profile);
        else
            state->profiles.remove(slave);
    };
    for (int slave : drives->slaves())
        update(slave);
    QObject::connect(drives, &BusDrives::driveAdded, drives, update);
    QObject::connect(drives, &BusDrives::driveChanged, drives, update);
    QObject::connect(drives, &BusDrives::driveRemoved, drives, update);
}

void TrafficDescriber::setGroups(const BusGroups& groups)
{
    QHash<int, QVector<int>> children;
    for (int slave : groups.drives())
        if (const QVector<int> c = groups.childrenOf(slave); !c.isEmpty())
            children.insert(slave, c);
    QMutexLocker lock(&m_state->mutex);
    m_state->children = children;
}

QString TrafficDescriber::describe(const TrafficEntry& entry, const ModbusRequest* request) const
{
    const QString names = describeNames(entry, request);
    // Who else executes a write: nobody replies for them, so the frame alone does not say.
    QString reach;
    if (request && request->isWrite() && entry.direction == TrafficEntry::Direction::Tx) {
        if (request->isBroadcast()) {
            reach = QCoreApplication::translate("opentop::TrafficDescriber",
                                                "broadcast: every drive executes it");
        } else {
            QVector<int> children;
            {
                QMutexLocker lock(&m_state->mutex);
                children = m_state->children.value(request->slave);
            }
            if (!children.isEmpty())
                reach = QCoreApplication::translate("opentop::TrafficDescriber",
                                                    "to %1 (group parent: also %2)")
                            .arg(request->slave)
                            .arg(BusGroups::listText(children));
        }
    }
    if (reach.isEmpty())
        return names;
    return QStringLiteral("%1 — %2").arg(names.isEmpty() ? entry.summary : names, reach);
}

QString TrafficDescriber::describeNames(const TrafficEntry& entry,
                                        const ModbusRequest* request) const
{
    if (!request || request->raw || request->isBroadcast() || !m_state->lookup)
        return QString();
    if (!request->isRead() && !request->isWrite())
        return QString();
    const Profile* profile = m_state->lookup(request->slave);
    if (!profile)
        return QString();

    QVector<quint16> values;
    const bool exception = (entry.function & 0x80) != 0;
    if (request->isWrite() && entry.direction != TrafficEntry::Direction::Event)
        values = request->values; // the request carries them; an echo repeats them
    else if (entry.direction == TrafficEntry::Direction::Rx && entry.error.isEmpty() && !exception)
        values = replyRegisters(entry, *request);
    if (exception)
        values.clear();
    const QString names = parameterText(*profile, *request, values);
    if (names.isEmpty())
        return QString();
    if (entry.summary.isEmpty())
        return QStringLiteral("(%1)").arg(names);
    return QStringLiteral("%1 (%2)").arg(entry.summary, names);
}

TrafficLog::Describer TrafficDescriber::describer() const
{
    const TrafficDescriber copy = *this;
    return [copy](const TrafficEntry& entry, const ModbusRequest* request) {
        return copy.describe(entry, request);
    };
}

} // namespace opentop
