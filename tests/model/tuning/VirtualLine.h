#pragma once

// A simulated bus whose time moves only with the line: every transaction is handled by the
// in-process simulator (SimBus, the DC controller and its motor) at the line's present time,
// then the time moves on by what the frames take on the wire at the line's rate (WireTiming)
// and a host's share. A tuning test on it runs at the pace of the CPU, gives the same samples
// on every run, however loaded the machine, and its runner stamps samples with the line's time.

#include "sim/ManualSimClock.h"
#include "sim/SimBus.h"
#include "sim/WireTiming.h"
#include "transport/ModbusBackend.h"
#include "transport/ModbusClient.h"
#include "transport/RtuFrame.h"

#include <atomic>
#include <functional>
#include <memory>

namespace opentop::test {

class VirtualLineBackend : public ModbusBackend
{
public:
    VirtualLineBackend(std::shared_ptr<SimBus> bus, std::shared_ptr<ManualSimClock> clock, int baud,
                       char parity, double hostMs, std::shared_ptr<std::atomic<double>> nowMs)
        : m_bus(std::move(bus))
        , m_clock(std::move(clock))
        , m_timing(baud, parity)
        , m_hostMs(hostMs)
        , m_now(std::move(nowMs))
    {
    }

    // Runs on the worker thread before each transaction, at the line's time (a load that
    // changes during a test).
    std::function<void(double nowMs)> beforeTransaction;
    // Another drive on the line, polled by someone else: before every `otherEvery`-th
    // transaction the line carries its 3-register read (0: a line of our own).
    int otherEvery = 0;

    bool open(QString*) override
    {
        m_open = true;
        return true;
    }
    void close() override { m_open = false; }
    bool isOpen() const override { return m_open; }
    QString describe() const override { return QStringLiteral("virtual line"); }

    ModbusResult transact(const ModbusRequest& request, int timeoutMs) override
    {
        ModbusResult result;
        result.attempts = 1;
        if (!m_open || m_bus->isUnplugged()) {
            m_open = false;
            result.error = ModbusError::PortError;
            result.message = QStringLiteral("the virtual line was unplugged");
            return result;
        }
        if (beforeTransaction)
            beforeTransaction(m_now->load());
        if (otherEvery > 0 && ++m_count % otherEvery == 0)
            advance(m_hostMs + m_timing.replyDelayMs(8, 11));
        const QByteArray adu = RtuFrame::encodeRequest(request);
        // As the simulator on a pty does: the device answers for the moment the request came.
        const SimOutcome outcome = m_bus->handleFrame(adu, m_clock->nowMs());
        double delay = m_hostMs + outcome.delayMs;
        if (!outcome.reply.isEmpty())
            delay += m_timing.replyDelayMs(int(adu.size()), int(outcome.reply.size()));
        const int timeout = timeoutMs > 0 ? timeoutMs : 200;
        const bool lost = outcome.reply.isEmpty() || delay >= timeout;
        advance(lost ? timeout : delay);
        result.elapsedMs = lost ? timeout : delay;
        if (lost) {
            result.error = ModbusError::Timeout;
            result.message = QStringLiteral("no reply within %1 ms").arg(timeout);
            return result;
        }
        RtuFrame::decodeReply(request, outcome.reply, &result);
        result.attempts = 1;
        result.reply = outcome.reply;
        return result;
    }

private:
    void advance(double ms)
    {
        const double now = m_now->load() + ms;
        m_now->store(now);
        m_clock->setNowMs(qint64(now));
    }

    std::shared_ptr<SimBus> m_bus;
    std::shared_ptr<ManualSimClock> m_clock;
    WireTiming m_timing;
    double m_hostMs;
    std::shared_ptr<std::atomic<double>> m_now;
    bool m_open = false;
    int m_count = 0;
};

// A bus of `spec` on a virtual line at `baud` (`parity` 'N', 'E' or 'O'; 10 or 11 bits).
struct VirtualLine
{
    std::shared_ptr<ManualSimClock> clock = std::make_shared<ManualSimClock>(0);
    std::shared_ptr<std::atomic<double>> nowMs = std::make_shared<std::atomic<double>>(0);
    std::shared_ptr<SimBus> bus;
    VirtualLineBackend* backend = nullptr; // owned by the client
    std::unique_ptr<ModbusClient> client;

    bool open(const QString& spec, int baud, char parity = 'N', double hostMs = 0.5)
    {
        QString error;
        bus = SimBus::fromSpec(spec, &error, clock);
        if (!bus)
            return false;
        auto made = std::make_unique<VirtualLineBackend>(bus, clock, baud, parity, hostMs, nowMs);
        backend = made.get();
        ConnectionSettings settings;
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.simSpec = spec;
        settings.baud = baud;
        settings.timeoutMs = 200;
        settings.retries = 0;
        client = std::make_unique<ModbusClient>(std::move(made), settings);
        return client->openBlocking().isEmpty();
    }
    std::function<double()> time() const
    {
        return [now = nowMs] { return now->load(); };
    }
};

} // namespace opentop::test
