#include "cli/ScanFormats.h"

#include "cli/CliContext.h"
#include "model/bus/BusScanner.h"
#include "model/bus/LineFormatHint.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/ModbusClient.h"

#include <QCoreApplication>
#include <algorithm>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::ScanFormats", text);
}

bool known(const QVector<DeviceInfo>& devices, int slave)
{
    return std::any_of(devices.begin(), devices.end(), [slave](const DeviceInfo& d) {
        return d.slave == slave && d.state != DeviceInfo::State::Absent &&
               d.state != DeviceInfo::State::IdentifyFailed;
    });
}

} // namespace

bool ScanFormats::run(CliContext& context, int from, int to, int waitMs,
                      QVector<DeviceInfo>* devices, double* elapsedMs)
{
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    for (const LineFormatHint::Candidate& c :
         LineFormatHint::otherFormats(registry, context.client()->settings())) {
        const int last = std::min(to, c.maxSlave);
        if (last < from)
            continue;
        BusScanner pass(context.client(), registry);
        pass.setRange(from, last);
        pass.setWaitMs(waitMs);
        pass.setLine(c.format);
        context.err() << tr("Scanning machine numbers %1–%2 at %3 (--try-formats), %4 ms each…")
                             .arg(from)
                             .arg(last)
                             .arg(c.format.text())
                             .arg(pass.waitMs())
                      << Qt::endl;
        const bool completed = context.wait([&pass](std::function<void()> finish) {
            QObject::connect(&pass, &BusScanner::finished, &pass, [finish] { finish(); });
            pass.start();
        });
        if (!completed)
            pass.cancel();
        *elapsedMs += pass.elapsedMs();
        for (const DeviceInfo& info : pass.devices()) {
            // A drive found at the port's format answers this one too only if it hears it.
            if (info.state != DeviceInfo::State::Present || known(*devices, info.slave))
                continue;
            context.client()->setDriveLine(info.slave, c.format);
            // One that answered at the port's format but was not identified there is now.
            devices->erase(
                std::remove_if(devices->begin(), devices->end(),
                               [&info](const DeviceInfo& d) { return d.slave == info.slave; }),
                devices->end());
            const auto at =
                std::lower_bound(devices->begin(), devices->end(), info.slave,
                                 [](const DeviceInfo& d, int slave) { return d.slave < slave; });
            devices->insert(at, info);
            context.err() << tr("Machine number %1 answered at %2: it is asked at that format "
                                "from now on (--drive-format %1=%3).")
                                 .arg(info.slave)
                                 .arg(c.format.text(), c.format.token())
                          << Qt::endl;
        }
        if (!completed || (pass.wasCancelled() && context.interrupted()))
            return false;
    }
    return true;
}

void ScanFormats::hint(CliContext& context, int from, int to, const QVector<DeviceInfo>& devices)
{
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    const ConnectionSettings& port = context.client()->settings();
    const QString missed = LineFormatHint::missedText(registry, port, devices);
    if (missed.isEmpty())
        return;
    const QVector<LineFormatHint::Candidate> candidates =
        LineFormatHint::otherFormats(registry, port);
    double seconds = 0;
    for (const LineFormatHint::Candidate& c : candidates) {
        ConnectionSettings at = port;
        at.setLine(c.format);
        seconds += LineFormatHint::requestsFor({c}, from, to) *
                   BusScanner::defaultWaitMs(at, context.client()->adapterLatencyMs()) / 1000.0;
    }
    context.err() << tr("hint: %1 If one is on this bus, give its machine number its format "
                        "with --drive-format ID=BAUD:FORMAT (e.g. 7=9600:8E1), or scan with "
                        "--try-formats: %2 more passes, %3 more requests, about %4 s more.")
                         .arg(missed)
                         .arg(candidates.size())
                         .arg(LineFormatHint::requestsFor(candidates, from, to))
                         .arg(QString::number(seconds, 'f', seconds < 10 ? 1 : 0))
                  << Qt::endl;
}

} // namespace opentop
