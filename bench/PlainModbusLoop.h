#pragma once

#include <QString>
#include <QVector>

struct _modbus; // libmodbus' modbus_t, kept out of this header

namespace opentop {

// The reference a tool without OpenTOP's stack would be: libmodbus called in a loop on the
// same pty, nothing else (no worker thread, no session, no codec, no resynchronisation).
class PlainModbusLoop
{
public:
    struct PollResult
    {
        int transactions = 0;
        int errors = 0;
        double seconds = 0;
        double perSecond() const { return seconds > 0 ? transactions / seconds : 0; }
    };
    struct ScanResult
    {
        QVector<int> found;
        double seconds = 0;
    };

    PlainModbusLoop(const QString& port, int baud);
    ~PlainModbusLoop();
    PlainModbusLoop(const PlainModbusLoop&) = delete;
    PlainModbusLoop& operator=(const PlainModbusLoop&) = delete;
    bool open(QString* error);

    struct Block
    {
        int function = 3; // 3 holding, 4 input registers
        int address = 0;
        int count = 1;
    };
    // The blocks read one after the other, again and again, for `seconds` (after a short
    // warm-up that is not counted).
    PollResult poll(int slave, const QVector<Block>& blocks, double seconds);
    // One read of `address` per machine number in [from, to], each waiting `waitMs` for a
    // reply, as a simple scanner does.
    ScanResult scan(int from, int to, int address, int count, int waitMs);

private:
    QString m_port;
    int m_baud;
    _modbus* m_ctx = nullptr;
};

} // namespace opentop
