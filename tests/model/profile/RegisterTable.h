#pragma once

// An independent reading of the register maps in the manuals, as data, and the check that
// compares one row with a built-in profile. The tables live in DbuRegisterTable.cpp
// (000_306a808c77939fd6.txt, chapter 12) and DcRegisterTable.cpp (003_e17f880ddc4c624e.txt,
// section 1.3). They are written from the manuals, not from model/profiles/*.json.

#include "model/profile/ParameterMeta.h"
#include "model/profile/Profile.h"

#include <QtGlobal>
#include <ostream>
#include <string>
#include <vector>

namespace opentop::manualcheck {

// An allowed interval in engineering units, as the manual writes it (0.5–30.0 s).
struct Interval
{
    double min;
    double max;
};

// One allowed set the manual gives, and the context in which it applies.
struct Allowed
{
    std::vector<Interval> ranges;  // engineering units
    std::vector<double> codes;     // raw codes (enumerations, command values)
    std::vector<double> refused;   // further raw values the manual rules out
    const char* variant = nullptr; // applies to this drive variant only
    int controller = -1;           // address (read with 03) of the parameter the set depends on
    qint64 controllerValue = 0;
    double scale = 0;   // 0: the row's scale
    bool strict = true; // values just outside must be refused

    Allowed onVariant(const char* id) const;
    Allowed when(int address, qint64 value) const;
    Allowed withScale(double s) const;
    Allowed advisory() const; // the manual only proposes the range: inside accepted, no more
    Allowed alsoRefusing(std::vector<double> raw) const;
    Allowed orCodes(std::vector<double> raw) const; // codes allowed beside the ranges
};

Allowed span(double min, double max);
Allowed spans(std::vector<Interval> ranges);
Allowed oneOf(std::vector<double> codes);

constexpr quint8 kNone = 0;         // no such function
constexpr quint8 kUnchecked = 0xFF; // write function not checked (reserved registers)

constexpr DataType u16 = DataType::U16;
constexpr DataType s16 = DataType::S16;
constexpr DataType u32 = DataType::U32;
constexpr DataType f32 = DataType::F32;
constexpr DataType text = DataType::String;
constexpr DataType bits = DataType::Bits;

struct Register
{
    quint16 address;
    quint8 read;  // 3, 4 or kNone
    quint8 write; // 6, 16, kNone or kUnchecked
    DataType type;
    int count;
    double scale;     // engineering = raw * scale; 0 when each Allowed gives its own
    const char* what; // the manual's words and section
    std::vector<Allowed> allowed = {};
    const char* kind = nullptr;      // checked when given
    const char* codeTable = nullptr; // checked when given
    std::vector<int> bits = {};      // bits the profile's bit fields must cover
};

// Compares one row with the profile; every difference is a GoogleTest failure naming the row.
void checkRegister(const Profile& profile, const Register& row);

// The register tables (static arrays in DbuRegisterTable.cpp / DcRegisterTable.cpp).
const std::vector<Register>& dbuRegisters();
const std::vector<Register>& dcRegisters();

void PrintTo(const Register& row, std::ostream* os);
// GoogleTest parameter name: "at_1303".
std::string testName(const Register& row);

} // namespace opentop::manualcheck
