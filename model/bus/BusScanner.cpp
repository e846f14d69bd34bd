#include "model/bus/BusScanner.h"

#include "model/ModelLog.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceIdentifier.h"
#include "transport/ModbusClient.h"

#include <algorithm>

namespace opentop {

BusScanner::BusScanner(ModbusClient* client, const ProfileRegistry& registry, QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
    , m_identifier(new DeviceIdentifier(client, registry, this))
    , m_waits(client)
{
    // A late reply can be taken by any request on the bus, not only the scan's: the program
    // polls the drives it has found meanwhile. Every result is looked at.
    // The scan's own results are looked at in handleReply() (the callback comes first).
    connect(client, &ModbusClient::finished, this, [this](quint64 id, const ModbusResult& r) {
        if (m_running && id != m_pendingId && id != m_handledId)
            noteLateAnswer(r);
    });
}

BusScanner::~BusScanner()
{
    // Deleted while running (its window closed): polling goes on.
    if (m_held)
        m_held->releasePolling();
}

void BusScanner::setRange(int from, int to)
{
    m_from = std::clamp(from, 1, 247);
    m_to = std::clamp(to, m_from, 247);
}

double BusScanner::elapsedMs() const
{
    return m_running ? double(m_timer.nsecsElapsed()) / 1e6 : m_elapsedMs;
}

void BusScanner::start()
{
    if (m_running)
        return;
    m_waits.begin();
    m_cursor = m_from;
    m_slave = 0;
    m_reasks.clear(std::max(double(kSuspectWindowMs), 4.0 * m_waits.passWaitMs()));
    m_reasking = false;
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
    // The scan owns the bus: a poll sent while a reply may still be on the line would destroy
    // both, and the scan would never know (issue 24: the DC controller's 25-byte reply).
    if (!m_held) {
        m_held = m_client;
        m_client->holdPolling();
    }
    qCDebug(lcModel) << "scan" << m_from << "to" << m_to << "wait" << m_waits.passWaitMs() << "ms";
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
    request.line = m_waits.line();
    // The wait follows what is known of the address: asked again, last, heard from, or not.
    using Asking = ScanWaits::Asking;
    const Asking asking = m_reasking                       ? Asking::Again
                          : m_slave == m_to                ? Asking::LastOfPass
                          : profileIndex > 0 || confirming ? Asking::Present
                                                           : Asking::First;
    request.timeoutMs = m_waits.timeoutMs(m_slave, rule.count, asking);
    request.probe = !m_reasking && !confirming && profileIndex == 0;
    // Silence is the normal answer in a scan: retrying it would only double the scan time.
    request.retries = 0;
    request.priority = ModbusRequest::Priority::User;
    ++m_requests;
    m_pendingId =
        m_client->submit(request, this, [this, profileIndex, confirming](const ModbusResult& r) {
            m_handledId = m_pendingId;
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
    // A device that refuses a family's read is there, whatever it turns out to be.
    if (info.state == DeviceInfo::State::Unidentified)
        m_reasks.answered(m_slave);
    // On a half-duplex line a late answer from the address before collides with this request:
    // both frames are garbled and the address before looked silent. Ask it again, with time.
    // A whole frame from another address names its sender (noteLateAnswer()).
    const bool senderKnown = result.error == ModbusError::WrongSlave && !result.reply.isEmpty();
    if (info.state == DeviceInfo::State::Garbled && !m_reasking && !senderKnown)
        askRecentAgain();
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
                         "%2; check their address switches (%3)")
                          .arg(result.errorText())
                          .arg(m_slave)
                          .arg(DeviceInfo::switchText(m_slave));
    else if (info.state == DeviceInfo::State::Unidentified)
        info.detail = tr("answers, but none of the device profiles matches (%1)").arg(info.detail);
    else if (info.state == DeviceInfo::State::Absent && m_reasks.hasAnswered(m_slave))
        info = identificationFailed(info);
    addressDone(info);
}

DeviceInfo BusScanner::identificationFailed(DeviceInfo info)
{
    if (const int attempt = m_reasks.retryIdentification(m_slave)) {
        emit identificationRetry(m_slave, attempt, kIdentifyRetries);
        return info;
    }
    info.state = DeviceInfo::State::IdentifyFailed;
    info.detail = tr("answered, but its identification read got no reply (%1), also when "
                     "asked %2 more times: add it by hand, or scan with a longer wait")
                      .arg(info.detail)
                      .arg(kIdentifyRetries);
    return info;
}

QVector<int> BusScanner::unidentified(const QVector<DeviceInfo>& devices)
{
    QVector<int> slaves;
    for (const DeviceInfo& d : devices)
        if (d.state == DeviceInfo::State::IdentifyFailed)
            slaves << d.slave;
    return slaves;
}

void BusScanner::noteLateAnswer(const ModbusResult& result)
{
    // A garbled frame thrown away before a request went out, or while the line was drained
    // after one: a reply met a request on the line after both their waits (a slow drive, a busy
    // machine). Its sender and the address the request asked were among those asked just before.
    if (result.discardedGarbled) {
        qCDebug(lcModel) << "scan: a garbled frame was discarded while asking" << m_slave;
        askRecentAgain();
    }
    // A reply from an address already passed as silent: that drive answers slower than the
    // wait. Its reply spoiled this request; ask it again with a longer wait rather than lose it.
    // Or one the transport discarded before sending this request (it came after its wait).
    int sender = result.lateReplyFrom;
    if (result.error == ModbusError::WrongSlave && !result.reply.isEmpty())
        sender = quint8(result.reply.at(0));
    if (sender < 0)
        return;
    const bool known = reported(sender);
    if (!known)
        m_reasks.answered(sender); // a whole frame with its number: it is there
    if (sender == m_slave || known)
        return;
    qCDebug(lcModel) << "scan: late answer from" << sender << "while asking" << m_slave;
    askAgainLater(sender);
}

bool BusScanner::reported(int slave) const
{
    return std::any_of(m_devices.begin(), m_devices.end(),
                       [slave](const DeviceInfo& d) { return d.slave == slave; });
}

void BusScanner::askAgainLater(int slave)
{
    // Only an address this pass has already judged silent.
    if (slave < m_from || slave >= m_cursor || slave == m_slave || reported(slave))
        return;
    m_reasks.askLate(slave);
}

void BusScanner::askRecentAgain()
{
    for (int slave : m_reasks.suspects(m_askedAtMs))
        askAgainLater(slave); // no longer a suspect once queued
}

void BusScanner::addressDone(DeviceInfo info)
{
    if (!m_reasking)
        ++m_done;
    if (info.state != DeviceInfo::State::Absent) {
        info.line = m_waits.line().isSet() ? m_waits.line() : LineFormat();
        if (!info.line.isSet() && m_client->hasOwnLine(info.slave))
            info.line = m_client->driveLine(info.slave);
        if (m_reasking && info.state != DeviceInfo::State::IdentifyFailed) {
            ++m_lateAnswers;
            const QString late = tr("answered late at first (after the %1 ms wait); a longer "
                                    "wait makes scans of this bus reliable")
                                     .arg(m_waits.passWaitMs());
            info.detail = info.detail.isEmpty() ? late : info.detail + QStringLiteral("; ") + late;
        }
        const auto at =
            std::lower_bound(m_devices.begin(), m_devices.end(), info.slave,
                             [](const DeviceInfo& d, int slave) { return d.slave < slave; });
        m_devices.insert(at, info);
        emit found(info);
    }
    if (!m_reasking) {
        m_reasks.passed(m_slave, info.state == DeviceInfo::State::Absent, m_askedAtMs);
        emit progress(m_done, total(), m_slave);
    }
    nextAddress();
}

void BusScanner::nextAddress()
{
    const bool more = m_cursor <= m_to || m_reasks.hasQueued();
    if (m_cancelRequested || !more) {
        m_cancelled = m_cancelRequested && more;
        finish();
        return;
    }
    // A late reply of the addresses asked just before may meet the next request (the suspects
    // of m_reasks); one asked again had a long wait, so its reply is not suspected.
    m_reasking = m_reasks.hasQueued();
    m_slave = m_reasking ? m_reasks.takeNext() : m_cursor++;
    m_askedAtMs = elapsedMs();
    askProfile(0, false);
}

void BusScanner::finish()
{
    m_running = false;
    if (m_held)
        m_held->releasePolling(); // before finished(): what listens may poll at once
    m_held = nullptr;
    m_elapsedMs = double(m_timer.nsecsElapsed()) / 1e6;
    qCDebug(lcModel) << "scan finished:" << m_done << "addresses," << m_devices.size() << "found,"
                     << m_requests << "requests," << m_elapsedMs << "ms"
                     << (m_cancelled ? "(cancelled)" : "");
    emit finished(m_devices);
}

} // namespace opentop
