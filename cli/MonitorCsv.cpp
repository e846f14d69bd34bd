#include "cli/MonitorCsv.h"

#include "cli/MonitorOutput.h"
#include "model/monitor/DeviceMonitor.h"

#include <QCoreApplication>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::MonitorCsv", text);
}

} // namespace

bool MonitorCsv::open(const QString& path, QString* error)
{
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        if (error)
            *error = m_file.errorString();
        return false;
    }
    m_out.setDevice(&m_file);
    return true;
}

QString MonitorCsv::linkLostNote()
{
    return tr("link lost");
}

QString MonitorCsv::linkBackNote()
{
    return tr("link back");
}

bool MonitorCsv::writeHeader(const std::vector<const MonitorOutput*>& outputs)
{
    for (const MonitorOutput* output : outputs) {
        for (const MonitorOutput::Column& c : output->columns()) {
            if (!m_keys.contains(c.key))
                m_keys << c.key;
        }
    }
    // "note" comes last: the columns before it are those of files written before it existed.
    QStringList header{QStringLiteral("timestamp"), QStringLiteral("slave"),
                       QStringLiteral("family")};
    for (const QString& k : m_keys)
        header << MonitorOutput::csvEscape(k);
    header << QStringLiteral("note");
    return writeRow(header);
}

bool MonitorCsv::writeSample(const MonitorOutput& output, const MonitorSample& s)
{
    const QStringList cells = output.csvCells(s);
    QStringList row{MonitorOutput::isoTime(s.timestamp), QString::number(s.slave), output.family()};
    for (const QString& key : m_keys) {
        int column = -1;
        for (int i = 0; i < output.columns().size(); ++i)
            column = output.columns()[i].key == key ? i : column;
        row << MonitorOutput::csvEscape(column >= 0 ? cells.value(column) : QString());
    }
    row << QString(); // no note
    return writeRow(row);
}

bool MonitorCsv::writeNote(const QDateTime& at, const QString& note)
{
    QStringList row{MonitorOutput::isoTime(at), QString(), QString()};
    for (int i = 0; i < m_keys.size(); ++i)
        row << QString();
    row << MonitorOutput::csvEscape(note);
    return writeRow(row);
}

bool MonitorCsv::writeRow(const QStringList& cells)
{
    m_out << cells.join(QLatin1Char(',')) << '\n';
    m_out.flush();
    return m_out.status() == QTextStream::Ok && m_file.error() == QFileDevice::NoError;
}

} // namespace opentop
