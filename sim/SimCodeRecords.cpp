#include "sim/SimCodeRecords.h"

#include "sim/SimDevice.h"

#include <QStringList>

namespace opentop {

SimCodeRecords::SimCodeRecords(SimDevice* device, const QString& prefix, int size)
    : m_device(device)
    , m_prefix(prefix)
    , m_size(size)
{
}

QString SimCodeRecords::name(int index) const
{
    return QStringLiteral("%1.record%2").arg(m_prefix).arg(index);
}

void SimCodeRecords::push(int code)
{
    for (int n = m_size; n > 1; --n)
        m_device->setRaw(name(n), at(n - 1));
    m_device->setRaw(name(1), code);
}

void SimCodeRecords::clear()
{
    for (int n = 1; n <= m_size; ++n)
        m_device->setRaw(name(n), 0);
}

int SimCodeRecords::at(int index) const
{
    return int(m_device->raw(name(index)).value_or(0));
}

const CodeTable* SimCodeRecords::table() const
{
    const ParameterMeta* first = m_device->param(name(1));
    if (first && !first->codeTable.isEmpty())
        return m_device->profile().codeTable(first->codeTable);
    return m_device->profile().codeTable(m_prefix);
}

const CodeEntry* SimCodeRecords::find(int code) const
{
    const CodeTable* t = table();
    return t ? t->find(code) : nullptr;
}

QString SimCodeRecords::codesText() const
{
    QStringList codes;
    if (const CodeTable* t = table()) {
        for (const CodeEntry& e : t->entries)
            codes << QStringLiteral("0x%1 %2").arg(e.code, 2, 16, QLatin1Char('0')).arg(e.name);
    }
    return codes.join(QStringLiteral(", "));
}

} // namespace opentop
