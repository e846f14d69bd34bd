#include "transport/RtuBackend.h"

#ifdef Q_OS_WIN
#include "transport/ComPortDriver_win.h"
#include "transport/ComPort_win.h"
#else
#include "transport/IoctlSerialDriver.h"
#endif
#include "transport/LateReplyJournal.h"
#include "transport/RtuFrame.h"
#include "transport/SerialSysfs.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <modbus.h>

namespace opentop {

namespace {

constexpr int kMaxAdu = MODBUS_RTU_MAX_ADU_LENGTH;

// Length of the reply `request` normally gets, to size the quiet time after an error. The
// drain restarts with every byte, so this only has to cover a reply that starts late.
int typicalReplyBytes(const ModbusRequest& request)
{
    if (request.raw)
        return 40; // a basic device identification
    if (request.isRead())
        return 5 + 2 * request.count;
    return 8;
}

} // namespace

RtuBackend::RtuBackend(const ConnectionSettings& settings)
    : LibmodbusBackend(settings)
    , m_lock(settings.port)
{
}

RtuBackend::~RtuBackend()
{
    close();
}

bool RtuBackend::open(QString* error)
{
    close();
    if (m_lock.acquire(error) == PortLock::Outcome::InUse)
        return false;
    if (!LibmodbusBackend::open(error)) {
        m_lock.release();
        return false;
    }
    m_lock.makeExclusive(descriptor());
    m_line = SerialLineSetup();
    m_lineReport = m_line.apply(*makeDriver(), settings(), SerialSysfs(settings().port));
    // The drives the line's previous user gave up on may still answer (LateReplyJournal).
    const qint64 wallMs = QDateTime::currentMSecsSinceEpoch();
    const double nowMs = clockMs();
    for (const LateReplyJournal::Entry& e : journal().take(wallMs))
        suspectUntil({e.slave, nowMs + double(e.untilMs - wallMs), e.function, e.count});
    return true;
}

LateReplyJournal RtuBackend::journal() const
{
    return LateReplyJournal(m_lock.device().isEmpty() ? settings().port : m_lock.device());
}

void RtuBackend::close()
{
    if (context()) { // open (a COM port has no descriptor on Windows)
        m_line.restore(*makeDriver());
        // For the line's next user: who may still answer a request we gave up on.
        const qint64 wallMs = QDateTime::currentMSecsSinceEpoch();
        const double nowMs = clockMs();
        QVector<LateReplyJournal::Entry> entries;
        for (const LateReplyWatch::Suspect& s : lateSuspects())
            entries.append(
                {s.slave, wallMs + qint64(std::ceil(s.untilMs - nowMs)), s.function, s.count});
        journal().write(entries);
    }
    m_lineReport = SerialLineReport();
    LibmodbusBackend::close();
    m_lock.release();
}

QString RtuBackend::describe() const
{
    return settings().describe();
}

int RtuBackend::defaultTurnaroundMs() const
{
    // Strictly more than C3.5 + 5 ms, also where that is a whole number of milliseconds.
    return std::max(10, int(std::floor(3.5 * lineSettings().charTimeMs() + 5)) + 1);
}

double RtuBackend::defaultFrameGapMs() const
{
    return lineSettings().baud > 19200 ? 1.75 : 3.5 * lineSettings().charTimeMs();
}

_modbus* RtuBackend::createContext()
{
    const ConnectionSettings& s = settings();
#ifdef Q_OS_WIN
    const QByteArray device = ComPort::devicePath(s.port.trimmed()).toLocal8Bit();
#else
    const QByteArray device = QFile::encodeName(s.port);
#endif
    return modbus_new_rtu(device.constData(), s.baud, s.parity, s.dataBits, s.stopBits);
}

QString RtuBackend::openErrorText(int err) const
{
    QString text = LibmodbusBackend::openErrorText(err);
#ifndef Q_OS_WIN // Windows has no dialout group: a port it refuses is one in use (EBUSY)
    if (err == EACCES)
        return text +
               QCoreApplication::translate(
                   "opentop::Transport",
                   ": your user may not open serial ports. Add it to the dialout group with\n"
                   "    sudo usermod -aG dialout $USER\n"
                   "then log out and in again (the group applies to new sessions only).");
#endif
    if (err == EINVAL && settings().parity != 'N')
        text += QCoreApplication::translate(
            "opentop::Transport", " (the device may not support this parity; ptys need N)");
    return text;
}

QByteArray RtuBackend::txAdu(const ModbusRequest& request) const
{
    return RtuFrame::encodeRequest(request);
}

QByteArray RtuBackend::toRtuAdu(const QByteArray& received) const
{
    return received;
}

int RtuBackend::receivedLength(const QByteArray& buffer) const
{
    // libmodbus reads a reply by its function code; for codes it does not know that is
    // id, function, one byte and the CRC.
    const int length = RtuFrame::expectedReplyLength(ModbusRequest(), buffer);
    return length > 0 ? std::min(length, kMaxAdu) : 5;
}

void RtuBackend::readRawReply(const ModbusRequest& request, int timeoutMs, QByteArray* adu,
                              ModbusResult* result)
{
    // libmodbus does not know the length of replies to functions it has no API for (0x2B):
    // read by the reply's own length (its object list), or until the line goes silent.
    const int gapMs = lineSettings().effectiveByteTimeoutMs();
    char chunk[kMaxAdu];
    for (;;) {
        const int need = RtuFrame::expectedReplyLength(request, *adu);
        if (need > kMaxAdu) {
            result->error = ModbusError::MalformedReply;
            result->message =
                QCoreApplication::translate("opentop::Transport", "reply announces %1 bytes, "
                                                                  "more than an RTU frame holds")
                    .arg(need);
            return;
        }
        if (need > 0 && adu->size() >= need)
            break;
        if (adu->size() >= kMaxAdu)
            break;
        const double wait = adu->isEmpty() ? std::max(1.0, timeoutMs - elapsedMs()) : gapMs;
        const int ready = waitReadable(wait);
        if (ready < 0) {
            result->error = ModbusError::Cancelled;
            return;
        }
        if (ready == 0) {
            if (need < 0 && !adu->isEmpty())
                break; // unknown length: the silence ends the frame
            result->error = ModbusError::Timeout;
            result->message =
                adu->isEmpty()
                    ? QCoreApplication::translate("opentop::Transport", "no reply")
                    : QCoreApplication::translate("opentop::Transport", "reply incomplete");
            return;
        }
        const int want = need > 0 ? need - int(adu->size()) : kMaxAdu - int(adu->size());
        const int n = readSome(chunk, want);
        if (n <= 0) {
            portFailure(n == 0 ? EIO : errno,
                        QCoreApplication::translate("opentop::Transport", "receive failed"),
                        result);
            return;
        }
        adu->append(chunk, n);
    }
    RtuFrame::decodeReply(request, *adu, result);
}

double RtuBackend::wireTimeMs(int bytes) const
{
    return bytes * lineSettings().charTimeMs();
}

int RtuBackend::recoveryQuietMs(const ModbusRequest& request) const
{
    return int(std::ceil((typicalReplyBytes(request) + 3.5) * lineSettings().charTimeMs())) + 10;
}

} // namespace opentop

namespace opentop {

std::unique_ptr<SerialDriver> RtuBackend::makeDriver()
{
#ifdef Q_OS_WIN
    return std::make_unique<ComPortDriver>(modbusContext().commHandle());
#else
    return std::make_unique<IoctlSerialDriver>(descriptor(), context());
#endif
}

bool RtuBackend::applyLineFormat(const LineFormat& format, QString* error)
{
    return m_line.switchFormat(*makeDriver(), format, error) == 0;
}

double RtuBackend::meanSwitchMicros() const
{
    return m_line.switchCount() > 0 ? double(m_line.switchMicros()) / m_line.switchCount() : 0;
}

} // namespace opentop
