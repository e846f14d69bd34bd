#pragma once

#include "transport/ConnectionSettings.h"

#include <QCommandLineParser>
#include <QString>
#include <optional>

namespace opentop {

// The connection options every OpenTOP program takes (--port, --tcp, --sim, --baud, ...), and
// their translation into ConnectionSettings with the defaults of the device family.
class ConnectionOptions
{
public:
    static void addTo(QCommandLineParser& parser);
    static QStringList names(); // the option names addTo() adds
    // True when --rs485, --rts-polarity, --rts-delay or --low-latency is given: they apply to
    // --port only, and fromParser() refuses them with anything else.
    static bool hasSerialLineOptions(const QCommandLineParser& parser);
    // `fallbackSim`: the simulated bus to use when no connection is named (the GUI's default);
    // empty means a connection must be named.
    // The first wrong value among the connection options given (a range, a family, a SPEC),
    // empty when they are all right; whether a bus is named at all is not checked here.
    static QString valueError(const QCommandLineParser& parser);
    static std::optional<ConnectionSettings> fromParser(const QCommandLineParser& parser,
                                                        const QString& fallbackSim, QString* error);

private:
    // The serial line's RS-485 and low-latency options into `s`; the first wrong value's
    // message, empty when they are right (and given with --port).
    static QString readSerialLine(const QCommandLineParser& parser, ConnectionSettings* s);
};

} // namespace opentop
