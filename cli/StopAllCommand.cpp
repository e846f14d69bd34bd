#include "cli/StopAllCommand.h"

#include "cli/CliContext.h"
#include "cli/TextTable.h"
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include "model/run/RunControl.h"
#include "transport/ConnectionSettings.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::StopAllCommand", text);
}

QString stateText(StopResult::State state)
{
    switch (state) {
    case StopResult::State::Stopped:
        return tr("stopped");
    case StopResult::State::StillRunning:
        return tr("STILL RUNNING");
    case StopResult::State::NoAnswer:
        return tr("no answer");
    }
    return QString();
}

QString stateKey(StopResult::State state)
{
    switch (state) {
    case StopResult::State::Stopped:
        return QStringLiteral("stopped");
    case StopResult::State::StillRunning:
        return QStringLiteral("still-running");
    case StopResult::State::NoAnswer:
        return QStringLiteral("no-answer");
    }
    return QString();
}

} // namespace

QString StopAllCommand::summary() const
{
    return tr("Broadcast stop to every drive, then confirm each has stopped (needs --yes)");
}

QList<QCommandLineOption> StopAllCommand::options() const
{
    return {
        {QStringLiteral("yes"), tr("Send the stop broadcast.")},
        {QStringLiteral("ids"),
         tr("Machine numbers to confirm, e.g. 1,2,5-7 (default on a simulated bus: its drives)."),
         tr("LIST")},
    };
}

int StopAllCommand::run(CliContext& context, const QStringList& args)
{
    QTextStream& out = context.out();
    QTextStream& err = context.err();
    if (!args.isEmpty()) {
        err << tr("error: usage: %1 (no other arguments)").arg(synopsis()) << Qt::endl;
        return ExitUsage;
    }
    std::optional<QVector<int>> ids;
    if (context.parser().isSet(QStringLiteral("ids"))) {
        QString error;
        ids = CliContext::parseIds(context.parser().value(QStringLiteral("ids")), &error);
        if (!ids) {
            err << tr("error: --ids: %1").arg(error) << Qt::endl;
            return ExitUsage;
        }
    }
    const QVector<RunControl::Broadcast> plan =
        RunControl::broadcastPlan(ProfileRegistry::builtIn());
    if (!context.parser().isSet(QStringLiteral("yes"))) {
        err << tr("Would broadcast to every drive on the bus (machine number 0, no reply):")
            << '\n';
        for (const RunControl::Broadcast& b : plan)
            err << "  " << b.family << ": " << b.description << '\n';
        err << tr("Add --yes to send it.") << Qt::endl;
        return ExitUsage;
    }
    if (!context.connectBus())
        return ExitCommunication;
    const bool simulated = context.settings().kind == ConnectionSettings::Kind::Simulated;
    const QVector<int> known = ids ? *ids : simulated ? context.knownSlaves() : QVector<int>();

    RunControl control(context.client(), ProfileRegistry::builtIn());
    RunControl::StopReport report;
    if (!context.wait([&](std::function<void()> finish) {
            control.stopAll(known, [&report, finish](const RunControl::StopReport& r) {
                report = r;
                finish();
            });
        }))
        return ExitInterrupted;

    QJsonArray broadcasts;
    for (const RunControl::Broadcast& b : report.broadcasts) {
        QJsonObject o{{QStringLiteral("family"), b.family},
                      {QStringLiteral("write"), b.description},
                      {QStringLiteral("sent"), b.sent}};
        if (!b.error.isEmpty())
            o.insert(QStringLiteral("error"), b.error);
        broadcasts.append(o);
        if (!context.json())
            out << (b.sent
                        ? tr("Broadcast %1: %2").arg(b.family, b.description)
                        : tr("Broadcast %1 FAILED: %2: %3").arg(b.family, b.description, b.error))
                << '\n';
    }
    QJsonArray drives;
    TextTable table({tr("ID"), tr("Family"), tr("State"), tr("Speed"), tr("After"), tr("Detail")});
    table.setRightAligned(0);
    table.setRightAligned(3);
    table.setRightAligned(4);
    for (const StopResult& r : report.drives) {
        const QString after =
            ValueCodec::formatNumber(r.elapsedMs / 1000.0, 1) + QStringLiteral(" s");
        table.addRow(
            {QString::number(r.slave), r.family, stateText(r.state), r.speedText, after, r.detail});
        QJsonObject o{{QStringLiteral("slave"), r.slave},
                      {QStringLiteral("family"), r.family},
                      {QStringLiteral("state"), stateKey(r.state)},
                      {QStringLiteral("seconds"), r.elapsedMs / 1000.0}};
        if (r.speed)
            o.insert(QStringLiteral("speed"), *r.speed);
        if (!r.detail.isEmpty())
            o.insert(QStringLiteral("detail"), r.detail);
        drives.append(o);
    }
    // Checked: the drives were asked afterwards. Confirmed: every one answered that it stopped.
    const bool checked = !known.isEmpty();
    const bool confirmed = checked && report.broadcastOk() && report.allStopped() &&
                           report.drives.size() == known.size();
    if (context.json()) {
        out << QJsonDocument(QJsonObject{{QStringLiteral("broadcasts"), broadcasts},
                                         {QStringLiteral("checked"), checked},
                                         {QStringLiteral("confirmed"), confirmed},
                                         {QStringLiteral("drives"), drives}})
                   .toJson(QJsonDocument::Indented);
    } else if (checked) {
        table.print(out);
    } else {
        out << tr("Only the broadcast was sent: drives do not answer a broadcast, so nothing "
                  "confirms that they stopped. To confirm, pass the machine numbers on this bus, "
                  "e.g. --ids 1,2,5-7 (opentop-cli scan finds them).")
            << '\n';
    }
    if (report.anyStillRunning())
        return ExitMismatch;
    if (report.anyNoAnswer() || !report.broadcastOk())
        return ExitCommunication;
    return ExitOk;
}

} // namespace opentop
