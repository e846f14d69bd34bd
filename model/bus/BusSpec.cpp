#include "model/bus/BusSpec.h"

#include "model/profile/ProfileRegistry.h"

#include <QCoreApplication>
#include <QSet>
#include <QStringList>

namespace opentop {

namespace {
QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::BusSpec", text);
}
// Splits at the commas outside braces; nothing when the braces do not pair.
std::optional<QStringList> splitItems(const QString& text)
{
    QStringList items;
    QString item;
    int depth = 0;
    for (const QChar c : text) {
        if (c == QLatin1Char('{') && ++depth > 1)
            return std::nullopt;
        if (c == QLatin1Char('}') && --depth < 0)
            return std::nullopt;
        if (c == QLatin1Char(',') && depth == 0) {
            if (!item.trimmed().isEmpty())
                items << item;
            item.clear();
        } else {
            item += c;
        }
    }
    if (depth != 0)
        return std::nullopt;
    if (!item.trimmed().isEmpty())
        items << item;
    return items;
}

} // namespace

std::optional<QVector<BusSpecEntry>> BusSpec::parse(const QString& text, QString* error)
{
    auto fail = [&](const QString& message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    const QString types = registry.deviceTypes().join(QStringLiteral(", "));
    QVector<BusSpecEntry> entries;
    QSet<int> used;
    const std::optional<QStringList> split = splitItems(text);
    if (!split)
        return fail(tr("\"%1\": the braces do not pair; a drive's defects are written in braces "
                       "after its number, e.g. dbu200@3{firmware=1.4,stall}")
                        .arg(text));
    const QStringList& items = *split;
    if (items.isEmpty())
        return fail(tr("empty device list; write TYPE@ID[,TYPE@ID...], e.g. dbu200@1,dcpid@7 "
                       "(types: %1)")
                        .arg(types));
    for (const QString& rawItem : items) {
        QString item = rawItem.trimmed();
        QString defects;
        if (const int brace = item.indexOf(QLatin1Char('{')); brace >= 0) {
            if (!item.endsWith(QLatin1Char('}')))
                return fail(tr("\"%1\": the defects in braces end the item, e.g. "
                               "dbu200@3{stall}")
                                .arg(item));
            defects = item.mid(brace + 1, item.size() - brace - 2).trimmed();
            item = item.left(brace).trimmed();
        }
        const int at = item.indexOf(QLatin1Char('@'));
        if (at <= 0)
            return fail(tr("\"%1\": write TYPE@ID or TYPE@FIRST-LAST, e.g. dbu200@1").arg(item));
        const QString type = item.left(at).trimmed().toLower();
        const Profile* profile = registry.forDeviceType(type);
        if (!profile)
            return fail(
                tr("\"%1\": unknown device type \"%2\"; known types: %3").arg(item, type, types));
        const QStringList ids = item.mid(at + 1).split(QLatin1Char('-'));
        bool ok1 = false;
        bool ok2 = ids.size() == 1;
        const int first = ids.value(0).trimmed().toInt(&ok1);
        const int last = ids.size() == 2 ? ids.value(1).trimmed().toInt(&ok2) : first;
        if (!ok1 || !ok2 || ids.size() > 2 || last < first)
            return fail(tr("\"%1\": the machine number must be a number or a range such as 1-16")
                            .arg(item));
        for (int id = first; id <= last; ++id) {
            if (id < profile->minSlave || id > profile->maxSlave)
                return fail(tr("\"%1\": machine number %2 is outside %3–%4 for %5")
                                .arg(item)
                                .arg(id)
                                .arg(profile->minSlave)
                                .arg(profile->maxSlave)
                                .arg(type));
            if (used.contains(id))
                return fail(tr("machine number %1 is given twice").arg(id));
            used.insert(id);
            entries.append({type, id, defects});
        }
    }
    return entries;
}

QString BusSpec::toString(const QVector<BusSpecEntry>& entries)
{
    QStringList items;
    for (const BusSpecEntry& e : entries)
        items << QStringLiteral("%1@%2").arg(e.type).arg(e.slave) +
                     (e.defects.isEmpty() ? QString() : QStringLiteral("{%1}").arg(e.defects));
    return items.join(QLatin1Char(','));
}

} // namespace opentop
