// libFuzzer harness: the traffic log's decoder. A frame seen on the wire (or a garbled one) is
// described with parameter names from the profile of the drive it concerns
// (TrafficDescriber::describe, which decodes a reply's registers from the bytes) and turned into
// the line --trace prints (TrafficEntry::toLine). Layout of the input: byte 0 picks the family,
// the direction and whether the drive is a group parent; byte 1 is the length of the request
// frame that follows (decoded with RtuFrame::decodeRequest as the log's request); the rest is
// the frame the entry carries. Nothing may read past the bytes given, whatever they claim.
#include "model/bus/BusGroups.h"
#include "model/profile/ProfileRegistry.h"
#include "model/traffic/TrafficDescriber.h"
#include "transport/ModbusRequest.h"
#include "transport/RtuFrame.h"
#include "transport/TrafficEntry.h"
#include <QByteArray>
#include <QDateTime>
#include <QTimeZone>
#include <algorithm>
#include <cstddef>
#include <cstdint>

using namespace opentop;

namespace {

const Profile* profileFor(uint8_t selector)
{
    const auto& profiles = ProfileRegistry::builtIn().profiles();
    if (profiles.isEmpty() || (selector & 3) == 3)
        return nullptr; // a drive of unknown family
    return &profiles[(selector & 3) % profiles.size()];
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size < 2)
        return 0;
    const uint8_t selector = data[0];
    const size_t requestLength = std::min<size_t>(data[1], size - 2);
    const QByteArray requestBytes(reinterpret_cast<const char*>(data + 2),
                                  static_cast<qsizetype>(requestLength));
    const QByteArray frame(reinterpret_cast<const char*>(data + 2 + requestLength),
                           static_cast<qsizetype>(size - 2 - requestLength));

    ModbusRequest request;
    const bool haveRequest = RtuFrame::decodeRequest(requestBytes, &request);

    TrafficEntry entry;
    entry.sequence = selector;
    entry.time = QDateTime::fromMSecsSinceEpoch(0, QTimeZone::utc());
    entry.direction = static_cast<TrafficEntry::Direction>((selector >> 2) % 3);
    entry.slave = frame.isEmpty() ? request.slave : quint8(frame[0]);
    entry.function = frame.size() < 2 ? request.function : quint8(frame[1]);
    entry.bytes = frame;
    entry.responseMs = (selector & 0x10) ? 12.5 : -1;
    if (selector & 0x20)
        entry.error = QStringLiteral("CRC error");

    const Profile* profile = profileFor(selector);
    TrafficDescriber describer([profile](int) { return profile; });
    if (selector & 0x40) { // the request's drive is a group parent of two others
        BusGroups groups;
        groups.addDrive(request.slave);
        groups.setGroup(request.slave == 2 ? 3 : 2, request.slave);
        groups.setGroup(request.slave == 4 ? 5 : 4, request.slave);
        describer.setGroups(groups);
    }
    entry.summary = describer.describe(entry, haveRequest ? &request : nullptr);
    (void)entry.toLine();
    (void)entry.directionText();
    return 0;
}
