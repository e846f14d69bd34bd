#pragma once

#include "transport/LineFormat.h"

#include <QMetaType>
#include <QString>
#include <QVector>

namespace opentop {

// What a scan or identification learned about one machine number.
struct DeviceInfo
{
    enum class State
    {
        Unknown,      // not asked yet
        Present,      // answered and identified
        Absent,       // no answer
        Garbled,      // answered with corrupt frames: two drives with one machine number?
        Unidentified, // answered, but no profile matches
        // Answered (an exception to one family's read, a late reply), but the identification
        // read was never answered in time, also when asked again: there, but not known as what.
        IdentifyFailed,
    };

    int slave = 0;
    State state = State::Unknown;
    QString family;      // profile family, empty when not identified
    QString variant;     // empty when the device does not tell its variant
    QString model;       // variant model, or the profile's name
    QString name;        // device name register
    QString firmware;    // "1.5"
    QString machineName; // the user's name for the machine (BusDrives::setName), empty: none
    QString detail;      // the error or remark behind the state
    // The identify read's registers (the profile's IdentifyRule block) when Present: a session
    // made for the drive starts with them (DeviceSession::acceptIdentification), so nothing
    // asks the drive again for what identification has just read.
    QVector<quint16> identifyRegisters;
    // The drive's own line format where it is not the port's (unset: the port's). Requests to
    // it go out in it (ModbusClient::setDriveLine).
    LineFormat line;

    // Present, of a family with variants, and the drive did not say which (nor did anyone).
    bool variantUnknown() const;
    // The model for short labels: "DBU200-D", or the family ("DBU") while the variant is unknown.
    QString shortModel() const;
    static QString hexText(int slave);
    // The switch positions that set `slave` on a device of `family`, in the family's own
    // notation (its profile's AddressSwitches): 150 -> "SW1=9 SW2=6" (DBU), 7 -> "DIP ON: 1,2,3"
    // (DC controller). Without a family, each family's that can have the number, named:
    // "DBU SW1=0 SW2=7 / DCPID DIP ON: 1,2,3".
    static QString switchText(int slave, const QString& family = QString());
    // What a list shows for the number's switches: "96h  SW1=9 SW2=6" where the switches are
    // hexadecimal, "DIP ON: 1,2,3" where they are binary.
    static QString addressText(int slave, const QString& family);
    // How the machine number is set, per family ("DBU: Set on the rotary switches…"), one line
    // each; only `family`'s when given.
    static QString switchHelp(const QString& family = QString());
    static QString stateText(State state);
};

} // namespace opentop

Q_DECLARE_METATYPE(opentop::DeviceInfo)
