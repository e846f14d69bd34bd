#include "model/session/DeviceRefusal.h"

#include "model/profile/Profile.h"
#include "model/session/BlockReader.h"
#include "model/session/DeviceSession.h"
#include "transport/ModbusClient.h"

namespace opentop {

const ParameterMeta* DeviceRefusal::errorRegister(const Profile& profile)
{
    for (const ParameterMeta& p : profile.parameters) {
        if (p.codeTable == QLatin1String("comm_error") && p.isReadable() &&
            p.kind != QLatin1String("record"))
            return &p;
    }
    return nullptr;
}

const CodeEntry* DeviceRefusal::exceptionEntry(const Profile& profile, int exceptionCode)
{
    const CodeEntry* found = nullptr;
    for (const CodeTable& table : profile.codeTables) {
        for (const CodeEntry& e : table.entries) {
            if (e.exceptionCode != exceptionCode)
                continue;
            if (found)
                return nullptr; // ambiguous: the drive's register says which
            found = &e;
        }
    }
    return found;
}

void DeviceRefusal::read(ModbusClient* client, QObject* context, const Profile& profile, int slave,
                         const ModbusResult& result, std::function<void(const Reason&)> done)
{
    if (result.error != ModbusError::Exception) {
        done(Reason());
        return;
    }
    const ParameterMeta* reg = errorRegister(profile);
    if (!reg) {
        Reason why;
        if (const CodeEntry* e = exceptionEntry(profile, result.exceptionCode))
            why.entry = *e;
        done(why);
        return;
    }
    // The DBU leaves the reason for an exception in its communication error register.
    client->submit(BlockReader::requestFor(slave, *reg), context,
                   [&profile, reg, done](const ModbusResult& r) {
                       Reason why;
                       if (!r.ok() || r.registers.isEmpty()) {
                           done(why);
                           return;
                       }
                       const CodeTable* table = profile.codeTable(reg->codeTable);
                       const qint64 code = r.registers.first();
                       const CodeEntry* entry = table ? table->find(code) : nullptr;
                       const QString hex = QString::number(code, 16).toUpper() + QLatin1Char('h');
                       if (entry) {
                           why.entry = *entry;
                           why.retry = entry->retry;
                           why.code = hex + QLatin1Char(' ') + entry->name;
                       } else {
                           why.code = DeviceSession::tr("error code %1").arg(hex);
                       }
                       done(why);
                   });
}

} // namespace opentop
