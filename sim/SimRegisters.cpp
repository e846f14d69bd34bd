#include "sim/SimRegisters.h"

#include "model/profile/ValueCodec.h"

namespace opentop {

SimRegisters::SimRegisters(const Profile* profile)
    : m_profile(profile)
{
    for (const ParameterMeta& p : m_profile->parameters) {
        for (int i = 0; i < p.registerCount; ++i) {
            const quint16 a = quint16(p.address + i);
            if (p.readFunction == 3)
                m_holdingIndex.insert(a, &p);
            else if (p.readFunction == 4)
                m_inputIndex.insert(a, &p);
            if (p.isWritable())
                m_writeIndex.insert(a, &p);
            if (!m_allIndex.contains(a))
                m_allIndex.insert(a, &p);
        }
        if (!p.storeWith.isEmpty())
            m_storeGroups[p.storeWith] << p.name;
    }
}

const ParameterMeta* SimRegisters::readable(quint8 function, quint16 address) const
{
    if (function == 3)
        return m_holdingIndex.value(address, nullptr);
    if (function == 4)
        return m_inputIndex.value(address, nullptr);
    return nullptr;
}

const ParameterMeta* SimRegisters::writable(quint16 address) const
{
    return m_writeIndex.value(address, nullptr);
}

bool SimRegisters::inReadBlock(quint8 function, quint16 address) const
{
    for (const ReadBlock& b : m_profile->readBlocks) {
        if (b.function == function && address >= b.first && address <= b.last)
            return true;
    }
    return false;
}

SimRegisters::Space SimRegisters::spaceOf(const ParameterMeta& meta)
{
    if (meta.readFunction == 4)
        return Space::Input;
    if (meta.readFunction == 3)
        return Space::Holding;
    return Space::Command;
}

quint16 SimRegisters::value(Space space, quint16 address) const
{
    return m_spaces[size_t(space)].value(address, 0);
}

void SimRegisters::setValue(Space space, quint16 address, quint16 value)
{
    m_spaces[size_t(space)].insert(address, value);
}

quint16 SimRegisters::readValue(quint8 function, quint16 address) const
{
    if (!readable(function, address))
        return 0;
    return value(spaceForFunction(function), address);
}

QVector<quint16> SimRegisters::registers(const ParameterMeta& meta) const
{
    QVector<quint16> values;
    values.reserve(meta.registerCount);
    const Space space = spaceOf(meta);
    for (int i = 0; i < meta.registerCount; ++i)
        values << value(space, quint16(meta.address + i));
    return values;
}

void SimRegisters::setRegisters(const ParameterMeta& meta, const QVector<quint16>& values)
{
    const Space space = spaceOf(meta);
    for (int i = 0; i < meta.registerCount && i < values.size(); ++i)
        setValue(space, quint16(meta.address + i), values.at(i));
}

double SimRegisters::raw(const ParameterMeta& meta) const
{
    return ValueCodec::registersToRaw(meta, registers(meta));
}

void SimRegisters::setRaw(const ParameterMeta& meta, double raw)
{
    setRegisters(meta, ValueCodec::rawToRegisters(meta, raw));
}

void SimRegisters::setText(const ParameterMeta& meta, const QString& text, char pad)
{
    const QByteArray bytes = text.toLatin1();
    QVector<quint16> values;
    for (int i = 0; i < meta.registerCount; ++i) {
        const char hi = 2 * i < bytes.size() ? bytes.at(2 * i) : pad;
        const char lo = 2 * i + 1 < bytes.size() ? bytes.at(2 * i + 1) : pad;
        values << quint16((quint8(hi) << 8) | quint8(lo));
    }
    setRegisters(meta, values);
}

void SimRegisters::storeParameter(const ParameterMeta& meta)
{
    m_stored.insert(meta.name, registers(meta));
}

void SimRegisters::restoreParameter(const ParameterMeta& meta)
{
    const auto it = m_stored.constFind(meta.name);
    if (it != m_stored.constEnd())
        setRegisters(meta, *it);
}

QVector<quint16> SimRegisters::storedRegisters(const ParameterMeta& meta) const
{
    return m_stored.value(meta.name, registers(meta));
}

void SimRegisters::storeGroup(const QString& storeCommand)
{
    for (const QString& name : m_storeGroups.value(storeCommand)) {
        if (const ParameterMeta* p = m_profile->parameter(name))
            storeParameter(*p);
    }
}

void SimRegisters::reloadGroup(const QString& storeCommand)
{
    for (const QString& name : m_storeGroups.value(storeCommand)) {
        if (const ParameterMeta* p = m_profile->parameter(name))
            restoreParameter(*p);
    }
}

} // namespace opentop
