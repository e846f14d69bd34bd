#include "model/profile/Profile.h"

#include <algorithm>

namespace opentop {

namespace {

// Holding registers are read by 03 and written by 06/16; input registers are read by 04.
bool inHoldingSpace(quint8 function)
{
    return function == 3 || function == 6 || function == 16;
}

bool occupies(const ParameterMeta& p, quint8 function)
{
    if (inHoldingSpace(function))
        return p.readFunction == 3 || (p.writeFunction != 0 && p.readFunction != 4);
    return p.readFunction == function;
}

} // namespace

const ParameterMeta* Profile::parameter(const QString& parameterName) const
{
    const auto it = m_byName.constFind(parameterName);
    return it == m_byName.cend() ? nullptr : &parameters[it.value()];
}

const ParameterMeta* Profile::parameterAt(quint8 function, quint16 address) const
{
    for (const ParameterMeta& p : parameters) {
        if (occupies(p, function) && address >= p.address && address < p.address + p.registerCount)
            return &p;
    }
    return nullptr;
}

const ProfileVariant* Profile::variant(const QString& id) const
{
    for (const ProfileVariant& v : variants) {
        if (v.id == id)
            return &v;
    }
    return nullptr;
}

const ProfileGroup* Profile::group(const QString& id) const
{
    for (const ProfileGroup& g : groups) {
        if (g.id == id)
            return &g;
    }
    return nullptr;
}

const CodeTable* Profile::codeTable(const QString& id) const
{
    const auto it = codeTables.constFind(id);
    return it == codeTables.cend() ? nullptr : &it.value();
}

const ProfileRole* Profile::role(const QString& roleName) const
{
    const auto it = roles.constFind(roleName);
    return it == roles.cend() ? nullptr : &it.value();
}

QVector<const ParameterMeta*> Profile::records(const QString& table) const
{
    QVector<const ParameterMeta*> result;
    for (const ParameterMeta& p : parameters) {
        if (p.kind == QLatin1String("record") && p.codeTable == table)
            result << &p;
    }
    std::sort(result.begin(), result.end(), [](const ParameterMeta* a, const ParameterMeta* b) {
        return a->address < b->address;
    });
    return result;
}

QVector<const ParameterMeta*> Profile::parametersInGroup(const QString& groupId) const
{
    QVector<const ParameterMeta*> result;
    for (const ParameterMeta& p : parameters) {
        if (p.group == groupId)
            result << &p;
    }
    return result;
}

void Profile::index()
{
    m_byName.clear();
    for (int i = 0; i < parameters.size(); ++i)
        m_byName.insert(parameters[i].name, i);
}

std::optional<double> Profile::knobDeceleration(qint64 selected) const
{
    for (const DecelerationKnob& k : decelerationKnobs) {
        if (k.selected == selected)
            return k.maxSeconds;
    }
    return std::nullopt;
}

const StatusLedEntry* Profile::ledEntry(const QString& light) const
{
    for (const StatusLedEntry& e : statusLed) {
        if (e.light == light)
            return &e;
    }
    return nullptr;
}

} // namespace opentop
