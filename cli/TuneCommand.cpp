#include "cli/TuneCommand.h"

#include "cli/CliContext.h"
#include "model/io/DisplayText.h"
#include "model/io/OutputFile.h"
#include "model/session/DeviceSession.h"
#include "model/tuning/TuningRunner.h"
#include "model/tuning/TuningVerdict.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::TuneCommand", text);
}

QString ms(const std::optional<double>& v)
{
    return v ? QStringLiteral("%1 ms").arg(*v, 0, 'f', 0) : tr("not reached");
}

QJsonObject gainsJson(const PidGains& g)
{
    return {{QStringLiteral("p"), g.p},
            {QStringLiteral("i"), g.i},
            {QStringLiteral("d"), g.d},
            {QStringLiteral("d_period_ms"), g.dPeriodMs}};
}

QString samplesCsv(const TuningRunner::Result& r)
{
    QString text = QStringLiteral("# gains: %1\nt_ms,command,speed,current_A,output_pct\n")
                       .arg(r.gains.toString());
    for (const TuningSample& s : r.samples)
        text += QStringLiteral("%1,%2,%3,%4,%5\n")
                    .arg(s.tMs, 0, 'f', 1)
                    .arg(s.command)
                    .arg(s.speed)
                    .arg(s.current)
                    .arg(s.output);
    return text;
}

// Runs until `start`'s callback. Ctrl-C (or SIGTERM) cancels the test, which stops the motor and
// confirms the stop: the command still waits for that, so no way out leaves the motor running.
bool awaitRunner(CliContext& context, TuningRunner& runner,
                 const std::function<void(std::function<void()>)>& start)
{
    QEventLoop loop;
    bool finished = false;
    bool interrupted = false;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (context.interrupted() && !interrupted) {
            interrupted = true;
            runner.cancel();
        }
    });
    poll.start(50);
    start([&finished, &loop] {
        finished = true;
        loop.quit();
    });
    if (!finished)
        loop.exec();
    return !interrupted;
}

} // namespace

QString TuneCommand::summary() const
{
    return tr("Speed-loop step test and relay autotune of a DC controller (needs --yes)");
}

QList<QCommandLineOption> TuneCommand::options() const
{
    return {
        {QStringLiteral("yes"), tr("Run the test (it moves the motor).")},
        {QStringLiteral("from"), tr("step: speed before the step (default 0)."), tr("SPEED")},
        {QStringLiteral("to"), tr("step: speed after the step."), tr("SPEED")},
        {QStringLiteral("record"), tr("step: record this long after the step (default 1500)."),
         tr("MS")},
        {QStringLiteral("speed"), tr("autotune: operating speed of the relay test."), tr("SPEED")},
        {QStringLiteral("amplitude"), tr("autotune: output swing, % of full output (default 10)."),
         tr("PERCENT")},
        {QStringLiteral("rule"),
         tr("autotune: soft, medium (default), stiff, tyreus-luyben or zn-pi."), tr("RULE")},
        {QStringLiteral("accept"), tr("autotune: write the proposed gains, then run a step test "
                                      "from half the operating speed to it.")},
        {QStringLiteral("store"),
         tr("autotune: with --accept, store the gains in the drive if the step measured with "
            "them passes the check.")},
        {QStringLiteral("override-check"),
         tr("autotune: with --accept, keep (and with --store, store) gains whose measured step "
            "failed the check; without it they are written back to what the drive had.")},
        {QStringLiteral("max-speed"),
         tr("Stop at once beyond this speed (default 120 % of the test's highest)."), tr("SPEED")},
        {QStringLiteral("max-current"), tr("Stop at once beyond this current in A (default 20)."),
         tr("A")},
        {QStringLiteral("csv"), tr("Write the samples to FILE."), tr("FILE")},
    };
}

int TuneCommand::run(CliContext& context, const QStringList& args)
{
    QTextStream& out = context.out();
    QTextStream& err = context.err();
    const QCommandLineParser& p = context.parser();
    QString error;
    const auto ids = args.isEmpty() ? std::nullopt : CliContext::parseIds(args.first(), &error);
    const QString what = args.value(1);
    if (!ids || ids->size() != 1 || args.size() != 2 ||
        (what != QLatin1String("step") && what != QLatin1String("autotune"))) {
        err << tr("error: usage: %1").arg(synopsis()) << Qt::endl;
        return ExitUsage;
    }
    const auto number = [&](const char* option, double fallback, bool* ok) {
        const QString name = QString::fromLatin1(option);
        if (!p.isSet(name))
            return fallback;
        bool good = false;
        const double v = p.value(name).toDouble(&good);
        if (!good || v < 0) {
            err << tr("error: --%1 must be a number 0 or more, got '%2'").arg(name, p.value(name))
                << Qt::endl;
            *ok = false;
        }
        return v;
    };
    bool ok = true;
    const bool step = what == QLatin1String("step");
    const double from = number("from", 0, &ok);
    const double to = number("to", -1, &ok);
    const double speed = number("speed", -1, &ok);
    const double amplitude = number("amplitude", 10, &ok);
    const double record = number("record", 1500, &ok);
    const double highest = step ? std::max(from, to) : speed;
    const double maxSpeed = number("max-speed", highest * 1.2, &ok);
    const double maxCurrent = number("max-current", 20, &ok);
    const auto rule = TuningRules::fromId(p.value(QStringLiteral("rule")).isEmpty()
                                              ? QStringLiteral("medium")
                                              : p.value(QStringLiteral("rule")));
    if (!ok)
        return ExitUsage;
    if ((step && to < 0) || (!step && speed <= 0) || !rule) {
        err << tr("error: %1")
                   .arg(step    ? tr("step needs --to SPEED")
                        : !rule ? tr("--rule must be one of %1")
                                      .arg(TuningRules::ids().join(QStringLiteral(", ")))
                                : tr("autotune needs --speed SPEED"))
            << Qt::endl;
        return ExitUsage;
    }
    const int slave = ids->first();
    DeviceSession* session = context.session(slave, &error);
    if (!session) {
        err << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitCommunication;
    }
    const std::optional<TuningSpec> spec = TuningSpec::of(session->profile(), &error);
    if (!spec) {
        err << tr("error: %1").arg(DisplayText::escapedLines(error)) << Qt::endl;
        return ExitInvalid;
    }
    if (!p.isSet(QStringLiteral("yes"))) {
        err << (step ? tr("Would run the motor of machine number %1 from %2 to %3 and record "
                          "the step response.")
                           .arg(slave)
                           .arg(from)
                           .arg(to)
                     : tr("Would run the motor of machine number %1 in a relay test around %2 "
                          "(output ±%3 %).")
                           .arg(slave)
                           .arg(speed)
                           .arg(amplitude))
            << '\n'
            << tr("This moves the motor: add --yes to run it.") << Qt::endl;
        return ExitUsage;
    }

    TuningRunner runner(session, *spec);
    TuningRunner::Limits limits;
    limits.maxSpeed = maxSpeed;
    limits.maxCurrent = maxCurrent;
    runner.setLimits(limits);
    if (!context.json())
        QObject::connect(&runner, &TuningRunner::phase, &runner,
                         [&err](const QString& text) { err << text << Qt::endl; });
    const auto runStep = [&](double a, double b, TuningRunner::Result* result) {
        TuningRunner::StepPlan plan;
        plan.from = a;
        plan.to = b;
        plan.recordMs = int(record);
        return awaitRunner(context, runner, [&](std::function<void()> finish) {
            runner.startStep(plan, [result, finish](const TuningRunner::Result& r) {
                *result = r;
                finish();
            });
        });
    };
    QJsonObject json{{QStringLiteral("slave"), slave}, {QStringLiteral("test"), what}};
    TuningRunner::Result result;
    TuningRunner::Result check;
    bool interrupted = false;
    if (step) {
        interrupted = !runStep(from, to, &result);
    } else {
        TuningRunner::RelayPlan plan;
        plan.speed = speed;
        plan.amplitude = amplitude;
        plan.rule = *rule;
        interrupted = !awaitRunner(context, runner, [&](std::function<void()> finish) {
            runner.startAutotune(plan, [&result, finish](const TuningRunner::Result& r) {
                result = r;
                finish();
            });
        });
    }
    const QString unit = result.speedUnit;
    json.insert(QStringLiteral("ok"), result.ok);
    json.insert(QStringLiteral("gains"), gainsJson(result.gains));
    json.insert(QStringLiteral("stop_confirmed"), result.stopConfirmed);
    if (!result.error.isEmpty())
        json.insert(QStringLiteral("error"), result.error);
    QStringList lines;
    lines << tr("Machine number %1, gains %2").arg(slave).arg(result.gains.toString());
    const auto metricsLines = [&](const StepMetrics& m) {
        lines << tr("  rise time (10–90 %): %1").arg(ms(m.riseMs))
              << tr("  overshoot: %1 %").arg(m.overshootPercent, 0, 'f', 1)
              << tr("  settling time (2 %): %1").arg(ms(m.settlingMs))
              << tr("  steady-state error: %1 %2").arg(m.steadyStateError, 0, 'f', 1).arg(unit)
              << tr("  peak current: %1 A").arg(m.peakCurrent, 0, 'f', 2);
    };
    const auto writeGains = [&](const PidGains& gains, QString* why) {
        bool written = false;
        awaitRunner(context, runner, [&](std::function<void()> finish) {
            runner.writeGains(
                gains, [&written, why, finish](bool good, const PidGains&, const QString& e) {
                    written = good;
                    *why = e;
                    finish();
                });
        });
        return written;
    };
    const auto metricsJson = [](const StepMetrics& m) {
        QJsonObject o{{QStringLiteral("overshoot_pct"), m.overshootPercent},
                      {QStringLiteral("steady_state_error"), m.steadyStateError},
                      {QStringLiteral("peak_current_a"), m.peakCurrent}};
        if (m.riseMs)
            o.insert(QStringLiteral("rise_ms"), *m.riseMs);
        if (m.settlingMs)
            o.insert(QStringLiteral("settling_ms"), *m.settlingMs);
        return o;
    };
    int code = result.ok ? ExitOk : result.aborted ? ExitFail : ExitInvalid;
    if (result.ok && step) {
        lines << tr("Step %1 → %2 %3:").arg(from).arg(to).arg(unit);
        metricsLines(result.metrics);
        json.insert(QStringLiteral("metrics"), metricsJson(result.metrics));
    } else if (result.ok) {
        const StepMetrics& predicted = result.predictedMetrics;
        lines << tr("Relay test: Ku %1, Tu %2 ms measured (amplitude ±%3 %4, %5 cycles, %6 "
                    "readings per period, one every %7 ms)")
                     .arg(result.relay.ultimateGain, 0, 'g', 4)
                     .arg(result.relay.periodMs, 0, 'f', 1)
                     .arg(result.relay.amplitude, 0, 'f', 1)
                     .arg(unit)
                     .arg(result.relay.cycles)
                     .arg(result.relay.readingsPerPeriod, 0, 'f', 1)
                     .arg(result.relay.readingMs, 0, 'f', 1)
              << tr("Model: gain %1, time constant %2 ms, dead time %3 ms (the bus's %4 ms "
                    "left out)")
                     .arg(result.plant.gain, 0, 'g', 4)
                     .arg(result.plant.tauMs, 0, 'f', 1)
                     .arg(result.plant.deadMs, 0, 'f', 1)
                     .arg(result.busDelayMs, 0, 'f', 1)
              << tr("The drive's own loop on the model: Ku %1, Tu %2 ms")
                     .arg(result.ultimateGain, 0, 'g', 4)
                     .arg(result.ultimatePeriodMs, 0, 'f', 1)
              << tr("Proposed (%1): %2").arg(TuningRules::title(*rule), result.proposal.toString())
              << tr("  the rule's P × %1, Ti × %2; predicted step %3 → %4 %5: overshoot %6 %, "
                    "settling time %7")
                     .arg(result.kpScale, 0, 'g', 3)
                     .arg(result.tiScale, 0, 'g', 3)
                     .arg(speed / 2)
                     .arg(speed)
                     .arg(unit)
                     .arg(predicted.overshootPercent, 0, 'f', 1)
                     .arg(ms(predicted.settlingMs));
        json.insert(QStringLiteral("ku"), result.relay.ultimateGain);
        json.insert(QStringLiteral("tu_ms"), result.relay.periodMs);
        json.insert(QStringLiteral("readings_per_period"), result.relay.readingsPerPeriod);
        json.insert(QStringLiteral("proposal"), gainsJson(result.proposal));
        json.insert(QStringLiteral("predicted"), metricsJson(predicted));
        if (p.isSet(QStringLiteral("accept")) && !interrupted) {
            if (!writeGains(result.proposal, &error)) {
                lines << tr("Writing the proposed gains failed: %1").arg(error);
                code = ExitCommunication;
            } else {
                lines << tr("Proposed gains written (not stored).");
                interrupted = !runStep(speed / 2, speed, &check);
                if (check.ok) {
                    lines << tr("Measured step %1 → %2 %3 with them:")
                                 .arg(speed / 2)
                                 .arg(speed)
                                 .arg(unit);
                    metricsLines(check.metrics);
                    json.insert(QStringLiteral("measured"), metricsJson(check.metrics));
                }
                const TuningVerdict verdict = interrupted
                                                  ? TuningVerdict::notMeasured(tr("interrupted"))
                                                  : TuningVerdict::judge(check, predicted);
                const bool override = p.isSet(QStringLiteral("override-check"));
                lines << (verdict.passed ? tr("Check after Accept: passed. %1")
                                         : tr("Check after Accept: FAILED. %1"))
                             .arg(verdict.text());
                json.insert(QStringLiteral("check"),
                            QJsonObject{{QStringLiteral("passed"), verdict.passed},
                                        {QStringLiteral("findings"),
                                         QJsonArray::fromStringList(verdict.findings)}});
                if (!verdict.passed && !override) {
                    // Reject, as the window offers first: the gains the drive had go back.
                    const bool restored = writeGains(result.gains, &error);
                    lines << (restored ? tr("The gains before were written back (%1); nothing "
                                            "was stored. --override-check keeps the proposal "
                                            "(and with --store stores it) all the same.")
                                             .arg(result.gains.toString())
                                       : tr("Writing back the gains before failed: %1; the "
                                            "proposal is still in the drive (not stored).")
                                             .arg(error));
                    json.insert(QStringLiteral("restored"), restored);
                    code = restored ? (interrupted ? code : int(ExitFail)) : ExitCommunication;
                } else if (p.isSet(QStringLiteral("store")) && !interrupted) {
                    if (!verdict.passed)
                        lines << tr("Storing although the check failed (--override-check).");
                    bool stored = false;
                    awaitRunner(context, runner, [&](std::function<void()> finish) {
                        runner.storeGains([&stored, &error, finish](bool good, const QString& why) {
                            stored = good;
                            error = why;
                            finish();
                        });
                    });
                    lines << (stored ? tr("Gains stored in the drive.")
                                     : tr("Storing the gains failed: %1").arg(error));
                    code = stored ? code : ExitCommunication;
                }
            }
        }
    }
    if (!result.ok)
        lines << tr("Test ended: %1").arg(result.error);
    if (!result.ok && !result.advice.isEmpty()) {
        lines << tr("What to change: %1").arg(result.advice);
        json.insert(QStringLiteral("advice"), result.advice);
    }
    if (!result.stopDetail.isEmpty())
        lines << result.stopDetail;
    if (!result.stopConfirmed || (check.samples.size() && !check.stopConfirmed))
        code = ExitMismatch;
    if (p.isSet(QStringLiteral("csv"))) {
        QString why;
        if (!OutputFile::write(p.value(QStringLiteral("csv")), samplesCsv(result).toUtf8(), &why)) {
            err << tr("error: %1").arg(DisplayText::escapedLines(why)) << Qt::endl;
            code = code == ExitOk ? ExitCommunication : code;
        }
    }
    if (context.json())
        out << QJsonDocument(json).toJson(QJsonDocument::Compact) << '\n';
    else
        out << lines.join(QLatin1Char('\n')) << '\n';
    return interrupted && code != ExitMismatch ? int(ExitInterrupted) : code;
}

} // namespace opentop
