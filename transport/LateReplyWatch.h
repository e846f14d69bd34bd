#pragma once

#include <QSet>
#include <QVector>
#include <optional>

namespace opentop {

class LineInput;
struct ModbusRequest;

// Which slaves may still answer a request that failed, for a master without transaction ids
// (LibmodbusBackend does the reading). Two records, all times in ms on the backend's clock:
// the waits after silent timeouts (until when a late reply from that slave could start, and the
// quiet time that ends it), and the suspects, whose replies are checked for another reply right
// behind them. What is remembered and when it is forgotten; the one look at the line is
// dueBefore()'s, whether bytes are arriving.
class LateReplyWatch
{
public:
    struct Wait
    {
        double untilMs = 0;
        int quietMs = 0;
    };

    // The port was opened at `nowMs`. The program that used the line before us may have left a
    // request unanswered (a CLI run that gave up, then exited): its late reply can reach our
    // first request of the same shape. Until that window has passed, every slave is a suspect
    // until its first exchange has been checked.
    void opened(double nowMs, int timeoutMs);
    void clear();

    // A request to `slave` timed out at `nowMs` with nothing received: the slave is a suspect,
    // a late reply may start until `untilMs`, and the line counts as quiet after `quietMs`
    // without a byte.
    void timedOut(quint8 slave, double nowMs, int timeoutMs, double untilMs, int quietMs);
    // Before sending `request` at `nowMs`: the waits not yet over as one (the latest end, the
    // longest quiet time), then forgotten, when they matter to it. A late reply from the slave
    // about to be asked again would look like its answer, and a broadcast gets no answer to
    // check at all; bytes already arriving on `input` are a reply in progress that would collide
    // with the request on the line. Otherwise none: a request to another slave goes out at once,
    // because a late reply carries its sender's id and is rejected as a wrong-slave reply.
    std::optional<Wait> dueBefore(const ModbusRequest& request, double nowMs,
                                  const LineInput& input);

    // A slave whose request failed may still answer it, later than any window: for a while
    // every reply from it is checked for another reply right behind it (issue 11's fault
    // matrix: a reply 1 s late answered a read of the same length).
    void suspect(quint8 slave, double nowMs, int timeoutMs);
    bool isSuspect(quint8 slave, double nowMs);
    struct Suspect
    {
        quint8 slave = 0;
        double untilMs = 0;
        quint8 function = 0; // with `count`, a request of this shape is unanswered; 0: none
        int count = 0;
    };
    // A suspect until `untilMs` whatever its exchanges show: the line's previous user gave up
    // on a request to it (LateReplyJournal), of the suspect's shape if it has one.
    void suspectUntil(const Suspect& suspect);
    // A request that got no answer it could take, at `nowMs`: until the suspect window is
    // over, a reply of its shape (function and length) may still be its late answer.
    void unanswered(const ModbusRequest& request, double nowMs, int timeoutMs);
    // A good reply to `request` may be the late answer to an earlier request of the same shape
    // to the same slave (unanswered(), or left by the line's previous user): it must be
    // confirmed (LibmodbusBackend reads again). Only that shape: a late reply of another
    // function or length fails RtuFrame::decodeReply's checks, and confirming every read of a
    // drive for seconds halved a monitor's rate after a scan.
    bool ambiguous(const ModbusRequest& request, double nowMs);
    // What is not yet over at `nowMs`, for the line's next user: each suspect slave (function
    // 0), and each unanswered shape.
    QVector<Suspect> suspects(double nowMs);
    // An exchange with `slave` went well with no reply behind it (or none looked for): a reply
    // the line's previous user left unanswered can no longer come from it (isSuspect()).
    void checked(quint8 slave) { m_checkedSinceOpen.insert(slave); }

private:
    struct Entry
    {
        quint8 slave = 0;
        Wait wait;
    };
    static void forgetOver(QVector<Entry>* entries, double nowMs);
    void forgetUnansweredOver(double nowMs);

    QVector<Entry> m_waits; // slaves that timed out silently, quiet time not yet over
    struct Shape
    {
        quint8 slave = 0;
        quint8 function = 0;
        int count = 0;
        double untilMs = 0;
    };
    QVector<Entry> m_suspects;       // slaves whose replies are checked for a second reply
    QVector<Shape> m_unanswered;     // requests whose late answer may still come
    double m_suspectAllUntilMs = 0;  // every slave is a suspect until then (opened())
    QSet<quint8> m_checkedSinceOpen; // slaves whose first exchange was checked (isSuspect())
};

} // namespace opentop
