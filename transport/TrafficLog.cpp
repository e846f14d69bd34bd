#include "transport/TrafficLog.h"

#include "transport/ModbusRequest.h"

#include <QMutexLocker>
#include <iterator>

namespace opentop {

TrafficLog::TrafficLog(int capacity, QObject* parent)
    : QObject(parent)
    , m_capacity(capacity > 0 ? capacity : 1)
{
    qRegisterMetaType<opentop::TrafficEntry>("opentop::TrafficEntry");
}

void TrafficLog::append(TrafficEntry entry, const ModbusRequest* request)
{
    if (!entry.time.isValid())
        entry.time = QDateTime::currentDateTime();
    Describer describer;
    {
        QMutexLocker lock(&m_mutex);
        describer = m_describer;
    }
    // The describer may look things up in a profile: run it without holding the lock.
    if (describer) {
        const QString described = describer(entry, request);
        if (!described.isEmpty())
            entry.summary = described;
    }
    std::function<void(const TrafficEntry&)> sink;
    {
        QMutexLocker lock(&m_mutex);
        entry.sequence = ++m_sequence;
        m_entries.push_back(entry);
        while (int(m_entries.size()) > m_capacity)
            m_entries.pop_front();
        sink = m_sink;
    }
    if (sink)
        sink(entry);
    emit entryAdded(entry);
}

QVector<TrafficEntry> TrafficLog::entries() const
{
    QMutexLocker lock(&m_mutex);
    return QVector<TrafficEntry>(m_entries.begin(), m_entries.end());
}

QVector<TrafficEntry> TrafficLog::entriesAfter(quint64 sequence) const
{
    QMutexLocker lock(&m_mutex);
    auto first = m_entries.end();
    while (first != m_entries.begin() && std::prev(first)->sequence > sequence)
        --first;
    return QVector<TrafficEntry>(first, m_entries.end());
}

int TrafficLog::size() const
{
    QMutexLocker lock(&m_mutex);
    return int(m_entries.size());
}

void TrafficLog::clear()
{
    QMutexLocker lock(&m_mutex);
    m_entries.clear();
}

void TrafficLog::setDescriber(Describer describer)
{
    QMutexLocker lock(&m_mutex);
    m_describer = std::move(describer);
}

void TrafficLog::setSink(std::function<void(const TrafficEntry&)> sink)
{
    QMutexLocker lock(&m_mutex);
    m_sink = std::move(sink);
}

} // namespace opentop
