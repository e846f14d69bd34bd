#pragma once

#include "transport/ConnectionSettings.h"
#include "transport/LineFormat.h"

#include <QString>
#include <QStringList>
#include <QVector>

namespace opentop {

class ProfileRegistry;
struct DeviceInfo;

// Drives that talk another format than the port's do not answer it: a DBU works only at 8N1,
// a DC controller at 8E1 (factory), 8O1 or 8N2. What a scan at the port's format may have
// missed, and the formats a scan can also try (off by default: each is a pass of its own).
class LineFormatHint
{
public:
    struct Candidate
    {
        LineFormat format;
        int maxSlave = 247; // the highest machine number a drive of that format can have
        QStringList families;
    };

    // Every format a profiled drive can be set to, at the port's rate and at the profile's
    // default rate, that the port's format does not reach; the factory formats first.
    static QVector<Candidate> otherFormats(const ProfileRegistry& registry,
                                           const ConnectionSettings& port);
    // The families none of `found` belongs to whose factory format the port's does not reach,
    // in sentences; empty when there are none (a TCP gateway: its line is not ours). What to
    // do about it is the caller's to say (an option, a button).
    static QString missedText(const ProfileRegistry& registry, const ConnectionSettings& port,
                              const QVector<DeviceInfo>& found);
    // A profile's formatHelp with each numbered step ("2. Set …") on a line of its own.
    static QString asSteps(const QString& help);
    // The machine numbers the passes of `candidates` ask over `from`–`to`, for their cost.
    static int requestsFor(const QVector<Candidate>& candidates, int from, int to);
};

} // namespace opentop
