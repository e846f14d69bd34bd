#pragma once

#include "transport/LineFormat.h"

#include <QMap>
#include <QVector>
#include <mutex>

namespace opentop {

struct ModbusRequest;

// The bus worker's copy of the drives that talk another format than the port's
// (ConnectionSettings::driveLines), and the formats a request goes out in. Any thread: the
// client sets it, the worker reads it before each transaction.
class DriveLineTable
{
public:
    void reset(const LineFormat& port, const QMap<int, LineFormat>& lines);
    // An unset format, or the port's, removes the drive's entry.
    void set(int slave, const LineFormat& format);
    // Each format the request goes out in: its own, else the drive's entry (unset: the
    // port's); a broadcast goes out in every format of the table.
    QVector<LineFormat> formatsFor(const ModbusRequest& request) const;

private:
    mutable std::mutex m_mutex;
    LineFormat m_port;
    QMap<int, LineFormat> m_lines;
};

} // namespace opentop
