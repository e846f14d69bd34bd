// ConnectionDialog::explainOpenError: kept apart from the dialog's layout code.
#include "ui/connection/ConnectionDialog.h"

#include <QStringList>

namespace opentop {

namespace {

bool mentions(const QString& error, std::initializer_list<const char*> words)
{
    for (const char* w : words) {
        if (error.contains(QLatin1String(w), Qt::CaseInsensitive))
            return true;
    }
    return false;
}

} // namespace

QString ConnectionDialog::explainOpenError(const ConnectionSettings& settings, const QString& error)
{
    QStringList checks;
    const bool serial = settings.kind == ConnectionSettings::Kind::Serial;
    if (mentions(error, {"in use", "busy", "locked", "EBUSY"})) {
        checks << tr("The port is in use by another program (named above where the system "
                     "tells it): a terminal program, ModemManager, another OpenTOP window or an "
                     "opentop-cli command. Close it, or disconnect the other window, and connect "
                     "again. Nothing was sent on the port.");
    }
    // The serial backend's own text may already give the usermod command: don't say it twice.
    if (error.contains(QStringLiteral("usermod"))) {
        checks << tr("Your user may not open serial ports: add it to the dialout group with the "
                     "command above, then log out and in again.");
    } else if (mentions(error, {"permission denied", "EACCES", "dialout", "not permitted"})) {
        checks << tr("Your user may not open serial ports. Add it to the dialout group:\n"
                     "    sudo usermod -aG dialout $USER\n"
                     "then log out and in again (the group applies to new sessions only).");
    }
    if (mentions(error, {"no such file", "no such device", "ENOENT", "ENODEV", "not found"})) {
        checks << tr("The port %1 does not exist: the USB adapter may be unplugged or have come "
                     "back under another name, or the path is mistyped. Plug it in, press "
                     "Refresh and pick it from the list; for a pseudo-terminal check that the "
                     "program serving it (opentop-sim, socat) still runs.")
                      .arg(settings.port);
    }
    if (mentions(error, {"timeout", "timed out", "no reply", "no answer"})) {
        checks << tr("The connection opened but no drive answered. Check that the baud rate, "
                     "parity and stop bits (%1) match the drives' settings (DBU: 19200 8N1, DC "
                     "controller: 9600 8E1) — a framing mismatch looks like silence — that the "
                     "machine number is right, and that the A and B (D+ and D−) wires are not "
                     "swapped.")
                      .arg(settings.describe());
    }
    if (!serial && mentions(error, {"refused", "unreachable", "no route", "host"})) {
        checks << tr("The gateway %1:%2 did not accept the connection: check the address and "
                     "port (Modbus TCP uses 502), that the gateway is powered and on this "
                     "network, and that no firewall blocks it.")
                      .arg(settings.host)
                      .arg(settings.tcpPort);
    }
    if (checks.isEmpty()) {
        checks << (serial ? tr("Check that the adapter is plugged in, that %1 is the right "
                               "port, and that no other program uses it.")
                                .arg(settings.port)
                          : tr("Check the connection settings and try again."));
    }
    QString text = tr("Could not use %1: %2").arg(settings.describe(), error.trimmed());
    text += QStringLiteral("\n\n") + tr("What to check:");
    for (const QString& c : checks)
        text += QStringLiteral("\n• ") + c;
    return text;
}

} // namespace opentop
