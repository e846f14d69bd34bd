#pragma once

#include "tests/soak/SoakGoals.h"
#include "tests/soak/SoakOptions.h"
#include "tests/soak/SoakPart.h"

#include <QObject>
#include <QTextStream>
#include <QTimer>
#include <QVector>
#include <memory>
#include <vector>

namespace opentop::soak {

class SoakSim;

// The soak: one simulator per monitoring part, both parts started, then — once every drive is
// monitored and live — a figure line per interval, and the goals checked at the end.
class SoakRun : public QObject
{
    Q_OBJECT
public:
    // Exit codes: 0 every goal met, 1 a goal missed, 3 the soak could not run.
    enum Exit
    {
        Met = 0,
        Missed = 1,
        Broken = 3
    };

    SoakRun(const SoakOptions& options, QTextStream& out, QObject* parent = nullptr);
    ~SoakRun() override;

    // Starts everything; the run ends with finished(exit code).
    void start();

signals:
    void finished(int exitCode);

private:
    struct Measured
    {
        std::unique_ptr<SoakSim> sim;
        std::unique_ptr<SoakPart> part;
        SoakPart::Totals previous;
        QVector<SoakPoint> points;
    };

    bool startNext();
    void waitUntilReady();
    void figureLine();
    SoakPoint measure(Measured& m, double elapsedS);
    void conclude();
    void abort(const QString& why);

    SoakOptions m_options;
    QTextStream& m_out;
    std::vector<Measured> m_measured;
    int m_drives = 0;
    qint64 m_startMs = 0; // when the parts were started
    qint64 m_liveMs = 0;  // when every drive was first live in every part
    qint64 m_readyMs = 0; // when, moreover, every traffic log was full: elapsed 0
    QTimer m_readyTimer;
    QTimer m_lineTimer;
    int m_started = 0; // parts started so far, in m_measured's order
    int m_lines = 0;
    bool m_done = false;
};

} // namespace opentop::soak
