#include "transport/LateReplyWatch.h"

#include "transport/LineInput.h"
#include "transport/ModbusRequest.h"

#include <algorithm>

namespace opentop {

void LateReplyWatch::opened(double nowMs, int timeoutMs)
{
    m_suspectAllUntilMs = nowMs + std::max(1000.0, 5.0 * timeoutMs);
}

void LateReplyWatch::clear()
{
    m_waits.clear();
    m_unanswered.clear();
    m_suspects.clear();
    m_checkedSinceOpen.clear();
}

void LateReplyWatch::timedOut(quint8 slave, double nowMs, int timeoutMs, double untilMs,
                              int quietMs)
{
    suspect(slave, nowMs, timeoutMs);
    m_waits.append(Entry{slave, {untilMs, quietMs}});
}

void LateReplyWatch::forgetOver(QVector<Entry>* entries, double nowMs)
{
    entries->erase(std::remove_if(entries->begin(), entries->end(),
                                  [nowMs](const Entry& e) { return e.wait.untilMs <= nowMs; }),
                   entries->end());
}

std::optional<LateReplyWatch::Wait> LateReplyWatch::dueBefore(const ModbusRequest& request,
                                                              double nowMs, const LineInput& input)
{
    forgetOver(&m_waits, nowMs);
    if (m_waits.isEmpty())
        return std::nullopt;
    const bool sameSlave = std::any_of(m_waits.begin(), m_waits.end(),
                                       [&](const Entry& e) { return e.slave == request.slave; });
    if (!sameSlave && !request.isBroadcast() && input.waitReadable(0) != 1)
        return std::nullopt;
    Wait all{nowMs, 0};
    for (const Entry& e : m_waits) {
        all.untilMs = std::max(all.untilMs, e.wait.untilMs);
        all.quietMs = std::max(all.quietMs, e.wait.quietMs);
    }
    m_waits.clear();
    return all;
}

void LateReplyWatch::suspect(quint8 slave, double nowMs, int timeoutMs)
{
    // Long after the late-reply window: a master without transaction ids cannot wait that
    // long before every retry, but it can check the replies that follow.
    const double untilMs = nowMs + std::max(3000.0, 10.0 * timeoutMs);
    for (Entry& e : m_suspects) {
        if (e.slave == slave) {
            e.wait.untilMs = std::max(e.wait.untilMs, untilMs);
            return;
        }
    }
    m_suspects.append(Entry{slave, {untilMs, 0}});
}

void LateReplyWatch::unanswered(const ModbusRequest& request, double nowMs, int timeoutMs)
{
    if (request.isBroadcast() || request.raw)
        return;
    const double untilMs = nowMs + std::max(3000.0, 10.0 * timeoutMs);
    for (Shape& s : m_unanswered) {
        if (s.slave == request.slave && s.function == request.function &&
            s.count == request.count) {
            s.untilMs = std::max(s.untilMs, untilMs);
            return;
        }
    }
    m_unanswered.append(Shape{request.slave, request.function, request.count, untilMs});
}

void LateReplyWatch::forgetUnansweredOver(double nowMs)
{
    m_unanswered.erase(std::remove_if(m_unanswered.begin(), m_unanswered.end(),
                                      [nowMs](const Shape& s) { return s.untilMs <= nowMs; }),
                       m_unanswered.end());
}

bool LateReplyWatch::ambiguous(const ModbusRequest& request, double nowMs)
{
    forgetUnansweredOver(nowMs);
    return std::any_of(m_unanswered.begin(), m_unanswered.end(), [&](const Shape& s) {
        return s.slave == request.slave && s.function == request.function &&
               s.count == request.count;
    });
}

void LateReplyWatch::suspectUntil(const Suspect& suspect)
{
    if (suspect.function != 0) {
        const auto same =
            std::find_if(m_unanswered.begin(), m_unanswered.end(), [&](const Shape& s) {
                return s.slave == suspect.slave && s.function == suspect.function &&
                       s.count == suspect.count;
            });
        if (same == m_unanswered.end())
            m_unanswered.append(
                Shape{suspect.slave, suspect.function, suspect.count, suspect.untilMs});
        else
            same->untilMs = std::max(same->untilMs, suspect.untilMs);
    }
    for (Entry& e : m_suspects) {
        if (e.slave == suspect.slave) {
            e.wait.untilMs = std::max(e.wait.untilMs, suspect.untilMs);
            return;
        }
    }
    m_suspects.append(Entry{suspect.slave, {suspect.untilMs, 0}});
}

QVector<LateReplyWatch::Suspect> LateReplyWatch::suspects(double nowMs)
{
    forgetOver(&m_suspects, nowMs);
    forgetUnansweredOver(nowMs);
    QVector<Suspect> left;
    for (const Entry& e : m_suspects)
        left.append(Suspect{e.slave, e.wait.untilMs, 0, 0});
    for (const Shape& s : m_unanswered)
        left.append(Suspect{s.slave, s.untilMs, s.function, s.count});
    return left;
}

bool LateReplyWatch::isSuspect(quint8 slave, double nowMs)
{
    // A slave answers its requests in order, so the previous program's unanswered request to
    // it is answered before ours: once one exchange with it has been checked, none of its
    // replies can still be on the way. Only the first exchange with each slave is checked.
    if (nowMs < m_suspectAllUntilMs && !m_checkedSinceOpen.contains(slave))
        return true;
    forgetOver(&m_suspects, nowMs);
    return std::any_of(m_suspects.begin(), m_suspects.end(),
                       [slave](const Entry& e) { return e.slave == slave; });
}

} // namespace opentop
