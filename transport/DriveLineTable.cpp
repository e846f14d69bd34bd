#include "transport/DriveLineTable.h"

#include "transport/ModbusRequest.h"

#include <algorithm>

namespace opentop {

void DriveLineTable::reset(const LineFormat& port, const QMap<int, LineFormat>& lines)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_port = port;
    m_lines = lines;
}

void DriveLineTable::set(int slave, const LineFormat& format)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    if (format.isSet() && format != m_port)
        m_lines.insert(slave, format);
    else
        m_lines.remove(slave);
}

QVector<LineFormat> DriveLineTable::formatsFor(const ModbusRequest& request) const
{
    if (request.line.isSet())
        return {request.line};
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!request.isBroadcast())
        return {m_lines.value(request.slave)};
    // A broadcast reaches every drive only in a format it hears: the port's first (unset),
    // then each of the table's that none before reaches.
    QVector<LineFormat> formats{m_port};
    for (const LineFormat& f : m_lines)
        if (std::none_of(formats.begin(), formats.end(),
                         [&f](const LineFormat& r) { return f.hears(r); }))
            formats << f;
    formats.first() = LineFormat();
    return formats;
}

} // namespace opentop
