#include "sim/SimBackdoor.h"

#include "sim/SimDevice.h"

namespace opentop {

SimBackdoor::SimBackdoor(SimDevice* device)
    : m_device(device)
{
}

SimControlResult SimBackdoor::getSet(const QStringList& args)
{
    const bool set = args.first() == QLatin1String("set");
    const int needed = set ? 3 : 2;
    if (args.size() < needed || args.size() > needed + 1)
        return SimDevice::fail(set ? tr("usage: set ID ADDR VALUE [fc]")
                                   : tr("usage: get ID ADDR [fc]"));
    const std::optional<qint64> address = SimDevice::parseNumber(args.at(1));
    if (!address || *address < 0 || *address > 0xFFFF)
        return SimDevice::fail(tr("address must be 0..0xFFFF, got '%1'").arg(args.at(1)));
    int function = 0;
    if (args.size() == needed + 1) {
        const std::optional<qint64> fc = SimDevice::parseNumber(args.at(needed));
        if (!fc || (*fc != 3 && *fc != 4 && *fc != 6))
            return SimDevice::fail(
                tr("function must be 3, 4 or 6 (write-only), got '%1'").arg(args.at(needed)));
        function = int(*fc);
    } else {
        const quint16 a = quint16(*address);
        function = m_device->memory().readable(3, a)   ? 3
                   : m_device->memory().readable(4, a) ? 4
                   : m_device->memory().writable(a)    ? 6
                                                       : 3;
    }
    const quint16 a = quint16(*address);
    if (set) {
        const std::optional<qint64> value = SimDevice::parseNumber(args.at(2));
        if (!value || *value < -32768 || *value > 0xFFFF)
            return SimDevice::fail(tr("value must be -32768..65535, got '%1'").arg(args.at(2)));
        m_device->setReg(quint8(function), a, quint16(*value));
    }
    const quint16 v = m_device->reg(quint8(function), a);
    return {true, QStringLiteral("0x%1 = %2 (0x%3) fc %4")
                      .arg(a, 4, 16, QLatin1Char('0'))
                      .arg(v)
                      .arg(v, 4, 16, QLatin1Char('0'))
                      .arg(function)};
}

} // namespace opentop
