#include "cli/ScanProgress.h"

#include <QCoreApplication>
#include <QFile>
#include <algorithm>
#include <unistd.h>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ScanProgress", text);
}

bool isTerminal(QTextStream& stream)
{
    auto* file = qobject_cast<QFile*>(stream.device());
    return file && file->handle() >= 0 && ::isatty(file->handle());
}

} // namespace

ScanProgress::ScanProgress(QTextStream& err)
    : m_err(err)
    , m_terminal(isTerminal(err))
{
}

void ScanProgress::update(int done, int total, int slave)
{
    if (m_terminal) {
        const QString line = tr("scanning %1/%2 (%3 %), machine number %4, %5 found")
                                 .arg(done)
                                 .arg(total)
                                 .arg(100 * done / total)
                                 .arg(slave)
                                 .arg(m_found);
        m_width = std::max(m_width, int(line.size()));
        m_err << '\r' << line.leftJustified(m_width);
        m_err.flush();
        return;
    }
    const int tenth = 10 * done / total;
    if (tenth <= m_lastTenth)
        return;
    m_lastTenth = tenth;
    m_err << tr("scan: %1 % (%2 of %3 machine numbers), %4 found")
                 .arg(100 * done / total)
                 .arg(done)
                 .arg(total)
                 .arg(m_found)
          << Qt::endl;
}

void ScanProgress::identificationRetry(int slave, int attempt, int attempts)
{
    clear();
    m_err << tr("scan: machine number %1 answered, identification failed: retrying (%2 of %3)…")
                 .arg(slave)
                 .arg(attempt)
                 .arg(attempts)
          << Qt::endl;
}

void ScanProgress::clear()
{
    if (m_terminal && m_width > 0) {
        m_err << '\r' << QString(m_width, QLatin1Char(' ')) << '\r';
        m_err.flush();
    }
}

} // namespace opentop
