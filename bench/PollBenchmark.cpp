#include "bench/PollBenchmark.h"

#include "bench/BenchReport.h"
#include "bench/PlainModbusLoop.h"
#include "bench/SimulatorProcess.h"
#include "bench/StackPoller.h"
#include "model/profile/ProfileRegistry.h"
#include "sim/WireTiming.h"
#include "transport/ModbusClient.h"
#include "transport/RtuBackend.h"

#include <algorithm>

namespace opentop {

namespace {

constexpr int kSlave = 1;
constexpr int kRounds = 5;

const Profile& dbu()
{
    return *ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
}

// OpenTOP's stack on `port`; frameGapMs < 0 keeps the protocol's inter-frame gap.
bool stackPoll(const ConnectionSettings& settings, double frameGapMs, const QStringList& names,
               double seconds, StackPoller::Result* result, QString* error)
{
    auto backend = std::make_unique<RtuBackend>(settings);
    backend->setFrameGapMs(frameGapMs);
    ModbusClient client(std::move(backend), settings);
    *error = client.openBlocking();
    if (!error->isEmpty())
        return false;
    *result = StackPoller::run(&client, dbu(), kSlave, names, seconds);
    if (result->transactions == 0 || result->failures > 0) {
        *error = QStringLiteral("%1 of %2 block reads failed")
                     .arg(result->failures)
                     .arg(result->transactions + result->failures);
        return false;
    }
    return true;
}

QVector<PlainModbusLoop::Block> plainBlocks(const QVector<ReadBlockPlan>& plan)
{
    QVector<PlainModbusLoop::Block> blocks;
    for (const ReadBlockPlan& b : plan)
        blocks << PlainModbusLoop::Block{b.function, b.address, b.count};
    return blocks;
}

} // namespace

QString PollBenchmark::description() const
{
    return QStringLiteral("a backup's block reads: OpenTOP's stack against a plain libmodbus "
                          "loop, and against the wire's limit at 19200 and 115200 bit/s");
}

bool PollBenchmark::run(const BenchEnvironment& env, BenchReport& report, QString* error)
{
    return stackOverhead(env, report, error) && wireFraction(env, 19200, report, error) &&
           wireFraction(env, 115200, report, error);
}

bool PollBenchmark::stackOverhead(const BenchEnvironment& env, BenchReport& report, QString* error)
{
    SimulatorProcess sim;
    // The drive hears only its own rate: the simulator at the rate both loops ask at.
    if (!sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@%1").arg(kSlave),
                    QStringLiteral("--baud"), QStringLiteral("115200")},
                   error))
        return false;
    QVector<ReadBlockPlan> plan;
    const QStringList names = StackPoller::backupSettings(dbu(), &plan);
    int registers = 0;
    for (const ReadBlockPlan& b : plan)
        registers += b.count;
    report.note(QStringLiteral("poll: a DBU200's backup reads (%1 settings in %2 blocks, %3 "
                               "registers) again and again; on a pty, no wire timing")
                    .arg(names.size())
                    .arg(plan.size())
                    .arg(registers));
    // Rounds alternate between the two, so a machine busy with something else for a while
    // weighs on both alike; the median round's ratio is judged.
    const double roundSeconds = std::max(0.5, env.seconds / kRounds);
    QVector<double> ratios;
    PlainModbusLoop::PollResult reference;
    StackPoller::Result stack;
    for (int round = 0; round < kRounds; ++round) {
        PlainModbusLoop::PollResult plainRound;
        {
            PlainModbusLoop plain(sim.pty(), 115200); // closed again before the stack opens it
            if (!plain.open(error))
                return false;
            plainRound = plain.poll(kSlave, plainBlocks(plan), roundSeconds);
        }
        if (plainRound.transactions == 0 || plainRound.errors > 0) {
            *error = QStringLiteral("the plain libmodbus loop failed %1 of %2 reads")
                         .arg(plainRound.errors)
                         .arg(plainRound.transactions + plainRound.errors);
            return false;
        }
        StackPoller::Result stackRound;
        if (!stackPoll(sim.lineSettings(115200), 0, names, roundSeconds, &stackRound, error))
            return false;
        ratios << plainRound.perSecond() / stackRound.perSecond();
        reference.transactions += plainRound.transactions;
        reference.seconds += plainRound.seconds;
        stack.transactions += stackRound.transactions;
        stack.seconds += stackRound.seconds;
    }
    std::sort(ratios.begin(), ratios.end());
    report.add(BenchFigure::plain(QStringLiteral("poll.plain_libmodbus"), reference.perSecond(),
                                  QStringLiteral("1/s"), 0, QStringLiteral("reference")));
    report.add(BenchFigure::plain(QStringLiteral("poll.stack"), stack.perSecond(),
                                  QStringLiteral("1/s"), 0));
    report.add(BenchFigure::atMost(
        QStringLiteral("poll.stack_cost"), ratios.at(kRounds / 2), QStringLiteral("x"), 1.10, 2,
        QStringLiteral("time per read against the plain loop; median of %1 rounds, %2 to %3")
            .arg(kRounds)
            .arg(ratios.first(), 0, 'f', 2)
            .arg(ratios.last(), 0, 'f', 2)));
    return true;
}

bool PollBenchmark::wireFraction(const BenchEnvironment& env, int baud, BenchReport& report,
                                 QString* error)
{
    SimulatorProcess sim;
    if (!sim.start({QStringLiteral("--devices"), QStringLiteral("dbu200@%1").arg(kSlave),
                    QStringLiteral("--wire-timing"), QStringLiteral("--half-duplex"),
                    QStringLiteral("--baud"), QString::number(baud)},
                   error))
        return false;
    QVector<ReadBlockPlan> plan;
    const QStringList names = StackPoller::backupSettings(dbu(), &plan);
    StackPoller::Result stack;
    if (!stackPoll(sim.lineSettings(baud), -1, names, env.seconds, &stack, error))
        return false;
    // Each read on the wire: request, gap, the simulator's default turnaround, reply, gap.
    const WireTiming wire(baud, 'N', 2.0);
    double planMs = 0;
    for (const ReadBlockPlan& b : plan)
        planMs += wire.frameMs(8) + wire.gapMs() + wire.turnaroundMs() +
                  wire.frameMs(5 + 2 * b.count) + wire.gapMs();
    const double limitMs = planMs / plan.size();
    const QString key = QStringLiteral("poll.wire_%1").arg(baud);
    report.add(BenchFigure::plain(key, stack.perSecond(), QStringLiteral("1/s"), 1));
    report.add(BenchFigure::plain(
        key + QStringLiteral(".limit"), 1000.0 / limitMs, QStringLiteral("1/s"), 1,
        QStringLiteral("%1 ms per read on the wire").arg(limitMs, 0, 'f', 2)));
    report.add(BenchFigure::atLeast(key + QStringLiteral(".fraction"),
                                    stack.perSecond() * limitMs / 1000.0, QStringLiteral("x"), 0.95,
                                    3, QStringLiteral("of the wire's limit")));
    return true;
}

} // namespace opentop
