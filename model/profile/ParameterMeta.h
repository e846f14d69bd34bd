#pragma once

#include <QString>
#include <QStringList>
#include <QVector>
#include <optional>

namespace opentop {

struct ValueContext;

enum class DataType
{
    U16,
    S16,
    U32,
    S32,
    F32,
    String,
    Bits
};
// How a 2-register value lies in its registers: the high word at the lower address (the
// Modbus convention and the profiles' default) or the low word there.
enum class WordOrder
{
    HighFirst,
    LowFirst
};
enum class Access
{
    ReadOnly,
    ReadWrite,
    WriteOnly
};

// An enumeration code with its label. Codes are raw register values.
struct EnumOption
{
    qint64 value = 0;
    QString label; // for people: in the profile language (ProfileTranslation)
    QString help;
    // The profile's English label: an interface, not a text for people. Backup and recipe files,
    // result records and --json write it, and typed values are matched against it too.
    QString canonicalLabel;
};

// An allowed interval in raw units (integers for integer types, the float itself for f32).
struct ValueRange
{
    double min = 0;
    double max = 0;
};

// A field of a bit-field register (bits bit .. bit+width-1).
struct BitField
{
    int bit = 0;
    int width = 1;
    QString name;
    QString label;
    QStringList values; // label per field value, optional
    QString function;   // a terminal's state: the setting that assigns its function ("io.x0")
    // The field means something only while setting `appliesParam` holds `appliesRaw` (the
    // Hold bit while "Holding force at stop" is set); empty: always.
    QString appliesParam;
    double appliesRaw = 0;
};

// What may change with the drive variant or with another parameter's value.
struct ValueSpec
{
    double scale = 1.0;         // engineering = raw * scale
    QString unit;               // "s", "r/min", "A", "%"... (profile language)
    QString canonicalUnit;      // the profile's own unit, for files and --json
    int decimals = 0;           // shown after the point
    QVector<ValueRange> ranges; // allowed intervals (raw)
    // Recommended intervals (raw), each inside an allowed one: a value allowed but outside them
    // is written with a warning (ValueCodec::recommendationWarning). Empty: no recommendation.
    QVector<ValueRange> recommended;
    QVector<EnumOption> options;      // allowed codes with labels (also allowed beside ranges)
    std::optional<double> defaultRaw; // factory default (raw); none when the manual gives none
    QString defaultText;              // string parameters
    QString note;                     // short context, e.g. "PWM duty in this speed mode"

    // Whether `raw` lies in a recommended interval; true when there is no recommendation.
    bool isRecommended(double raw) const;
};

// A write the device wants as part of a larger frame (profile key "writeBlock"): function 0x10
// over `count` registers from `address`. The registers before the tail are read first (03), so
// the others keep their values; the parameter's own registers replace theirs and the `tail`
// values follow (the DC controller's 15-register configuration write from 0x0080 and its
// 5-register GPIO write from 0x0050, which also store what they write).
struct BlockWrite
{
    quint16 address = 0;
    int count = 0; // 0: written on its own
    QVector<quint16> tail;

    bool isSet() const { return count > 0; }
    int readCount() const { return count - int(tail.size()); }
};

// A ValueSpec that applies when the variant is `variant`, or parameter `param` holds `equals`.
struct ValueCondition
{
    QString variant;
    QString param;
    qint64 equals = 0;
    ValueSpec spec;
    // What the `when` entry gives itself; the rest of `spec` is the parameter's. The profile's
    // texts (ProfileTexts) name only a condition's own texts.
    bool ownUnit = false;
    bool ownNote = false;
    bool ownOptions = false;
};

// Everything known about one register or register group of a device, apart from its value.
// Metadata only: values live in the device model, conversions in ValueCodec.
struct ParameterMeta
{
    QString name;           // stable dotted name, unique in its profile: "spno2.speed"
    QString label;          // for people: in the profile language (ProfileTranslation)
    QString canonicalLabel; // the profile's English label: result records, files
    QString help;
    QString group; // id of a ProfileGroup
    quint16 address = 0;
    quint8 readFunction = 0;  // 3 or 4; 0 when not readable
    quint8 writeFunction = 0; // 6 or 16; 0 when not writable
    DataType type = DataType::U16;
    int registerCount = 1;
    WordOrder wordOrder = WordOrder::HighFirst; // 2-register numbers and bit fields
    Access access = Access::ReadWrite;
    QString kind;          // setting | status | info | command | record | reserved
    QString safety;        // commands only: motion | reset | erase | init | store | comm
    QString codeTable;     // record and code registers: id of a CodeTable
    QString storeWith;     // settings that are temporary until this command parameter is written
    BlockWrite writeBlock; // how a write of it is sent when not on its own
    QVector<BitField> bits;
    ValueSpec spec;                     // the base spec
    QVector<ValueCondition> conditions; // first match overrides the base spec
    bool backup = false; // part of a backup / restore (readable and writable settings)

    bool isReadable() const { return readFunction != 0; }
    bool isWritable() const { return writeFunction != 0; }
    bool isNumeric() const { return type != DataType::String && type != DataType::Bits; }
    bool isSigned() const { return type == DataType::S16 || type == DataType::S32; }
    bool dependsOnParameter() const;
    QStringList controllingParameters() const;
    // The spec in force for `context`. When it depends on a parameter whose value is not known,
    // returns the base spec and sets *unresolved to that parameter's name.
    const ValueSpec& specFor(const ValueContext& context, QString* unresolved = nullptr) const;
    QString addressText() const;   // "0x0109"
    QString functionsText() const; // "03/06", "04", "06"
};

QString dataTypeName(DataType type);
std::optional<DataType> dataTypeFromName(const QString& name);
QString accessName(Access access);

} // namespace opentop
