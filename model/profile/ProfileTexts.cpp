#include "model/profile/ProfileTexts.h"

namespace opentop {

namespace {

using Visit = std::function<void(const QString& key, QString& text)>;

void visitOptions(QVector<EnumOption>& options, const QString& prefix, const Visit& visit)
{
    for (EnumOption& o : options) {
        const QString key = prefix + QStringLiteral(".enum.") + QString::number(o.value);
        visit(key, o.label);
        visit(key + QStringLiteral(".help"), o.help);
    }
}

} // namespace

QMap<QString, QString> ProfileTexts::of(const Profile& profile)
{
    QMap<QString, QString> texts;
    // Visiting needs a mutable profile; a copy keeps `of` honest about not changing it.
    Profile copy = profile;
    visitTexts(copy, false, [&](const QString& key, QString& text) {
        if (!text.trimmed().isEmpty()) // extract.py leaves out blank texts
            texts.insert(key, text);
    });
    // A text that names settings is keyed as written ({setting:…}), not as resolved for people.
    for (auto it = profile.referencedTexts.cbegin(); it != profile.referencedTexts.cend(); ++it) {
        if (texts.contains(it.key()))
            texts.insert(it.key(), it.value());
    }
    return texts;
}

void ProfileTexts::forEachText(Profile& profile, const Visit& visit)
{
    visitTexts(profile, true, visit);
}

void ProfileTexts::visitTexts(Profile& profile, bool inherited, const Visit& visit)
{
    visit(QStringLiteral("name"), profile.name);
    visit(QStringLiteral("address.help"), profile.addressSwitches.help);
    visit(QStringLiteral("serial.formatHelp"), profile.serial.formatHelp);
    for (ProfileVariant& v : profile.variants)
        visit(QStringLiteral("variants.%1.label").arg(v.id), v.label);
    for (ProfileGroup& g : profile.groups) {
        visit(QStringLiteral("groups.%1.label").arg(g.id), g.label);
        visit(QStringLiteral("groups.%1.help").arg(g.id), g.help);
    }
    for (auto it = profile.codeTables.begin(); it != profile.codeTables.end(); ++it) {
        const QString table = QStringLiteral("codeTables.") + it.key();
        visit(table + QStringLiteral(".label"), it->label);
        for (CodeEntry& e : it->entries) {
            const QString entry = table + QLatin1Char('.') + QString::number(e.code);
            visit(entry + QStringLiteral(".name"), e.name);
            visit(entry + QStringLiteral(".resetText"), e.resetText);
            visit(entry + QStringLiteral(".cause"), e.cause);
            visit(entry + QStringLiteral(".remedy"), e.remedy);
        }
    }
    for (StatusLedEntry& e : profile.statusLed) {
        const QString led = QStringLiteral("statusLed.") + e.light;
        visit(led + QStringLiteral(".label"), e.label);
        visit(led + QStringLiteral(".meaning"), e.meaning);
        visit(led + QStringLiteral(".blink"), e.blink);
    }
    for (ParameterMeta& p : profile.parameters) {
        const QString param = QStringLiteral("parameters.") + p.name;
        visit(param + QStringLiteral(".label"), p.label);
        visit(param + QStringLiteral(".help"), p.help);
        visit(param + QStringLiteral(".unit"), p.spec.unit);
        visit(param + QStringLiteral(".note"), p.spec.note);
        visitOptions(p.spec.options, param, visit);
        for (BitField& b : p.bits) {
            const QString bit = param + QStringLiteral(".bits.") + b.name;
            visit(bit + QStringLiteral(".label"), b.label);
            for (int i = 0; i < b.values.size(); ++i)
                visit(bit + QStringLiteral(".values.") + QString::number(i), b.values[i]);
        }
        for (int i = 0; i < p.conditions.size(); ++i) {
            ValueCondition& c = p.conditions[i];
            const QString own = param + QStringLiteral(".w") + QString::number(i);
            if (c.ownUnit || inherited)
                visit((c.ownUnit ? own : param) + QStringLiteral(".unit"), c.spec.unit);
            if (c.ownNote || inherited)
                visit((c.ownNote ? own : param) + QStringLiteral(".note"), c.spec.note);
            if (c.ownOptions || inherited)
                visitOptions(c.spec.options, c.ownOptions ? own : param, visit);
        }
    }
}

} // namespace opentop
