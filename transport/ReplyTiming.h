#pragma once

namespace opentop {

// Whether a complete reply can physically be the answer to the request just sent: its last
// byte cannot arrive before the request has left the UART and the reply's own bytes have
// crossed the wire (the drive's turnaround only adds). A reply complete sooner was already on
// its way when we asked: a late answer to an earlier request (issue 28: a 35-byte reply taken
// "in 4.2 ms" at 19200 bit/s, where it takes 18 ms). Some lines carry no wire time (a pty to a
// simulator without --wire-timing, a virtual port): the rule learns from the clean exchanges
// whether the line keeps wire time and judges only where it does. Times in ms since sending.
class ReplyTiming
{
public:
    void reset();
    // A clean exchange (a good reply from a slave no late reply is feared from) took
    // `elapsedMs` where the wire needs `wireMs`.
    void learn(double elapsedMs, double wireMs);
    // True when the line keeps wire time and a reply complete after `elapsedMs` cannot have
    // crossed the wire in that time.
    bool tooEarly(double elapsedMs, double wireMs) const;
    // A rare fast exchange on a real line (a late reply whose own answer was lost) does not
    // switch the rule off for good; a line without wire time is fast every time.
    bool keepsWireTime() const { return m_slow >= kToLearn && m_fast * 20 <= m_slow; }

    // The share of the wire time a reply must have taken: a UART's clock may run a few per cent
    // fast, and the time a request went out is taken just before write().
    static constexpr double kMargin = 0.85;
    static constexpr int kToLearn = 2;

private:
    int m_slow = 0; // clean exchanges that took the wire time
    int m_fast = 0; // clean exchanges faster than any wire: the line has no wire time
};

} // namespace opentop
