#include "model/bus/LineFormatHint.h"

#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceInfo.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <algorithm>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::LineFormatHint", text);
}

LineFormat factoryFormat(const Profile& p)
{
    return LineFormat{p.serial.baud, p.serial.parity, 8, p.serial.stopBits};
}

} // namespace

QVector<LineFormatHint::Candidate> LineFormatHint::otherFormats(const ProfileRegistry& registry,
                                                                const ConnectionSettings& port)
{
    QVector<Candidate> out;
    if (port.kind == ConnectionSettings::Kind::Tcp)
        return out;
    const LineFormat portLine = port.line();
    auto add = [&](const LineFormat& f, const Profile& p) {
        if (f.hears(portLine))
            return;
        for (Candidate& c : out) {
            if (c.format.hears(f) && f.hears(c.format)) {
                c.maxSlave = std::max(c.maxSlave, p.maxSlave);
                if (!c.families.contains(p.family))
                    c.families << p.family;
                return;
            }
        }
        out << Candidate{f, p.maxSlave > 0 ? p.maxSlave : 247, {p.family}};
    };
    for (const Profile& p : registry.profiles())
        add(factoryFormat(p), p);
    for (const Profile& p : registry.profiles()) {
        for (int baud : {p.serial.baud, portLine.baud}) {
            if (!p.serial.bauds.isEmpty() && !p.serial.bauds.contains(baud))
                continue;
            for (const QString& frame : p.serial.formats)
                if (const auto f = LineFormat::parse(frame, baud))
                    add(*f, p);
        }
    }
    return out;
}

QString LineFormatHint::missedText(const ProfileRegistry& registry, const ConnectionSettings& port,
                                   const QVector<DeviceInfo>& found)
{
    if (port.kind == ConnectionSettings::Kind::Tcp)
        return QString();
    QStringList missed;
    for (const Profile& p : registry.profiles()) {
        const bool seen = std::any_of(found.begin(), found.end(),
                                      [&p](const DeviceInfo& d) { return d.family == p.family; });
        const LineFormat factory = factoryFormat(p);
        if (seen || factory.hears(port.line()))
            continue;
        missed << tr("%1: %2 from the factory (it can be set to %3).")
                      .arg(p.name, factory.text(), p.serial.formats.join(QStringLiteral(", ")));
    }
    if (missed.isEmpty())
        return QString();
    return tr("Drives set to another line format than %1 do not answer it. %2")
        .arg(port.line().text(), missed.join(QLatin1Char(' ')));
}

QString LineFormatHint::asSteps(const QString& help)
{
    // After a sentence's full stop (also the CJK one), before "N. ".
    static const QRegularExpression step(QStringLiteral("(?<=[.。])\\s?(?=[1-9]\\. )"));
    return QString(help).replace(step, QStringLiteral("\n"));
}

int LineFormatHint::requestsFor(const QVector<Candidate>& candidates, int from, int to)
{
    int count = 0;
    for (const Candidate& c : candidates)
        count += std::max(0, std::min(to, c.maxSlave) - from + 1);
    return count;
}

} // namespace opentop
