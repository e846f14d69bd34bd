#include "bench/PlainModbusLoop.h"

#include <QElapsedTimer>
#include <QFile>
#include <QThread>
#include <cerrno>
#include <modbus.h>

namespace opentop {

PlainModbusLoop::PlainModbusLoop(const QString& port, int baud)
    : m_port(port)
    , m_baud(baud)
{
}

PlainModbusLoop::~PlainModbusLoop()
{
    if (m_ctx) {
        modbus_close(m_ctx);
        modbus_free(m_ctx);
    }
}

bool PlainModbusLoop::open(QString* error)
{
    m_ctx = modbus_new_rtu(QFile::encodeName(m_port).constData(), m_baud, 'N', 8, 1);
    if (!m_ctx || modbus_connect(m_ctx) == -1) {
        *error = QStringLiteral("libmodbus cannot open %1: %2")
                     .arg(m_port, QString::fromLocal8Bit(modbus_strerror(errno)));
        return false;
    }
    modbus_set_response_timeout(m_ctx, 1, 0);
    return true;
}

PlainModbusLoop::PollResult PlainModbusLoop::poll(int slave, const QVector<Block>& blocks,
                                                  double seconds)
{
    PollResult result;
    uint16_t registers[125];
    modbus_set_slave(m_ctx, slave);
    auto read = [this, &registers](const Block& b) {
        const int n = b.function == 4
                          ? modbus_read_input_registers(m_ctx, b.address, b.count, registers)
                          : modbus_read_registers(m_ctx, b.address, b.count, registers);
        return n == b.count;
    };
    QElapsedTimer warmUp;
    warmUp.start();
    for (int i = 0; warmUp.elapsed() < 300; ++i)
        read(blocks.at(i % blocks.size()));
    QElapsedTimer timer;
    timer.start();
    for (int i = 0; double(timer.nsecsElapsed()) / 1e9 < seconds; ++i) {
        if (read(blocks.at(i % blocks.size())))
            ++result.transactions;
        else
            ++result.errors;
    }
    result.seconds = double(timer.nsecsElapsed()) / 1e9;
    return result;
}

PlainModbusLoop::ScanResult PlainModbusLoop::scan(int from, int to, int address, int count,
                                                  int waitMs)
{
    ScanResult result;
    uint16_t registers[125];
    modbus_set_response_timeout(m_ctx, uint32_t(waitMs / 1000), uint32_t(waitMs % 1000) * 1000);
    QElapsedTimer timer;
    timer.start();
    for (int slave = from; slave <= to; ++slave) {
        modbus_set_slave(m_ctx, slave);
        if (modbus_read_registers(m_ctx, address, count, registers) == count)
            result.found << slave;
        else
            modbus_flush(m_ctx); // a late reply must not be read as the next one's
    }
    result.seconds = double(timer.nsecsElapsed()) / 1e9;
    modbus_set_response_timeout(m_ctx, 1, 0);
    return result;
}

} // namespace opentop
