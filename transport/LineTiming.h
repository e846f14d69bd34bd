#pragma once

#include <QElapsedTimer>

namespace opentop {

// The times a master keeps for its line, in ms on one monotonic clock: when the current request
// went out, when the line last carried a frame, and the silences kept before the next frame:
// the inter-frame gap after any frame, the turnaround after a broadcast. Each silence is the
// line's own (the caller gives it: it follows the line's format) unless one is set.
class LineTiming
{
public:
    LineTiming();

    double nowMs() const { return double(m_clock.nsecsElapsed()) / 1e6; }
    // The current request goes out now.
    void sending();
    double sentAtMs() const { return m_sentAtMs; }
    // Since the current request was sent.
    double elapsedMs() const { return double(m_timer.nsecsElapsed()) / 1e6; }
    // The line carried a frame until `atMs` (on the clock).
    void activeUntil(double atMs) { m_activeAtMs = atMs; }
    // How much of a gap of `gapMs` after the last frame is still to come; <= 0 when none.
    double gapLeftMs(double gapMs) const { return m_activeAtMs + gapMs - nowMs(); }

    // < 0 restores the line's own.
    void setTurnaroundMs(int ms) { m_turnaroundMs = ms; }
    int turnaroundMs(int lineMs) const;
    void setFrameGapMs(double ms) { m_frameGapMs = ms; }
    double frameGapMs(double lineMs) const;

private:
    QElapsedTimer m_clock;
    QElapsedTimer m_timer;      // since the current request was sent
    double m_sentAtMs = 0;      // when the current request was sent
    double m_activeAtMs = -1e9; // the end of the last frame on the line
    int m_turnaroundMs = -1;
    double m_frameGapMs = -1;
};

} // namespace opentop
