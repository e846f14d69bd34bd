#pragma once

#include <QDateTime>
#include <QFile>
#include <QStringList>
#include <QTextStream>
#include <vector>

namespace opentop {

class MonitorOutput;
struct MonitorSample;

// The CSV file of `monitor --csv FILE`: a header (timestamp, slave, family, every drive's
// columns by key, note), a row per sample with an empty note, and a row where the link was
// lost or came back: its time and the note ("link lost", "link back"), every other cell empty,
// so that a gap in the samples is a gap in the file. docs/monitor.md describes the format.
class MonitorCsv
{
public:
    MonitorCsv() = default;
    MonitorCsv(const MonitorCsv&) = delete;
    MonitorCsv& operator=(const MonitorCsv&) = delete;

    // Truncates or creates `path`; false with *error when it cannot be written.
    bool open(const QString& path, QString* error);
    bool isOpen() const { return m_file.isOpen(); }
    QString fileName() const { return m_file.fileName(); }
    QString errorString() const { return m_file.errorString(); }

    // The header, from the drives' outputs (a column key shared by drives is one column).
    bool writeHeader(const std::vector<const MonitorOutput*>& outputs);
    bool writeSample(const MonitorOutput& output, const MonitorSample& sample);
    bool writeNote(const QDateTime& at, const QString& note);

    // The note column's texts (translated like the rest of the file's text).
    static QString linkLostNote();
    static QString linkBackNote();

private:
    bool writeRow(const QStringList& cells); // false: the write failed (a full disk)

    QFile m_file;
    QTextStream m_out;
    QStringList m_keys;
};

} // namespace opentop
