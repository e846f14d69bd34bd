#pragma once

#include <QString>
#include <QTextStream>

namespace opentop {

// The scan's progress on standard error: one updating line on a terminal, a line per 10 %
// otherwise (a log file or a CI job should not fill up with carriage returns), and a line of
// its own for an address that answered but is being identified again.
class ScanProgress
{
public:
    explicit ScanProgress(QTextStream& err);

    void deviceFound() { ++m_found; }
    void update(int done, int total, int slave);
    // `slave` answered, but its identification failed; it is asked again.
    void identificationRetry(int slave, int attempt, int attempts);
    // Removes the updating line before the results are printed.
    void clear();

private:
    QTextStream& m_err;
    bool m_terminal;
    int m_lastTenth = 0;
    int m_found = 0;
    int m_width = 0;
};

} // namespace opentop
