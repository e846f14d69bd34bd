#pragma once

#include "model/profile/Profile.h"

#include <QHash>
#include <QStringList>
#include <QVector>
#include <array>

namespace opentop {

// The register memory of one simulated device, laid out by its profile: holding (03) and input
// (04) registers are separate spaces, and write-only commands keep their last value in a third
// one. Knows which addresses exist for each function; holds no behaviour.
class SimRegisters
{
public:
    enum class Space
    {
        Holding,
        Input,
        Command
    };

    explicit SimRegisters(const Profile* profile);

    // The parameter readable with `function` (3 or 4) whose registers include `address`.
    const ParameterMeta* readable(quint8 function, quint16 address) const;
    // The parameter writable (06 or 10) whose registers include `address`.
    const ParameterMeta* writable(quint16 address) const;
    bool inReadBlock(quint8 function, quint16 address) const;
    // Any parameter the profile declares at `address`, whatever its functions.
    const ParameterMeta* declared(quint16 address) const
    {
        return m_allIndex.value(address, nullptr);
    }
    static Space spaceOf(const ParameterMeta& meta);
    static Space spaceForFunction(quint8 function)
    {
        return function == 4 ? Space::Input : Space::Holding;
    }

    quint16 value(Space space, quint16 address) const;
    void setValue(Space space, quint16 address, quint16 value);
    // A read of one register: its value when a readable parameter covers it, 0 in block gaps.
    quint16 readValue(quint8 function, quint16 address) const;

    QVector<quint16> registers(const ParameterMeta& meta) const;
    void setRegisters(const ParameterMeta& meta, const QVector<quint16>& values);
    double raw(const ParameterMeta& meta) const;
    void setRaw(const ParameterMeta& meta, double raw);
    // A string parameter: two characters per register, high byte first, padded with `pad`.
    void setText(const ParameterMeta& meta, const QString& text, char pad);

    // Temporary settings (storeWith): the value they return to at power-on.
    bool isStoreCommand(const QString& name) const { return m_storeGroups.contains(name); }
    QStringList storedBy(const QString& storeCommand) const
    {
        return m_storeGroups.value(storeCommand);
    }
    void storeParameter(const ParameterMeta& meta);   // current value becomes the power-on value
    void restoreParameter(const ParameterMeta& meta); // back to the power-on value
    QVector<quint16> storedRegisters(const ParameterMeta& meta) const; // the power-on value
    void storeGroup(const QString& storeCommand);
    void reloadGroup(const QString& storeCommand);

private:
    const Profile* m_profile;
    std::array<QHash<quint16, quint16>, 3> m_spaces;
    QHash<quint16, const ParameterMeta*> m_holdingIndex;
    QHash<quint16, const ParameterMeta*> m_inputIndex;
    QHash<quint16, const ParameterMeta*> m_writeIndex;
    QHash<quint16, const ParameterMeta*> m_allIndex;
    QHash<QString, QVector<quint16>> m_stored;
    QHash<QString, QStringList> m_storeGroups; // store command -> parameters it stores
};

} // namespace opentop
