#include "model/files/RestorePlan.h"

#include "model/files/BackupValidator.h"
#include "model/profile/ValueCodec.h"
#include "model/profile/WriteOrder.h"
#include "model/session/SerialLock.h"

#include <QSet>
#include <algorithm>

namespace opentop {

namespace {

// The setting that locks the line settings, if the family has one (role "serialLock").
QString serialLock(const Profile& profile)
{
    const ProfileRole* role = profile.role(QStringLiteral("serialLock"));
    return role ? role->parameter : QString();
}

// Text that DeviceSession::write encodes to exactly these registers: a raw hexadecimal code
// where possible (no rounding through the scale), the shortest exact decimal otherwise.
QString exactText(const ParameterMeta& meta, const QVector<quint16>& registers,
                  const ValueContext& context)
{
    const ParamValue value = ValueCodec::decode(meta, registers, context);
    if (meta.type == DataType::String)
        return value.text;
    const double scale = meta.specFor(context).scale;
    if (meta.type == DataType::F32)
        return QString::number(double(float(value.raw)) * scale, 'g', 17);
    if (value.raw >= 0)
        return QStringLiteral("0x") + QString::number(qulonglong(value.raw), 16).toUpper();
    return QString::number(value.raw * scale, 'g', 17);
}

// The value of a store command that stores (1 on the DC controller: "Store to memory").
QString storeText(const ParameterMeta& command)
{
    for (const EnumOption& o : command.spec.options) {
        if (o.canonicalLabel.contains(QLatin1String("store"), Qt::CaseInsensitive))
            return QString::number(o.value);
    }
    if (command.spec.options.size() == 1)
        return QString::number(command.spec.options.first().value);
    return QStringLiteral("1");
}

} // namespace

bool RestorePlan::isCommunicationSetting(const Profile& profile, const ParameterMeta& meta)
{
    // Settings that change the line itself (role "communication"): written last.
    const ProfileRole* role = profile.role(QStringLiteral("communication"));
    return role && role->parameters.contains(meta.name);
}

RestorePlan RestorePlan::check(const Profile& profile, const QString& liveVariant,
                               const BackupDevice& file)
{
    RestorePlan plan;
    plan.slave = file.slave;
    plan.title = file.title();
    auto refuse = [&plan](const QString& reason) {
        plan.outcome = Outcome::Refused;
        plan.reason = reason;
        return plan;
    };
    if (file.family != profile.family)
        return refuse(tr("the file holds a %1 drive (%2), but machine number %3 is a %4 drive; "
                         "nothing written")
                          .arg(file.family, file.model)
                          .arg(file.slave)
                          .arg(profile.family));
    if (!file.variant.isEmpty() && !liveVariant.isEmpty() && file.variant != liveVariant) {
        const ProfileVariant* live = profile.variant(liveVariant);
        return refuse(tr("the file is from a %1 (%2), but machine number %3 is a %4 (%5); their "
                         "allowed values differ, nothing written")
                          .arg(file.model, file.variant)
                          .arg(file.slave)
                          .arg(live ? live->model : liveVariant, liveVariant));
    }
    if (liveVariant.isEmpty() && !profile.variants.isEmpty())
        plan.notes << tr("the drive does not tell its variant: every value must suit all "
                         "variants (name it with --variant to use its own ranges)");

    plan.problems = BackupValidator::checkStructure(profile, file);
    plan.problems += BackupValidator::checkValues(profile, file, liveVariant,
                                                  BackupValidator::UnknownVariant::AllMustFit);
    ValueContext context = file.context(profile);
    context.variant = liveVariant;
    if (liveVariant.isEmpty()) {
        for (const ProfileVariant& v : profile.variants)
            context.possibleVariants << v.id;
    }

    // Write order: controlling parameters (each after its own controllers), ordinary settings,
    // communication settings with the serial lock last.
    QSet<QString> controlling;
    for (const BackupParameter& p : file.parameters) {
        if (const ParameterMeta* meta = profile.parameter(p.name)) {
            for (const QString& c : meta->controllingParameters()) {
                if (file.parameter(c))
                    controlling.insert(c);
            }
        }
    }
    QStringList order;
    for (const BackupParameter& p : file.parameters)
        if (controlling.contains(p.name) && profile.parameter(p.name))
            order << p.name;
    order = WriteOrder::of(profile, order);
    QStringList ordinary, communication;
    for (const BackupParameter& p : file.parameters) {
        const ParameterMeta* meta = profile.parameter(p.name);
        if (!meta || order.contains(p.name))
            continue;
        if (!isCommunicationSetting(profile, *meta))
            ordinary << p.name;
        else if (p.name != serialLock(profile))
            communication << p.name;
    }
    order += ordinary + communication;
    if (!serialLock(profile).isEmpty() && file.parameter(serialLock(profile)))
        order << serialLock(profile);

    QStringList stores;
    for (const QString& name : order) {
        const ParameterMeta& meta = *profile.parameter(name);
        Item item;
        item.parameter = name;
        item.fileRegisters = file.parameter(name)->registers;
        item.fileText = file.text(profile, name);
        if (item.fileRegisters.size() == meta.registerCount) {
            item.writeText = exactText(meta, item.fileRegisters, context);
            const ValueCodec::Encoded encoded =
                ValueCodec::encodeText(meta, item.writeText, context);
            if (!encoded.ok)
                plan.problems << encoded.error;
            else if (encoded.registers != item.fileRegisters)
                plan.problems
                    << tr("%1: the value cannot be written exactly").arg(context.nameFor(name));
        }
        if (!meta.storeWith.isEmpty() && !stores.contains(meta.storeWith))
            stores << meta.storeWith;
        plan.items << item;
    }
    // Store commands in profile order, after the writes; build() keeps those that something
    // written needs (RestorePlan::build).
    std::sort(stores.begin(), stores.end(), [&profile](const QString& a, const QString& b) {
        return profile.parameter(a) < profile.parameter(b); // into the list: profile order
    });
    for (const QString& name : stores) {
        Item item;
        item.parameter = name;
        item.action = Item::Action::Store;
        item.writeText = storeText(*profile.parameter(name));
        plan.items << item;
    }
    plan.problems.removeDuplicates();
    if (!plan.problems.isEmpty())
        return refuse(tr("%n value(s) of the file may not be written to this drive; nothing "
                         "written",
                         "", int(plan.problems.size())));
    return plan;
}

void RestorePlan::build(const Profile& profile, const QString& liveVariant,
                        const QHash<QString, QVector<quint16>>& live, const QStringList& unstored)
{
    deviceRead = true;
    BackupDevice drive;
    drive.family = profile.family;
    drive.variant = liveVariant;
    for (const Item& item : items) {
        if (live.contains(item.parameter))
            drive.parameters << BackupParameter{item.parameter, live.value(item.parameter)};
    }
    int firstCommunication = -1;
    for (int i = 0; i < items.size(); ++i) {
        Item& item = items[i];
        if (item.action == Item::Action::Store)
            continue;
        const ParameterMeta* meta = profile.parameter(item.parameter);
        if (firstCommunication < 0 && meta && isCommunicationSetting(profile, *meta))
            firstCommunication = i;
        item.deviceRegisters = live.value(item.parameter);
        item.deviceText = drive.text(profile, item.parameter);
        const bool same = item.deviceRegisters == item.fileRegisters;
        item.action = same ? Item::Action::Keep : Item::Action::Write;
        item.status = same ? Item::Status::Unchanged : Item::Status::Pending;
    }
    // A lock being released goes before the settings it locks.
    for (int i = 0; i < items.size(); ++i) {
        const Item& item = items.at(i);
        const bool releases = !serialLock(profile).isEmpty() &&
                              item.parameter == serialLock(profile) &&
                              item.action == Item::Action::Write &&
                              std::all_of(item.fileRegisters.begin(), item.fileRegisters.end(),
                                          [](quint16 r) { return r == 0; });
        if (releases && firstCommunication >= 0 && firstCommunication < i) {
            items.move(i, firstCommunication);
            break;
        }
    }
    keepNeededStores(profile, unstored);
    // A lock being set can shut this program out of the drive: said before anything is written.
    const QString lock = lockWarning(profile);
    if (!lock.isEmpty())
        notes << lock;
}

void RestorePlan::keepNeededStores(const Profile& profile, const QStringList& unstored)
{
    // A store command is sent when this restore writes a setting it stores, or when one was
    // written earlier and not stored since (an interrupted restore, kept by StoreTracker and
    // BusMemory). What a drive has stored cannot be read back; a store for nothing would only
    // wear its memory and say that something changed.
    QStringList written;
    for (const Item& item : items) {
        const ParameterMeta* meta = profile.parameter(item.parameter);
        if (item.action == Item::Action::Write && meta && !meta->storeWith.isEmpty() &&
            !meta->writeBlock.isSet()) // the configuration frame stores itself
            written << meta->storeWith;
    }
    QStringList sent, earlier, dropped;
    for (int i = int(items.size()) - 1; i >= 0; --i) {
        if (items.at(i).action != Item::Action::Store)
            continue;
        const QString name = items.at(i).parameter;
        const ParameterMeta* meta = profile.parameter(name);
        const QString label = meta ? meta->label : name;
        if (written.contains(name)) {
            sent.prepend(label);
        } else if (unstored.contains(name)) {
            earlier.prepend(label);
        } else {
            dropped.prepend(label);
            items.removeAt(i);
        }
    }
    const QString list = QStringLiteral(", ");
    if (!sent.isEmpty())
        notes << tr("%1 sent after the writes, so that the settings written survive power-off")
                     .arg(sent.join(list));
    if (!earlier.isEmpty())
        notes << tr("%1 sent: settings written to this drive earlier (by an interrupted restore, "
                    "a page or the command line) are not stored yet")
                     .arg(earlier.join(list));
    if (!dropped.isEmpty())
        notes << tr("%1 not sent: nothing it stores is written. What a drive has stored cannot "
                    "be read back: if it loses settings at power-off, switch it off and on and "
                    "restore again")
                     .arg(dropped.join(list));
}

QString RestorePlan::lockWarning(const Profile& profile, const ValueContext& naming) const
{
    for (const Item& item : items) {
        const ParameterMeta* meta = profile.parameter(item.parameter);
        if (item.action == Item::Action::Write && meta && item.parameter == serialLock(profile))
            return SerialLock::warning(
                profile, *meta, qint64(ValueCodec::registersToRaw(*meta, item.fileRegisters)),
                naming);
    }
    return QString();
}

int RestorePlan::count(Item::Status status) const
{
    return int(std::count_if(items.begin(), items.end(),
                             [status](const Item& i) { return i.status == status; }));
}

int RestorePlan::count(Item::Action action) const
{
    return int(std::count_if(items.begin(), items.end(),
                             [action](const Item& i) { return i.action == action; }));
}

QString RestorePlan::actionText(Item::Action action)
{
    switch (action) {
    case Item::Action::Keep:
        return tr("keep");
    case Item::Action::Write:
        return tr("write");
    case Item::Action::Store:
        return tr("store");
    }
    return QString();
}

QString RestorePlan::statusText(const Item& item)
{
    switch (item.status) {
    case Item::Status::Pending:
        return actionText(item.action);
    case Item::Status::Unchanged:
        return tr("unchanged");
    case Item::Status::Verified:
        if (!item.error.isEmpty()) // held by the drive, not verified on every drive reached
            return tr("written, not verified: %1").arg(item.error);
        return item.action == Item::Action::Store ? tr("written") : tr("written and verified");
    case Item::Status::Failed:
        return tr("failed: %1").arg(item.error);
    case Item::Status::NotAttempted:
        return tr("not attempted");
    case Item::Status::NotConfirmed:
        return tr("not confirmed (%1): the drive may or may not hold it; run the restore again "
                  "to read it back")
            .arg(item.error);
    }
    return QString();
}

QString RestorePlan::statusKey(Item::Status status)
{
    static const char* const keys[] = {"pending", "unchanged",     "verified",
                                       "failed",  "not-attempted", "not-confirmed"};
    return QString::fromLatin1(keys[int(status)]);
}

QString RestorePlan::outcomeKey(Outcome outcome)
{
    static const char* const keys[] = {"planned",       "done",     "refused",
                                       "communication", "mismatch", "interrupted"};
    return QString::fromLatin1(keys[int(outcome)]);
}

QString RestorePlan::outcomeText(Outcome outcome)
{
    switch (outcome) {
    case Outcome::Planned:
        return tr("planned");
    case Outcome::Done:
        return tr("restored");
    case Outcome::Refused:
        return tr("refused");
    case Outcome::Communication:
        return tr("communication failure");
    case Outcome::Mismatch:
        return tr("verification mismatch");
    case Outcome::Interrupted:
        return tr("interrupted");
    }
    return QString();
}

} // namespace opentop
