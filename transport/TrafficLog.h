#pragma once

#include "transport/TrafficEntry.h"

#include <QMutex>
#include <QObject>
#include <QVector>
#include <deque>
#include <functional>

namespace opentop {

struct ModbusRequest;

// Thread-safe record of every frame sent and received. Backends append from the worker thread;
// the GUI takes what is new with entriesAfter() a few times a second (a queued signal per frame
// woke the GUI thread a thousand times a second), the command line prints with a sink.
class TrafficLog : public QObject
{
    Q_OBJECT
public:
    // Adds meaning to a frame's summary (e.g. parameter names from a profile); set by the model.
    // Returns the summary to keep (typically entry.summary plus names); empty keeps it as is.
    // Runs on the appending thread, without the log's lock held.
    using Describer =
        std::function<QString(const TrafficEntry& entry, const ModbusRequest* request)>;

    explicit TrafficLog(int capacity = 20000, QObject* parent = nullptr);

    void append(TrafficEntry entry, const ModbusRequest* request = nullptr);
    QVector<TrafficEntry> entries() const;
    // The entries with a sequence number above `sequence`, oldest first (those still held).
    QVector<TrafficEntry> entriesAfter(quint64 sequence) const;
    void clear();
    int capacity() const { return m_capacity; }
    int size() const; // entries held now
    void setDescriber(Describer describer);
    // Called for every entry on the appending thread (e.g. --trace to stderr).
    void setSink(std::function<void(const TrafficEntry&)> sink);

signals:
    void entryAdded(const opentop::TrafficEntry& entry);

private:
    mutable QMutex m_mutex;
    std::deque<TrafficEntry> m_entries;
    int m_capacity;
    quint64 m_sequence = 0;
    Describer m_describer;
    std::function<void(const TrafficEntry&)> m_sink;
};

} // namespace opentop

Q_DECLARE_METATYPE(opentop::TrafficEntry)
