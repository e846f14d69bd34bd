#pragma once

#include <QCoreApplication>
#include <QString>
#include <optional>

namespace opentop {

// What a variant probe changed, kept on disk while the drive holds the probe value: a station
// killed between the probe and its write-back leaves the entry, and the next probe of that
// drive (the restarted station's next unit, a retest, `recipe create`) puts the original value
// back first. One small JSON file per user (beside the results spool), written whole and
// renamed into place, so a kill leaves the old or the new file, never half of one. Entries are
// keyed by port and machine number: a drive on another bus is never touched.
class ProbeJournal
{
    Q_DECLARE_TR_FUNCTIONS(opentop::ProbeJournal)
public:
    struct Entry
    {
        QString parameter;
        QString original; // engineering value as text, as it is written back
        QString probe;    // the probe value as text: restored only while the drive holds it
    };

    explicit ProbeJournal(const QString& path = defaultPath());
    static QString defaultPath();

    std::optional<Entry> pending(const QString& port, int slave) const;
    // Before the probe is sent; false (with *error) when it cannot be kept: then nothing is
    // probed.
    bool begin(const QString& port, int slave, const Entry& entry, QString* error);
    // The drive holds its original value again (or another one nobody should overwrite).
    bool end(const QString& port, int slave, QString* error);

private:
    const QString m_path;
};

} // namespace opentop
