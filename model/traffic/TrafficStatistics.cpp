#include "model/traffic/TrafficStatistics.h"

#include "transport/ModbusCrc.h"
#include "transport/ModbusResult.h"

#include <QStringList>

#include <algorithm>

namespace opentop {

void TrafficStatistics::add(const TrafficEntry& entry)
{
    if (entry.direction == TrafficEntry::Direction::Tx) {
        m_lastRequestSlave = entry.slave;
        ++stats(entry.slave).requests;
        return;
    }
    if (entry.kind == TrafficEntry::Kind::Late) {
        // Late bytes may hold a whole frame (a reply to an earlier request) or debris.
        const bool frame = entry.bytes.size() >= 4 && ModbusCrc::check(entry.bytes) &&
                           quint8(entry.bytes.at(0)) != 0;
        ++stats(frame ? quint8(entry.bytes.at(0))
                      : (m_lastRequestSlave >= 0 ? m_lastRequestSlave : entry.slave))
              .late;
        return;
    }
    const int slave = m_lastRequestSlave >= 0 ? m_lastRequestSlave : entry.slave;
    DriveTrafficStats& s = stats(slave);
    if (entry.direction == TrafficEntry::Direction::Event) {
        // Events carry the error of a request that got no usable frame back.
        if (entry.error.startsWith(modbusErrorName(ModbusError::Timeout)))
            ++s.timeouts;
        return;
    }
    ++s.replies;
    if (entry.responseMs >= 0) {
        ++s.timedReplies;
        s.totalMs += entry.responseMs;
        s.maxMs = std::max(s.maxMs, entry.responseMs);
    }
    if (!entry.error.isEmpty()) {
        if (entry.error.startsWith(modbusErrorName(ModbusError::CrcError)))
            ++s.crcErrors;
        else
            ++s.garbled;
    } else if (entry.function & 0x80) {
        ++s.exceptions;
    }
}

void TrafficStatistics::clear()
{
    m_drives.clear();
    m_lastRequestSlave = -1;
}

QVector<int> TrafficStatistics::slaves() const
{
    return QVector<int>(m_drives.keyBegin(), m_drives.keyEnd());
}

QVector<int> TrafficStatistics::unanswered() const
{
    QVector<int> silent;
    for (const DriveTrafficStats& s : m_drives) {
        if (s.slave != 0 && s.requests > 0 && s.replies == 0)
            silent << s.slave;
    }
    return silent;
}

QString TrafficStatistics::rangesText(const QVector<int>& slaves)
{
    QStringList parts;
    for (int i = 0; i < slaves.size();) {
        int j = i;
        while (j + 1 < slaves.size() && slaves[j + 1] == slaves[j] + 1)
            ++j;
        parts << (j == i ? QString::number(slaves[i])
                         : QStringLiteral("%1–%2").arg(slaves[i]).arg(slaves[j]));
        i = j + 1;
    }
    return parts.join(QStringLiteral(", "));
}

DriveTrafficStats TrafficStatistics::drive(int slave) const
{
    DriveTrafficStats s = m_drives.value(slave);
    s.slave = slave;
    return s;
}

DriveTrafficStats TrafficStatistics::total() const
{
    DriveTrafficStats t;
    t.slave = -1;
    for (const DriveTrafficStats& s : m_drives) {
        t.requests += s.requests;
        t.replies += s.replies;
        t.timeouts += s.timeouts;
        t.crcErrors += s.crcErrors;
        t.exceptions += s.exceptions;
        t.garbled += s.garbled;
        t.late += s.late;
        t.timedReplies += s.timedReplies;
        t.totalMs += s.totalMs;
        t.maxMs = std::max(t.maxMs, s.maxMs);
    }
    return t;
}

DriveTrafficStats& TrafficStatistics::stats(int slave)
{
    DriveTrafficStats& s = m_drives[slave];
    s.slave = slave;
    return s;
}

} // namespace opentop
