#pragma once

#include "model/profile/CodeTable.h"

#include <QString>

namespace opentop {

class SimDevice;

// A stack of code records in a device's registers ("alarm.record1".."alarm.record15"), newest
// first, decoded by the code table its first record names.
class SimCodeRecords
{
public:
    SimCodeRecords(SimDevice* device, const QString& prefix, int size = 15);

    void push(int code);
    void clear();
    int at(int index) const; // 1-based, as the parameter names count
    const CodeTable* table() const;
    const CodeEntry* find(int code) const;
    QString codesText() const; // "0x01 Overvoltage, 0x03 Overcurrent, ..."

private:
    QString name(int index) const;

    SimDevice* m_device;
    QString m_prefix;
    int m_size;
};

} // namespace opentop
