#pragma once

#include "tests/soak/SoakPart.h"

#include <QProcess>
#include <QTemporaryDir>

namespace opentop::soak {

// The program as delivered: the opentop executable on the pty (offscreen), which scans the bus,
// opens the bus overview and the trends of every drive (--monitor-all) and prints its monitor
// hub's totals every second (--stats-every 1); the soak measures that process from /proc.
class GuiSoak : public SoakPart
{
    Q_OBJECT
public:
    GuiSoak(const QString& program, int baud, int pollMs, QObject* parent = nullptr);
    ~GuiSoak() override;

    QString name() const override { return QStringLiteral("gui"); }
    bool start(const QString& pty, QString* error) override;
    void stop() override;
    qint64 pid() const override { return m_process.processId(); }
    Totals totals() const override { return m_totals; }
    // What the program wrote on stderr (warnings), kept in a file.
    QString stderrPath() const;

    // Reads a "monitor: N drives, S samples, E errors, T stale, P trend points" line; false for
    // other lines.
    static bool parseTotals(const QString& line, Totals* totals);

private:
    void readLines();

    QString m_program;
    int m_baud;
    int m_pollMs;
    QTemporaryDir m_home; // the program's settings: neither the user's nor remembered
    QProcess m_process;
    Totals m_totals;
    bool m_stopping = false;
};

} // namespace opentop::soak
