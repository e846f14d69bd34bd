#pragma once

#include "model/profile/AddressSwitches.h"
#include "model/profile/CodeTable.h"
#include "model/profile/ParameterMeta.h"

#include <QHash>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QVector>
#include <optional>

namespace opentop {

struct ProfileVariant
{
    QString id;        // "dbu200"
    QString model;     // "DBU200-D"
    QString label;     // "DBU200-D, 24 V, 200 W, 250–3000 r/min"
    QString nameMatch; // device name prefix that identifies this variant, if the device tells
};

struct ProfileGroup
{
    QString id;
    QString label;
    QString help;
    QString editor; // a specialised editor page for this group; empty: the generic one
};

// Address range the device answers block reads for (unused registers inside read as 0).
struct ReadBlock
{
    quint8 function = 3;
    quint16 first = 0;
    quint16 last = 0;
};

// How a scan recognises the family: a read that only this family answers as expected.
struct IdentifyRule
{
    quint8 function = 3;
    quint16 address = 0;
    quint16 count = 1;
    QString nameParameter;    // decoded for the device name
    QString versionParameter; // decoded for the firmware version ("hi.lo" byte format)
    QString nameMatch;        // regular expression the name must match; empty: any
};

// What a parameter (or a value of it) means to generic code: "stop" is writing 0 to run.start
// on a DBU and 0 to speed.command on the DC controller; "running" is a status bit or a
// non-zero value. Keeps family knowledge in the data.
struct ProfileRole
{
    QString parameter;           // single-parameter roles
    QString field;               // a bit field of `parameter` (bits type)
    std::optional<qint64> value; // the raw value to write, for command roles
    QStringList parameters;      // list roles, e.g. "monitor"
};

struct SerialDefaults
{
    int baud = 19200;
    char parity = 'N';
    int stopBits = 1;
    QVector<int> bauds;
    int powerOnDelayMs = 0; // after power-on, the drive answers only after this long
    // The character formats the drive can be set to ("8N1"; the DC controller: 8E1, 8O1, 8N2),
    // the default's first when the profile names none.
    QStringList formats;
    // How to change the drive's format and rate over the bus (which setting, how it is stored,
    // when it takes effect, in which order), for a drive that must join a bus of another
    // format; empty when the drive cannot be changed.
    QString formatHelp;
};

// A deceleration the drive takes from a knob, not from a setting that can be read (the DBU's SD
// knob for SPno1): a stop may take up to `maxSeconds` while the running data whose "selected"
// role value is `selected` runs.
struct DecelerationKnob
{
    qint64 selected = 0;
    double maxSeconds = 0;
};

// One colour of the drive's status LED as its manual gives it. `light` is the model's name for
// it (DriveStatus::Led: green, orange, skyBlue, red, purple, blue; white: no power); `colour` the
// "#rrggbb" a view paints; `blink` how the manual says it blinks (empty: it does not say).
struct StatusLedEntry
{
    QString light;
    QString colour;
    QString label;   // "Red" (profile language)
    QString meaning; // "Alarm"
    QString blink;   // "Flashes"
};

// A device family described by data: parameters, groups, code tables, limits.
class Profile
{
public:
    QString family; // "dbu", "dcpid"
    QString name;
    QString vendor;
    QString manual;
    QString sourceFile; // where it was loaded from, for error messages
    SerialDefaults serial;
    int maxReadRegisters = 125;
    int maxWriteRegisters = 123;
    int minSlave = 1;
    int maxSlave = 247;
    AddressSwitches addressSwitches; // how the machine number is set on the device
    bool supportsBroadcast = true;
    bool supportsGroups = false;
    QVector<ProfileVariant> variants;
    QVector<ProfileGroup> groups;
    QVector<ReadBlock> readBlocks;
    IdentifyRule identify;
    QHash<QString, CodeTable> codeTables;
    QHash<QString, ProfileRole> roles;
    QVector<ParameterMeta> parameters;
    // How the device's speed loop is tuned (model/tuning/TuningSpec reads and checks it);
    // empty when it has none.
    QJsonObject tuning;
    // How a drive that does not report its variant proves it (profile/VariantProbe reads and
    // checks it); empty when the family needs none.
    QJsonObject variantProbe;
    QVector<DecelerationKnob> decelerationKnobs;
    QVector<StatusLedEntry> statusLed;
    // Texts whose setting references were resolved (SettingReference), as written, by their
    // ProfileTexts key: what a translation is checked against and keyed by.
    QHash<QString, QString> referencedTexts;

    // The knob's deceleration for running data `selected` (the "selected" role's raw value).
    std::optional<double> knobDeceleration(qint64 selected) const;
    // The LED entry for `light`; nullptr when the profile has none.
    const StatusLedEntry* ledEntry(const QString& light) const;
    const ParameterMeta* parameter(const QString& parameterName) const;
    // The parameter whose registers include `address` in the read (3/4) or write space.
    const ParameterMeta* parameterAt(quint8 function, quint16 address) const;
    const ProfileVariant* variant(const QString& id) const;
    const ProfileGroup* group(const QString& id) const;
    const CodeTable* codeTable(const QString& id) const;
    const ProfileRole* role(const QString& roleName) const;
    // Parameters of kind "record" decoded by `codeTable`, in address order (newest first).
    QVector<const ParameterMeta*> records(const QString& codeTable) const;
    QVector<const ParameterMeta*> parametersInGroup(const QString& group) const;
    // Builds the name index; called by the loader.
    void index();

private:
    QHash<QString, int> m_byName;
};

} // namespace opentop
