#include "bus/BusScanner.h"

#include "ModbusClient.h"
#include "ModelLog.h"
#include "profile/ProfileRegistry.h"
#include "session/DeviceIdentifier.h"

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

constexpr int kReadRequestBytes = 8; // id, function, address, count, CRC
constexpr double kMarginMs = 2.0;    // scheduling on the master's side
// A TCP gateway queues the request and forwards it on its own serial line.
constexpr double kGatewayMs = 50.0;

} // namespace

BusScanner::BusScanner(ModbusClient* client, const ProfileRegistry& registry, QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
    , m_identifier(new DeviceIdentifier(client, registry, this))
{
    // A late reply can be taken by any request on the bus, not only the scan's: the program
    // polls the drives it has found meanwhile. Every result is looked at.
    connect(client, &ModbusClient::finished, this, [this](quint64 id, const ModbusResult& r) {
        if (m_running && id != m_pendingId)
            noteLateAnswer(r);
    });
}

BusScanner::~BusScanner() = default;

int BusScanner::defaultWaitMs(const ConnectionSettings& settings, int adapterLatencyMs)
{
    const double c = settings.charTimeMs();
    const double gap = settings.baud > 19200 ? 1.75 : 3.5 * c; // Modbus RTU's, as the drive keeps
    double ms = kReadRequestBytes * c + gap + kAnswerBudgetMs + kMarginMs + adapterLatencyMs;
    if (settings.kind == ConnectionSettings::Kind::Tcp)
        ms += kGatewayMs;
    return std::clamp(int(std::ceil(ms)), kMinWaitMs, kMaxWaitMs);
}

void BusScanner::setRange(int from, int to)
{
    m_from = std::clamp(from, 1, 247);
    m_to = std::clamp(to, m_from, 247);
}

void BusScanner::setWaitMs(int ms)
{
    m_waitMs = ms > 0 ? std::clamp(ms, kMinWaitMs, kMaxWaitMs) : 0;
}

int BusScanner::waitMs() const
{
    return waitFor(0);
}

int BusScanner::waitFor(int slave) const
{
    if (m_waitMs > 0)
        return m_waitMs;
    ConnectionSettings settings = m_client->settings();
    if (m_line.isSet())
        settings.setLine(m_line);
    else if (slave > 0)
        settings.setLine(m_client->driveLine(slave));
    return defaultWaitMs(settings, m_client->adapterLatencyMs());
}

double BusScanner::elapsedMs() const
{
    return m_running ? double(m_timer.nsecsElapsed()) / 1e6 : m_elapsedMs;
}

void BusScanner::start()
{
    if (m_running)
        return;
    m_effectiveWaitMs = waitMs();
    m_cursor = m_from;
    m_slave = 0;
    m_reasking = false;
    m_late.clear();
    m_lateAnswers = 0;
    m_done = 0;
    m_requests = 0;
    m_cancelled = false;
    m_cancelRequested = false;
    m_error.clear();
    m_devices.clear();
    m_elapsedMs = 0;
    m_running = true;
    m_timer.start();
    qCDebug(lcModel) << "scan" << m_from << "to" << m_to << "wait" << m_effectiveWaitMs << "ms";
    nextAddress();
}

void BusScanner::cancel()
{
    if (!m_running || m_cancelRequested)
        return;
    m_cancelRequested = true;
    // A request still queued behind other traffic is withdrawn (its callback reports
    // Cancelled); one on the wire completes first.
    m_client->cancel(m_pendingId);
}

void BusScanner::askProfile(int profileIndex, bool confirming)
{
    const IdentifyRule& rule = m_registry.profiles()[profileIndex].identify;
    ModbusRequest request =
        rule.function == 4 ? ModbusRequest::readInput(quint8(m_slave), rule.address, rule.count)
                           : ModbusRequest::readHolding(quint8(m_slave), rule.address, rule.count);
    // A drive asked again because it answered late: four waits, or the connection's timeout.
    // The last address of the pass has no next request to catch its late reply: four waits.
    const bool last = !m_reasking && m_slave == m_to;
    request.line = m_line;
    // A drive of its own format is asked at its rate: the wait follows it.
    const int effectiveWaitMs = std::max(m_effectiveWaitMs, waitFor(m_slave));
    request.timeoutMs =
        m_reasking ? std::clamp(std::max(4 * effectiveWaitMs, m_client->settings().timeoutMs),
                                kMinWaitMs, kMaxWaitMs)
        : last     ? std::clamp(4 * effectiveWaitMs, kMinWaitMs, kMaxWaitMs)
                   : effectiveWaitMs;
    // Silence is the normal answer in a scan: retrying it would only double the scan time.
    request.retries = 0;
    request.priority = ModbusRequest::Priority::User;
    ++m_requests;
    m_pendingId =
        m_client->submit(request, this, [this, profileIndex, confirming](const ModbusResult& r) {
            handleReply(profileIndex, confirming, r);
        });
}

void BusScanner::handleReply(int profileIndex, bool confirming, const ModbusResult& result)
{
    if (result.error == ModbusError::Cancelled) {
        m_cancelled = true; // withdrawn or interrupted: this address was not scanned
        finish();
        return;
    }
    noteLateAnswer(result);
    DeviceInfo info = m_identifier->interpret(m_slave, profileIndex, result);
    if (info.state == DeviceInfo::State::Unknown) {
        // Not an answer of any kind (port failed, not connected, request refused): every
        // further address would fail the same way.
        m_error = result.errorText();
        finish();
        return;
    }
    // On a half-duplex line a late answer from the address before collides with this request:
    // both frames are garbled and the address before looked silent. Ask it again, with time.
    if (info.state == DeviceInfo::State::Garbled && !m_reasking)
        askAgainLater(m_slave - 1);
    // A single corrupt frame may be noise; two drives answering at once garble every reply.
    const bool confirm = info.state == DeviceInfo::State::Garbled && !confirming;
    // A device that refuses this family's read may be of another family.
    const bool nextFamily = info.state == DeviceInfo::State::Unidentified &&
                            profileIndex + 1 < m_registry.profiles().size();
    if ((confirm || nextFamily) && m_cancelRequested) {
        // Between two transactions of one address: stop without a half-made verdict.
        m_cancelled = true;
        finish();
        return;
    }
    if (confirm || nextFamily) {
        askProfile(confirm ? profileIndex : profileIndex + 1, confirm);
        return;
    }
    if (info.state == DeviceInfo::State::Garbled)
        info.detail = tr("garbled replies twice (%1): two drives probably share machine number "
                         "%2; check their SW1/SW2 switches")
                          .arg(result.errorText())
                          .arg(m_slave);
    else if (info.state == DeviceInfo::State::Unidentified)
        info.detail = tr("answers, but none of the device profiles matches (%1)").arg(info.detail);
    addressDone(info);
}

void BusScanner::noteLateAnswer(const ModbusResult& result)
{
    // A reply from an address already passed as silent: that drive answers slower than the
    // wait. Its reply spoiled this request; ask it again with a longer wait rather than lose it.
    // Or one the transport discarded before sending this request (it came after its wait).
    int sender = result.lateReplyFrom;
    if (result.error == ModbusError::WrongSlave && !result.reply.isEmpty())
        sender = quint8(result.reply.at(0));
    if (sender < 0)
        return;
    const bool known = std::any_of(m_devices.begin(), m_devices.end(),
                                   [sender](const DeviceInfo& d) { return d.slave == sender; });
    if (sender == m_slave || known)
        return;
    qCDebug(lcModel) << "scan: late answer from" << sender << "while asking" << m_slave;
    askAgainLater(sender);
}

void BusScanner::askAgainLater(int slave)
{
    // Only an address this pass has already judged silent.
    const bool known = std::any_of(m_devices.begin(), m_devices.end(),
                                   [slave](const DeviceInfo& d) { return d.slave == slave; });
    if (slave < m_from || slave >= m_cursor || slave == m_slave || known || m_late.contains(slave))
        return;
    ++m_lateAnswers;
    m_late << slave;
}

void BusScanner::addressDone(DeviceInfo info)
{
    if (!m_reasking)
        ++m_done;
    if (info.state != DeviceInfo::State::Absent) {
        info.line = m_line.isSet() ? m_line : LineFormat();
        if (!info.line.isSet() && m_client->hasOwnLine(info.slave))
            info.line = m_client->driveLine(info.slave);
        if (m_reasking) {
            const QString late = tr("answered late at first (after the %1 ms wait); a longer "
                                    "wait makes scans of this bus reliable")
                                     .arg(m_effectiveWaitMs);
            info.detail = info.detail.isEmpty() ? late : info.detail + QStringLiteral("; ") + late;
        }
        const auto at =
            std::lower_bound(m_devices.begin(), m_devices.end(), info.slave,
                             [](const DeviceInfo& d, int slave) { return d.slave < slave; });
        m_devices.insert(at, info);
        emit found(info);
    }
    if (!m_reasking)
        emit progress(m_done, total(), m_slave);
    nextAddress();
}

void BusScanner::nextAddress()
{
    const bool more = m_cursor <= m_to || !m_late.isEmpty();
    if (m_cancelRequested || !more) {
        m_cancelled = m_cancelRequested && more;
        finish();
        return;
    }
    m_reasking = !m_late.isEmpty();
    m_slave = m_reasking ? m_late.takeFirst() : m_cursor++;
    askProfile(0, false);
}

void BusScanner::finish()
{
    m_running = false;
    m_elapsedMs = double(m_timer.nsecsElapsed()) / 1e6;
    qCDebug(lcModel) << "scan finished:" << m_done << "addresses," << m_devices.size() << "found,"
                     << m_requests << "requests," << m_elapsedMs << "ms"
                     << (m_cancelled ? "(cancelled)" : "");
    emit finished(m_devices);
}

} // namespace opentop
