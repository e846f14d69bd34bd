#include "ui/alarms/AlarmExport.h"

#include "model/bus/BusDrives.h"
#include "model/io/DisplayText.h"
#include "model/io/OutputFile.h"
#include "model/session/DeviceSession.h"
#include "ui/alarms/AlarmRecordsView.h"

#include <QPointer>

namespace opentop {

namespace {

// A cell made safe for a spreadsheet (DisplayText::csvCell: no control character, no formula),
// then quoted when it must be.
QString field(const QString& cell)
{
    const QString text = DisplayText::csvCell(cell);
    static const QString special = QStringLiteral(",\"");
    bool quote = false;
    for (const QChar c : text)
        quote = quote || special.contains(c);
    if (!quote)
        return text;
    QString escaped = text;
    escaped.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + escaped + QLatin1Char('"');
}

QString row(const QStringList& fields)
{
    QStringList quoted;
    for (const QString& f : fields)
        quoted << field(f);
    return quoted.join(QLatin1Char(',')) + QStringLiteral("\r\n");
}

} // namespace

AlarmExport::AlarmExport(BusDrives* drives, QObject* parent)
    : QObject(parent)
    , m_drives(drives)
{
}

QString AlarmExport::csv(const QVector<DriveReport>& reports)
{
    QString text =
        row({tr("Machine"), tr("Machine name"), tr("Model"), tr("Kind"), tr("Record"), tr("Code"),
             tr("Panel code"), tr("Name"), tr("Cleared by"), tr("Cause"), tr("Remedy")});
    for (const DriveReport& d : reports) {
        for (const AlarmHistory::History& h : d.report.histories) {
            const QString kind = h.table == QLatin1String("alarm")     ? tr("alarm")
                                 : h.table == QLatin1String("warning") ? tr("warning")
                                                                       : h.table;
            for (const AlarmHistory::Record& r : h.records) {
                if (r.empty)
                    continue;
                const std::optional<CodeEntry>& e = r.entry;
                text += row({QString::number(d.slave), d.name, d.model, kind,
                             QString::number(r.index), AlarmRecordsView::codeText(r.code),
                             e ? e->panel : QString(), e ? e->name : tr("unknown code"),
                             e ? AlarmRecordsView::clearedByText(e->reset) : QString(),
                             e ? e->cause : QString(), e ? e->remedy : QString()});
            }
        }
    }
    return text;
}

bool AlarmExport::exportTo(const QString& path)
{
    if (m_busy)
        return false;
    m_busy = true;
    m_path = path;
    m_queue = m_drives->slaves();
    m_reports.clear();
    m_errors.clear();
    readNext();
    return true;
}

void AlarmExport::readNext()
{
    while (!m_queue.isEmpty()) {
        const int slave = m_queue.takeFirst();
        DeviceSession* session = m_drives->session(slave);
        if (!session)
            continue;
        // Parented to the session, so that it goes with a drive removed meanwhile.
        auto* history = new AlarmHistory(session, session);
        if (!history->supported()) {
            delete history;
            continue;
        }
        DriveReport d;
        d.slave = slave;
        d.model = m_drives->info(slave).model;
        d.name = m_drives->name(slave);
        QPointer<AlarmExport> self(this);
        history->read([self, history, d](const AlarmHistory::Report& report) mutable {
            history->deleteLater();
            if (!self)
                return;
            d.report = report;
            if (!report.ok)
                self->m_errors << tr("machine %1: %2")
                                      .arg(d.slave)
                                      .arg(report.errors.join(QStringLiteral("; ")));
            self->m_reports << d;
            self->readNext();
        });
        return;
    }
    writeFile();
}

void AlarmExport::writeFile()
{
    m_busy = false;
    int records = 0;
    for (const DriveReport& d : m_reports)
        for (const AlarmHistory::History& h : d.report.histories)
            records += h.used();
    QString error;
    if (!OutputFile::write(m_path, csv(m_reports).toUtf8(), &error)) {
        emit finished(false, error); // "cannot write PATH: why"
        return;
    }
    QString message = tr("%n record(s) of %1 drive(s) written to %2.", nullptr, records)
                          .arg(m_reports.size())
                          .arg(m_path);
    if (!m_errors.isEmpty())
        message += QLatin1Char(' ') +
                   tr("Not everything could be read: %1").arg(m_errors.join(QStringLiteral("; ")));
    emit finished(m_errors.isEmpty(), message);
}

} // namespace opentop
