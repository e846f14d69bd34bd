// The comparison of one manual register row with a built-in profile (see RegisterTable.h).
#include "tests/model/profile/RegisterTable.h"

#include "model/profile/ValueCodec.h"
#include "model/profile/ValueContext.h"

#include <gtest/gtest.h>

#include <QString>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>

namespace opentop::manualcheck {

Allowed Allowed::onVariant(const char* id) const
{
    Allowed a = *this;
    a.variant = id;
    return a;
}

Allowed Allowed::when(int address, qint64 value) const
{
    Allowed a = *this;
    a.controller = address;
    a.controllerValue = value;
    return a;
}

Allowed Allowed::withScale(double s) const
{
    Allowed a = *this;
    a.scale = s;
    return a;
}

Allowed Allowed::advisory() const
{
    Allowed a = *this;
    a.strict = false;
    return a;
}

Allowed Allowed::alsoRefusing(std::vector<double> raw) const
{
    Allowed a = *this;
    a.refused.insert(a.refused.end(), raw.begin(), raw.end());
    return a;
}

Allowed Allowed::orCodes(std::vector<double> raw) const
{
    Allowed a = *this;
    a.codes.insert(a.codes.end(), raw.begin(), raw.end());
    return a;
}

Allowed span(double min, double max)
{
    Allowed a;
    a.ranges.push_back({min, max});
    return a;
}

Allowed spans(std::vector<Interval> ranges)
{
    Allowed a;
    a.ranges = std::move(ranges);
    return a;
}

Allowed oneOf(std::vector<double> codes)
{
    Allowed a;
    a.codes = std::move(codes);
    return a;
}

namespace {

std::string hex4(int value)
{
    return (QStringLiteral("0x") +
            QStringLiteral("%1").arg(value, 4, 16, QLatin1Char('0')).toUpper())
        .toStdString();
}

std::string typeName(DataType type)
{
    return dataTypeName(type).toStdString();
}

std::string describe(const Allowed& a)
{
    std::ostringstream s;
    const char* sep = "";
    for (const Interval& r : a.ranges) {
        s << sep << r.min;
        if (r.max != r.min)
            s << "–" << r.max;
        sep = " or ";
    }
    for (double c : a.codes) {
        s << sep << "code " << hex4(static_cast<int>(c));
        sep = " or ";
    }
    if (a.variant)
        s << " [variant " << a.variant << "]";
    if (a.controller >= 0)
        s << " [when " << hex4(a.controller) << " = " << a.controllerValue << "]";
    return s.str();
}

// Engineering -> raw with the manual's scale; the table must only hold whole raw numbers.
double toRaw(double engineering, double scale, DataType type, const std::string& where)
{
    if (type == DataType::F32)
        return engineering;
    const double raw = engineering / scale;
    if (std::fabs(raw - std::round(raw)) > 1e-6)
        ADD_FAILURE() << where << ": test table error, " << engineering << " is not a whole "
                      << "multiple of the scale " << scale;
    return std::round(raw);
}

// Finds the parameter the row describes; on a miss, says what the profile has there instead.
const ParameterMeta* lookUp(const Profile& profile, const Register& row, const std::string& where)
{
    const quint8 function = row.read != kNone ? row.read : row.write;
    if (const ParameterMeta* p = profile.parameterAt(function, row.address))
        return p;
    std::ostringstream found;
    for (quint8 other : {quint8(3), quint8(4), quint8(6), quint8(16)}) {
        if (other == function)
            continue;
        if (const ParameterMeta* p = profile.parameterAt(other, row.address))
            found << " (the profile has " << p->name.toStdString() << " there, read "
                  << int(p->readFunction) << " write " << int(p->writeFunction) << ")";
    }
    ADD_FAILURE() << where << ": the profile has no parameter at " << hex4(row.address)
                  << " for function " << int(function) << found.str();
    return nullptr;
}

void checkValues(const Profile& profile, const ParameterMeta& p, const Register& row,
                 const Allowed& a, const std::string& where)
{
    ValueContext context;
    std::string condition = describe(a);
    if (a.variant) {
        context.variant = QString::fromLatin1(a.variant);
        EXPECT_NE(profile.variant(context.variant), nullptr)
            << where << ": the profile has no variant " << a.variant;
    }
    if (a.controller >= 0) {
        const ParameterMeta* controller = profile.parameterAt(3, quint16(a.controller));
        if (!controller) {
            ADD_FAILURE() << where << ": the allowed set depends on " << hex4(a.controller)
                          << ", which the profile does not have";
            return;
        }
        const QString name = controller->name;
        const qint64 value = a.controllerValue;
        context.parameterRaw = [name, value](const QString& parameter) -> std::optional<qint64> {
            if (parameter == name)
                return value;
            return std::nullopt;
        };
        condition += " (" + name.toStdString() + ")";
    }

    QString unresolved;
    const ValueSpec& spec = p.specFor(context, &unresolved);
    EXPECT_TRUE(unresolved.isEmpty())
        << where << " " << condition << ": the profile makes the allowed values depend on "
        << unresolved.toStdString() << ", the manual does not";
    const double scale = a.scale != 0 ? a.scale : row.scale;
    EXPECT_NEAR(spec.scale, scale, std::fabs(scale) * 1e-9)
        << where << " " << condition << ": scale " << spec.scale << ", manual " << scale;

    std::vector<double> inside;
    for (const Interval& r : a.ranges) {
        inside.push_back(toRaw(r.min, scale, row.type, where));
        inside.push_back(toRaw(r.max, scale, row.type, where));
    }
    inside.insert(inside.end(), a.codes.begin(), a.codes.end());
    auto isInside = [&](double raw) {
        for (const Interval& r : a.ranges) {
            if (raw >= toRaw(r.min, scale, row.type, where) &&
                raw <= toRaw(r.max, scale, row.type, where))
                return true;
        }
        for (double c : a.codes) {
            if (raw == c)
                return true;
        }
        return false;
    };

    for (double raw : inside) {
        const QString error = ValueCodec::checkRaw(p, raw, context);
        EXPECT_TRUE(error.isEmpty()) << where << ": raw " << raw << " (" << raw * scale
                                     << ") must be allowed, manual: " << condition
                                     << "; the profile refuses it: " << error.toStdString();
    }
    if (!a.strict || row.type == DataType::Bits || row.type == DataType::String)
        return;

    std::vector<double> outside = a.refused;
    auto below = [&](double raw) {
        return row.type == DataType::F32
                   ? double(std::nextafter(float(raw), -std::numeric_limits<float>::infinity()))
                   : raw - 1;
    };
    auto above = [&](double raw) {
        return row.type == DataType::F32
                   ? double(std::nextafter(float(raw), std::numeric_limits<float>::infinity()))
                   : raw + 1;
    };
    for (const Interval& r : a.ranges) {
        outside.push_back(below(toRaw(r.min, scale, row.type, where)));
        outside.push_back(above(toRaw(r.max, scale, row.type, where)));
    }
    for (double c : a.codes) {
        outside.push_back(below(c));
        outside.push_back(above(c));
    }
    for (double raw : outside) {
        if (isInside(raw) && std::find(a.refused.begin(), a.refused.end(), raw) == a.refused.end())
            continue;
        EXPECT_FALSE(ValueCodec::checkRaw(p, raw, context).isEmpty())
            << where << ": raw " << raw << " (" << raw * scale
            << ") must be refused, manual allows only " << condition;
    }
}

} // namespace

void checkRegister(const Profile& profile, const Register& row)
{
    const std::string where =
        profile.family.toStdString() + " " + hex4(row.address) + " " + row.what;
    const ParameterMeta* p = lookUp(profile, row, where);
    if (!p)
        return;
    const std::string name = " (" + p->name.toStdString() + ")";

    if (row.kind) {
        EXPECT_EQ(p->kind.toStdString(), row.kind) << where << name << ": kind";
    }
    if (row.kind && std::string(row.kind) == "reserved") {
        // Reserved registers only need to be known as readable (block reads over them).
        EXPECT_EQ(int(p->readFunction), int(row.read)) << where << name << ": read function";
        return;
    }

    EXPECT_EQ(hex4(p->address), hex4(row.address))
        << where << name << ": the parameter covering this register starts elsewhere";
    EXPECT_EQ(int(p->readFunction), int(row.read)) << where << name << ": read function";
    if (row.write != kUnchecked) {
        EXPECT_EQ(int(p->writeFunction), int(row.write)) << where << name << ": write function";
    }
    EXPECT_EQ(typeName(p->type), typeName(row.type)) << where << name << ": type";
    EXPECT_EQ(p->registerCount, row.count) << where << name << ": register count";
    if (row.scale != 0) {
        EXPECT_NEAR(p->spec.scale, row.scale, std::fabs(row.scale) * 1e-9)
            << where << name << ": scale";
    }

    // Every register of the value is found at its own address, in both function spaces.
    const quint8 function = row.read != kNone ? row.read : row.write;
    for (int i = 1; i < row.count; ++i) {
        EXPECT_EQ(profile.parameterAt(function, quint16(row.address + i)), p)
            << where << name << ": register " << hex4(row.address + i) << " is not part of it";
    }
    if (row.read != kNone && row.write != kNone && row.write != kUnchecked) {
        EXPECT_EQ(profile.parameterAt(row.write, row.address), p)
            << where << name << ": not found in the write space of function " << int(row.write);
    }

    if (row.codeTable) {
        EXPECT_EQ(p->codeTable.toStdString(), row.codeTable) << where << name << ": code table";
        EXPECT_NE(profile.codeTable(QString::fromLatin1(row.codeTable)), nullptr)
            << where << name << ": the profile has no code table " << row.codeTable;
    }
    for (int bit : row.bits) {
        bool covered = false;
        for (const BitField& field : p->bits)
            covered = covered || (bit >= field.bit && bit < field.bit + field.width);
        EXPECT_TRUE(covered) << where << name << ": no bit field covers bit " << bit;
    }
    for (const Allowed& a : row.allowed)
        checkValues(profile, *p, row, a, where + name);
}

std::string testName(const Register& row)
{
    char name[16];
    std::snprintf(name, sizeof name, "at_%04X", unsigned(row.address));
    return name;
}

void PrintTo(const Register& row, std::ostream* os)
{
    *os << hex4(row.address) << " " << row.what;
}

} // namespace opentop::manualcheck
