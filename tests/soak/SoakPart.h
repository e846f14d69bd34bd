#pragma once

#include <QObject>
#include <QString>

namespace opentop::soak {

// One way of monitoring every drive of the bus that the soak measures: the model's monitor hub
// in the soak's own process (ModelSoak), or the opentop program (GuiSoak).
class SoakPart : public QObject
{
    Q_OBJECT
public:
    // Running totals since monitoring began.
    struct Totals
    {
        int drives = 0;          // watched
        qint64 samples = 0;      // sample signals of the monitor hub
        qint64 errors = 0;       // failed polls (lost samples)
        int stale = 0;           // watched drives whose values are not live now (monitor/Freshness)
        qint64 trendPoints = 0;  // held by the watched drives' trend histories
        int trafficFrames = 0;   // held by the traffic log
        int trafficCapacity = 0; // the most it holds (0: the part keeps none)
        qint64 atMs = 0;         // when counted (steady clock, QDeadlineTimer::current)
    };

    using QObject::QObject;
    ~SoakPart() override;

    virtual QString name() const = 0;
    // Connects to the simulated bus on `pty` and starts monitoring; false with *error.
    virtual bool start(const QString& pty, QString* error) = 0;
    virtual void stop() = 0;
    // The process to measure (0: this one).
    virtual qint64 pid() const = 0;
    virtual Totals totals() const = 0;
    // Monitoring has settled: at least kReadyShare of the `drives` drives on the bus are
    // monitored (a scan on a loaded machine may miss a few late answers: the summary names how
    // many), each has answered, and none is stale.
    bool isReady(int drives) const;
    static constexpr double kReadyShare = 0.9;
    // The bounded buffers have reached their bound (the traffic log holds its last frames):
    // memory grows while they fill, by design, and is judged after.
    bool buffersFull() const;

    static qint64 nowMs();

signals:
    // Monitoring cannot go on (the program ended, the port was lost).
    void failed(const QString& why);
};

} // namespace opentop::soak
