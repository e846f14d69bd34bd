#include "tests/soak/SoakRun.h"

#include "model/bus/BusSpec.h"
#include "model/monitor/TrendHistory.h"
#include "tests/soak/GuiSoak.h"
#include "tests/soak/ModelSoak.h"
#include "tests/soak/ProcessProbe.h"
#include "tests/soak/SoakSim.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>

namespace opentop::soak {

namespace {

// How long the scans and the first samples of every drive may take.
constexpr qint64 kReadyTimeoutMs = 180000;
// How long the traffic logs may take to fill after that (20,000 frames: about two minutes at
// the soak's 87 transactions a second).
constexpr qint64 kFillTimeoutMs = 300000;

QString clockText(double seconds)
{
    const qint64 s = qint64(seconds + 0.5);
    return QStringLiteral("%1:%2").arg(s / 60, 3).arg(s % 60, 2, 10, QLatin1Char('0'));
}

} // namespace

SoakRun::SoakRun(const SoakOptions& options, QTextStream& out, QObject* parent)
    : QObject(parent)
    , m_options(options)
    , m_out(out)
{
}

SoakRun::~SoakRun()
{
    for (Measured& m : m_measured) {
        if (m.part)
            m.part->stop();
        if (m.sim)
            m.sim->stop();
    }
}

void SoakRun::start()
{
    QString error;
    const auto spec = BusSpec::parse(m_options.devices, &error);
    if (!spec || spec->isEmpty()) {
        abort(QStringLiteral("--devices: ") + error);
        return;
    }
    m_drives = int(spec->size());
    const QString guiProgram = QDir(m_options.binDir).filePath(QStringLiteral("opentop"));
    m_out << "opentop-soak: " << m_drives << " drives (" << m_options.devices << "), "
          << m_options.baud << " bit/s with wire timing, poll every " << m_options.pollMs
          << " ms per drive, " << m_options.minutes << " min, a line every "
          << m_options.intervalSeconds << " s" << Qt::endl;
    // The program first, alone: its scan of 1..247 has the line and the processor to itself
    // (a scan waits only a few ms per address); the model's part starts when it is done.
    if (m_options.gui) {
        Measured m;
        m.part = std::make_unique<GuiSoak>(guiProgram, m_options.baud, m_options.pollMs);
        m_measured.push_back(std::move(m));
    }
    if (m_options.model) {
        Measured m;
        m.part = std::make_unique<ModelSoak>(m_options.baud, m_options.pollMs);
        m_measured.push_back(std::move(m));
    }
    m_startMs = SoakPart::nowMs();
    if (!startNext())
        return;
    connect(&m_readyTimer, &QTimer::timeout, this, &SoakRun::waitUntilReady);
    m_readyTimer.start(250);
}

bool SoakRun::startNext()
{
    Measured& m = m_measured[size_t(m_started++)];
    QString error;
    m.sim = std::make_unique<SoakSim>();
    const QString simProgram = QDir(m_options.binDir).filePath(QStringLiteral("opentop-sim"));
    if (!m.sim->start(simProgram, m_options.devices, m_options.baud, &error)) {
        abort(m.part->name() + QStringLiteral(": ") + error);
        return false;
    }
    connect(m.sim.get(), &SoakSim::died, this, [this, name = m.part->name()](const QString& why) {
        abort(name + QStringLiteral(": ") + why);
    });
    connect(m.part.get(), &SoakPart::failed, this, &SoakRun::abort);
    if (!m.part->start(m.sim->pty(), &error)) {
        abort(m.part->name() + QStringLiteral(": ") + error);
        return false;
    }
    m_out << m.part->name() << ": monitoring " << m.sim->pty() << " (opentop-sim pid "
          << m.sim->pid() << ", measured pid "
          << (m.part->pid() ? m.part->pid() : QCoreApplication::applicationPid()) << ")"
          << Qt::endl;
    return true;
}

void SoakRun::waitUntilReady()
{
    if (m_done)
        return;
    // The part started last has found its drives: the next one may scan.
    if (m_started < int(m_measured.size()) &&
        m_measured[size_t(m_started - 1)].part->totals().drives >=
            SoakPart::kReadyShare * m_drives &&
        !startNext())
        return;
    bool ready = m_started == int(m_measured.size());
    for (const Measured& m : m_measured)
        ready = ready && m.part->isReady(m_drives);
    const qint64 now = SoakPart::nowMs();
    if (!ready) {
        // Once every drive was live, a moment without (a drive briefly stale) waits for the
        // traffic logs' time limit below.
        const bool late =
            m_liveMs == 0 ? now - m_startMs > kReadyTimeoutMs : now - m_liveMs > kFillTimeoutMs;
        if (late) {
            QStringList states;
            for (const Measured& m : m_measured) {
                const SoakPart::Totals t = m.part->totals();
                states << QStringLiteral("%1: %2 of %3 drives watched, %4 stale")
                              .arg(m.part->name())
                              .arg(t.drives)
                              .arg(m_drives)
                              .arg(t.stale);
            }
            abort(QStringLiteral("not every drive was monitored and live after %1 s (%2)")
                      .arg((now - m_startMs) / 1000)
                      .arg(states.join(QStringLiteral("; "))));
        }
        return;
    }
    if (m_liveMs == 0) {
        m_liveMs = now;
        for (const Measured& m : m_measured) {
            const SoakPart::Totals t = m.part->totals();
            m_out << m.part->name() << ": " << t.drives << " of " << m_drives << " drives monitored"
                  << (t.drives < m_drives ? " (its scan did not find the others)" : "") << Qt::endl;
            if (t.trafficCapacity > 0)
                m_out << m.part->name() << ": its traffic log holds " << t.trafficFrames
                      << " frames and keeps the last " << t.trafficCapacity
                      << "; the figures start when it is full" << Qt::endl;
        }
    }
    // The traffic log grows to its capacity by design: judged while filling, memory would
    // count it as growth (a soak once failed on it).
    bool full = true;
    for (const Measured& m : m_measured)
        full = full && m.part->buffersFull();
    if (!full) {
        if (now - m_liveMs > kFillTimeoutMs)
            abort(QStringLiteral("the traffic log was not full %1 s after every drive was live")
                      .arg(kFillTimeoutMs / 1000));
        return;
    }
    m_readyTimer.stop();
    m_readyMs = now;
    m_out << "monitoring settled after " << (now - m_startMs) / 1000.0
          << " s (every drive live after " << (m_liveMs - m_startMs) / 1000.0
          << " s); figures from now on (samples/s: per interval; lost: failed polls in it; "
             "stale: drives not live at that moment)"
          << Qt::endl;
    QString header = QStringLiteral("elapsed");
    for (const Measured& m : m_measured)
        header += QStringLiteral(" | %1: RSS MiB trends MiB    fds threads samples/s lost stale")
                      .arg(m.part->name(), -5);
    m_out << header << Qt::endl;
    for (Measured& m : m_measured)
        m.previous = m.part->totals();
    figureLine();
    connect(&m_lineTimer, &QTimer::timeout, this, &SoakRun::figureLine);
    m_lineTimer.start(int(m_options.intervalSeconds * 1000));
}

SoakPoint SoakRun::measure(Measured& m, double elapsedS)
{
    const ProcessFigures f = ProcessProbe::read(m.part->pid());
    const SoakPart::Totals t = m.part->totals();
    SoakPoint p;
    p.elapsedS = elapsedS;
    p.rssKb = f.rssKb;
    p.fds = f.fds;
    p.threads = f.threads;
    p.stale = t.stale;
    p.trendKb = t.trendPoints * qint64(sizeof(TrendHistory::Point)) / 1024;
    if (elapsedS > 0) {
        const double seconds = double(t.atMs - m.previous.atMs) / 1000.0;
        p.samplesPerS = seconds > 0 ? double(t.samples - m.previous.samples) / seconds : 0;
        p.lost = t.errors - m.previous.errors;
    }
    m.previous = t;
    return p;
}

void SoakRun::figureLine()
{
    const double elapsed = m_lines == 0 ? 0.0 : double(SoakPart::nowMs() - m_readyMs) / 1000.0;
    ++m_lines;
    QString line = clockText(elapsed).rightJustified(7);
    for (Measured& m : m_measured) {
        const SoakPoint p = measure(m, elapsed);
        m.points << p;
        line += QStringLiteral(" | %1: %2 %8 %3 %4 %5 %6 %7")
                    .arg(m.part->name(), -5)
                    .arg(double(p.rssKb) / 1024.0, 7, 'f', 1)
                    .arg(p.fds, 6)
                    .arg(p.threads, 7)
                    .arg(p.samplesPerS, 9, 'f', 1)
                    .arg(p.lost, 4)
                    .arg(p.stale, 5)
                    .arg(double(p.trendKb) / 1024.0, 10, 'f', 1);
    }
    m_out << line << Qt::endl;
    // The last line falls on the end of the run (timers drift by a few ms a line).
    if (elapsed + m_options.intervalSeconds / 2 >= m_options.minutes * 60)
        conclude();
}

void SoakRun::conclude()
{
    if (m_done)
        return;
    m_done = true;
    m_lineTimer.stop();
    const double total = m_options.minutes * 60;
    const double warmup =
        m_options.warmupSeconds >= 0 ? m_options.warmupSeconds : SoakGoals::warmupS(total);
    m_out << "summary after " << clockText(m_measured.front().points.last().elapsedS)
          << " (warm-up " << warmup << " s):" << Qt::endl;
    QStringList missed;
    for (const Measured& m : m_measured) {
        const SoakGoals::Summary s = SoakGoals::check(m.part->name(), m.points, total, warmup);
        for (const QString& l : SoakGoals::describe(s))
            m_out << "  " << l << Qt::endl;
        missed << s.missed;
        if (auto* gui = qobject_cast<GuiSoak*>(m.part.get())) {
            QFile err(gui->stderrPath());
            if (err.open(QIODevice::ReadOnly) && err.size() > 0)
                m_out << "  gui: " << err.size() << " bytes of warnings on stderr, first: "
                      << QString::fromLocal8Bit(err.readLine()).trimmed() << Qt::endl;
        }
    }
    for (Measured& m : m_measured) {
        m.part->stop();
        m.sim->stop();
    }
    m_out << (missed.isEmpty() ? "soak: every goal met" : "soak: FAILED, goals missed: ")
          << missed.join(QStringLiteral("; ")) << Qt::endl;
    emit finished(missed.isEmpty() ? Met : Missed);
}

void SoakRun::abort(const QString& why)
{
    if (m_done)
        return;
    m_done = true;
    m_readyTimer.stop();
    m_lineTimer.stop();
    m_out << "soak: cannot go on: " << why << Qt::endl;
    for (Measured& m : m_measured) {
        if (m.part)
            m.part->stop();
        if (m.sim)
            m.sim->stop();
    }
    // Asynchronously: abort() may run inside start() before the caller listens.
    QTimer::singleShot(0, this, [this] { emit finished(Broken); });
}

} // namespace opentop::soak
