#pragma once

// Helpers for the simulator tests: a bus on a manual clock, frames built and decoded by hand
// (independent of the transport's RtuFrame, so that both are checked against each other).

#include "sim/ManualSimClock.h"
#include "sim/SimBus.h"
#include "sim/SimDevice.h"
#include "transport/ModbusCrc.h"

#include <QByteArray>
#include <QLoggingCategory>
#include <QVector>
#include <gtest/gtest.h>
#include <memory>

namespace opentop::test {

// The simulator's frame and state trace is noise in test output; warnings stay on.
inline const bool kQuietSimulatorLog = [] {
    QLoggingCategory::setFilterRules(
        QStringLiteral("opentop.sim.debug=false\nopentop.sim.info=false"));
    return true;
}();

// What came back for one request.
struct Answer
{
    bool replied = false;
    quint8 exception = 0;    // 0 when the reply is a normal one
    QVector<quint16> values; // read replies
    QByteArray adu;

    bool ok() const { return replied && exception == 0; }
};

inline QByteArray hexBytes(const char* text)
{
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

inline QByteArray withCrc(const QByteArray& aduWithoutCrc)
{
    return ModbusCrc::append(aduWithoutCrc);
}

class SimFixture
{
public:
    explicit SimFixture(const char* spec)
        : clock(std::make_shared<ManualSimClock>(1000))
    {
        QString error;
        bus = SimBus::fromSpec(QString::fromLatin1(spec), &error, clock);
        EXPECT_TRUE(bus) << error.toStdString();
    }

    SimDevice* device(int slave) const { return bus->device(slave); }

    quint16 address(int slave, const char* name) const
    {
        const ParameterMeta* p = device(slave)->param(QString::fromLatin1(name));
        EXPECT_TRUE(p) << name;
        return p ? p->address : 0;
    }

    // The raw value of a parameter at the current time.
    double raw(int slave, const char* name) const
    {
        device(slave)->advance(clock->nowMs());
        return device(slave)->raw(QString::fromLatin1(name)).value_or(-1);
    }

    void advance(qint64 ms) { clock->advanceMs(ms); }

    Answer send(const QByteArray& aduWithCrc) const
    {
        Answer a;
        a.adu = bus->handleFrame(aduWithCrc, clock->nowMs()).reply;
        a.replied = !a.adu.isEmpty();
        if (!a.replied)
            return a;
        const quint8 function = quint8(a.adu.at(1));
        if (function & 0x80) {
            a.exception = quint8(a.adu.at(2));
        } else if ((function == 3 || function == 4) && a.adu.size() >= 5) {
            const int bytes = quint8(a.adu.at(2));
            for (int i = 0; i + 1 < bytes; i += 2)
                a.values << quint16((quint8(a.adu.at(3 + i)) << 8) | quint8(a.adu.at(4 + i)));
        }
        return a;
    }

    Answer read(int slave, int function, quint16 addr, quint16 count = 1) const
    {
        QByteArray adu;
        adu.append(char(slave)).append(char(function));
        appendWord(&adu, addr);
        appendWord(&adu, count);
        return send(withCrc(adu));
    }

    Answer write(int slave, quint16 addr, quint16 value) const
    {
        QByteArray adu;
        adu.append(char(slave)).append(char(6));
        appendWord(&adu, addr);
        appendWord(&adu, value);
        return send(withCrc(adu));
    }

    Answer writeMany(int slave, quint16 addr, const QVector<quint16>& values) const
    {
        QByteArray adu;
        adu.append(char(slave)).append(char(0x10));
        appendWord(&adu, addr);
        appendWord(&adu, quint16(values.size()));
        adu.append(char(values.size() * 2));
        for (quint16 v : values)
            appendWord(&adu, v);
        return send(withCrc(adu));
    }

    Answer write(int slave, const char* name, quint16 value) const
    {
        return write(slave, address(slave, name), value);
    }

    quint16 readOne(int slave, const char* name) const
    {
        const ParameterMeta* p = device(slave)->param(QString::fromLatin1(name));
        const Answer a = read(slave, p->readFunction, p->address, 1);
        EXPECT_TRUE(a.ok()) << name << " exception " << int(a.exception);
        return a.values.value(0);
    }

    static void appendWord(QByteArray* bytes, quint16 value)
    {
        bytes->append(char(value >> 8));
        bytes->append(char(value & 0xFF));
    }

    std::shared_ptr<ManualSimClock> clock;
    std::shared_ptr<SimBus> bus;
};

} // namespace opentop::test
