#include "sim/SimBus.h"

#include "model/bus/BusSpec.h"
#include "model/profile/ProfileRegistry.h"
#include "sim/DbuSimDevice.h"
#include "sim/DcPidSimDevice.h"
#include "sim/GenericSimDevice.h"
#include "sim/SimLog.h"
#include "sim/SteadySimClock.h"
#include "transport/ModbusCrc.h"
#include "transport/ModbusRequest.h"

namespace opentop {

namespace {

quint16 word(const QByteArray& bytes, int at)
{
    return quint16((quint8(bytes.at(at)) << 8) | quint8(bytes.at(at + 1)));
}

} // namespace

SimBus::SimBus(std::shared_ptr<SimClock> clock)
    : m_clock(clock ? std::move(clock) : std::make_shared<SteadySimClock>())
{
}

SimBus::~SimBus() = default;

std::unique_ptr<SimDevice> SimBus::createDevice(const QString& type, int slave, QString* error)
{
    QString variant;
    const Profile* profile = ProfileRegistry::builtIn().forDeviceType(type, &variant);
    if (!profile) {
        if (error)
            *error =
                tr("unknown device type '%1'; known: %2")
                    .arg(type, ProfileRegistry::builtIn().deviceTypes().join(QStringLiteral(", ")));
        return nullptr;
    }
    if (variant.isEmpty() && !profile->variants.isEmpty())
        variant = profile->variants.first().id;
    if (profile->family == QLatin1String("dbu"))
        return std::make_unique<DbuSimDevice>(*profile, variant, slave);
    if (profile->family == QLatin1String("dcpid"))
        return std::make_unique<DcPidSimDevice>(*profile, variant, slave);
    return std::make_unique<GenericSimDevice>(*profile, variant, slave);
}

std::shared_ptr<SimBus> SimBus::fromSpec(const QString& spec, QString* error,
                                         std::shared_ptr<SimClock> clock)
{
    const std::optional<QVector<BusSpecEntry>> entries = BusSpec::parse(spec, error);
    if (!entries)
        return nullptr;
    auto bus = std::make_shared<SimBus>(std::move(clock));
    for (const BusSpecEntry& e : *entries) {
        std::unique_ptr<SimDevice> device = createDevice(e.type, e.slave, error);
        if (!device || !bus->addDevice(std::move(device), error))
            return nullptr;
        QString items = e.defects;
        QString why;
        if (!takeLineItems(*bus, e.slave, &items, &why)) {
            if (error)
                *error = tr("%1@%2{%3}: %4").arg(e.type).arg(e.slave).arg(e.defects, why);
            return nullptr;
        }
        if (!items.isEmpty()) {
            SimDevice* added = bus->device(e.slave);
            const std::optional<SimDefectSpec> defects = SimDefectSpec::parse(items, &why);
            if (!defects || !added->addDefects(*defects, &why)) {
                if (error)
                    *error = tr("%1@%2{%3}: %4").arg(e.type).arg(e.slave).arg(e.defects, why);
                return nullptr;
            }
        }
    }
    return bus;
}

bool SimBus::takeLineItems(SimBus& bus, int slave, QString* items, QString* error)
{
    QString format;
    QString baud;
    QStringList rest;
    for (const QString& raw : items->split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString item = raw.trimmed();
        if (item.startsWith(QLatin1String("format="), Qt::CaseInsensitive))
            format = item.mid(7).trimmed();
        else if (item.startsWith(QLatin1String("baud="), Qt::CaseInsensitive))
            baud = item.mid(5).trimmed();
        else
            rest << item;
    }
    *items = rest.join(QLatin1Char(','));
    if (format.isEmpty() && baud.isEmpty())
        return true;
    return bus.setOwnLine(slave, format, baud, error);
}

bool SimBus::setOwnLine(int slave, const QString& format, const QString& baud, QString* error)
{
    QMutexLocker lock(&m_mutex);
    SimDevice* d = device(slave);
    if (!d) {
        *error = tr("no device with machine number %1").arg(slave);
        return false;
    }
    const SerialDefaults& serial = d->profile().serial;
    bool ok = true;
    const int rate = baud.isEmpty() ? serial.baud : baud.toInt(&ok);
    if (!ok || (!serial.bauds.isEmpty() && !serial.bauds.contains(rate))) {
        QStringList rates;
        for (int b : serial.bauds)
            rates << QString::number(b);
        *error =
            tr("baud=%1: this drive talks at %2 bit/s").arg(baud, rates.join(QStringLiteral(", ")));
        return false;
    }
    const std::optional<LineFormat> wanted =
        LineFormat::parse(format.isEmpty() ? serial.formats.value(0) : format, rate, error);
    if (!wanted)
        return false;
    if (!serial.formats.contains(wanted->frameText())) {
        *error = tr("format=%1: this drive offers %2 only")
                     .arg(format, serial.formats.join(QStringLiteral(", ")));
        return false;
    }
    d->configureLine(wanted->baud, wanted->parity);
    if (d->lineFormat() != *wanted) {
        *error = tr("this simulated drive has no line settings of its own");
        return false;
    }
    m_ownLine.insert(slave);
    return true;
}

bool SimBus::addDevice(std::unique_ptr<SimDevice> device, QString* error)
{
    QMutexLocker lock(&m_mutex);
    const int slave = device->slave();
    if (slave < 1 || slave > 247 || m_devices.count(slave)) {
        if (error)
            *error = slave < 1 || slave > 247 ? tr("machine number %1 is outside 1..247").arg(slave)
                                              : tr("machine number %1 is used twice").arg(slave);
        return false;
    }
    if (m_lineBaud)
        device->configureLine(m_lineBaud, m_lineParity);
    m_devices[slave] = std::move(device);
    return true;
}

SimDevice* SimBus::device(int slave) const
{
    const auto it = m_devices.find(slave);
    return it == m_devices.end() ? nullptr : it->second.get();
}

QList<SimDevice*> SimBus::devices() const
{
    QList<SimDevice*> list;
    for (const auto& [slave, device] : m_devices)
        list << device.get();
    return list;
}

QString SimBus::spec() const
{
    QVector<BusSpecEntry> entries;
    for (const auto& [slave, device] : m_devices) {
        const LineFormat own = device->lineFormat();
        entries << BusSpecEntry{
            device->type(), slave,
            m_ownLine.contains(slave)
                ? QStringLiteral("format=%1,baud=%2").arg(own.frameText()).arg(own.baud)
                : QString()};
    }
    return BusSpec::toString(entries);
}

void SimBus::setFaults(const FaultInjector& faults)
{
    QMutexLocker lock(&m_mutex);
    m_faults = faults;
}

void SimBus::setLine(int baud, char parity)
{
    QMutexLocker lock(&m_mutex);
    m_lineBaud = baud;
    m_lineParity = parity;
    for (const auto& [slave, device] : m_devices)
        if (!m_ownLine.contains(slave))
            device->configureLine(baud, parity);
}

bool SimBus::hears(const SimDevice& device, const LineFormat& sent) const
{
    const LineFormat own = device.lineFormat();
    // On a bus whose line was never set (in process), a device without settings of its own
    // was configured to whatever the master uses.
    if (!sent.isSet() || !own.isSet() || (!m_lineBaud && !m_ownLine.contains(device.slave())))
        return true;
    return own.hears(sent);
}

bool SimBus::decodeRequest(const QByteArray& adu, ModbusRequest* request)
{
    if (adu.size() < 4)
        return false;
    *request = ModbusRequest();
    request->slave = quint8(adu.at(0));
    request->function = quint8(adu.at(1));
    request->rawData = adu.mid(2, adu.size() - 4);
    const QByteArray& d = request->rawData;
    switch (request->function) {
    case ModbusRequest::ReadHolding:
    case ModbusRequest::ReadInput:
        if (d.size() >= 4) {
            request->address = word(d, 0);
            request->count = word(d, 2);
        }
        break;
    case ModbusRequest::WriteSingle:
        if (d.size() >= 4) {
            request->address = word(d, 0);
            request->count = 1;
            request->values = {word(d, 2)};
        }
        break;
    case ModbusRequest::WriteMultiple:
        if (d.size() >= 5) {
            request->address = word(d, 0);
            request->count = word(d, 2);
            for (int at = 5; at + 1 < d.size(); at += 2)
                request->values << word(d, at);
        }
        break;
    default:
        request->raw = true;
        break;
    }
    return true;
}

SimOutcome SimBus::handleFrame(const QByteArray& requestAdu, qint64 nowMs, const LineFormat& line)
{
    QMutexLocker lock(&m_mutex);
    SimOutcome out;
    ModbusRequest request;
    if (requestAdu.size() < 4 || !ModbusCrc::check(requestAdu) ||
        !decodeRequest(requestAdu, &request)) {
        qCDebug(lcSim) << "ignoring frame with a bad CRC" << requestAdu.toHex(' ');
        return out;
    }
    const LineFormat sent =
        line.isSet() || !m_lineBaud ? line : LineFormat{m_lineBaud, m_lineParity, 8, 1};
    const bool write = request.function == ModbusRequest::WriteSingle ||
                       request.function == ModbusRequest::WriteMultiple;
    for (const auto& [slave, device] : m_devices) {
        const bool direct = request.slave != 0 && slave == request.slave;
        const bool broadcast = request.slave == 0 && device->profile().supportsBroadcast;
        const bool groupCopy = request.slave != 0 && !direct && write &&
                               device->profile().supportsGroups &&
                               device->groupAddress() == int(request.slave);
        if (!direct && !broadcast && !groupCopy)
            continue;
        if (!hears(*device, sent)) {
            // Framing or parity errors for this device: noise, never an answer.
            qCInfo(lcSim).noquote()
                << QStringLiteral("%1@%2 talks %3: a frame at %4 is noise to it")
                       .arg(device->type())
                       .arg(slave)
                       .arg(device->lineFormat().text(), sent.text());
            continue;
        }
        if (direct && m_faults.isActive()) {
            out.fault = m_faults.next();
            if (out.fault == FaultInjector::Fault::Busy) {
                out.reply = device->busyReply(request, nowMs);
                continue;
            }
        }
        const QByteArray reply = device->handle(request, nowMs, direct);
        if (direct) {
            out.reply = reply;
            out.turnaroundMs = device->defects().turnaroundMs.value_or(-1.0);
        }
    }
    switch (out.fault) {
    case FaultInjector::Fault::Drop:
        out.reply.clear();
        break;
    case FaultInjector::Fault::Crc:
        if (!out.reply.isEmpty())
            out.reply[out.reply.size() - 1] = char(out.reply.at(out.reply.size() - 1) ^ 0x5A);
        break;
    case FaultInjector::Fault::Late:
        out.delayMs = m_faults.lateMs();
        break;
    default:
        break;
    }
    if (out.fault != FaultInjector::Fault::None)
        qCInfo(lcSim) << "fault" << FaultInjector::faultName(out.fault) << "on"
                      << requestAdu.toHex(' ');
    return out;
}

SimControlResult SimBus::control(int slave, const QStringList& args)
{
    QMutexLocker lock(&m_mutex);
    SimDevice* d = device(slave);
    if (!d)
        return {false, tr("no device with machine number %1 (bus: %2)").arg(slave).arg(spec())};
    return d->control(args, nowMs());
}

} // namespace opentop
