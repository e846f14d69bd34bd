#include "model/profile/AddressSwitches.h"

#include "model/profile/JsonReader.h"

namespace opentop {

QString AddressSwitches::positions(int slave) const
{
    switch (notation) {
    case Notation::None:
        break;
    case Notation::HexRotary: {
        QStringList parts;
        for (int i = 0; i < names.size(); ++i) {
            const int digit = (slave >> (4 * (names.size() - 1 - i))) & 0xF;
            parts << QStringLiteral("%1=%2").arg(names[i], QString::number(digit, 16).toUpper());
        }
        return parts.join(QLatin1Char(' '));
    }
    case Notation::BinaryDip: {
        // "ON" as printed on the switch block, in every language.
        QStringList on;
        for (int bit = 0; bit < names.size(); ++bit) {
            if (slave & (1 << bit))
                on << names[bit];
        }
        return QStringLiteral("DIP ON: ") +
               (on.isEmpty() ? QStringLiteral("—") : on.join(QLatin1Char(',')));
    }
    }
    return QString();
}

int AddressSwitches::highest() const
{
    switch (notation) {
    case Notation::None:
        return 0;
    case Notation::HexRotary:
        return (1 << (4 * names.size())) - 1;
    case Notation::BinaryDip:
        return (1 << names.size()) - 1;
    }
    return 0;
}

bool AddressSwitches::read(const QJsonObject& root, JsonReader& json, int maxSlave,
                           AddressSwitches* out)
{
    *out = AddressSwitches();
    if (!root.contains(QStringLiteral("address")))
        return true;
    const QJsonObject o = json.object(root, QStringLiteral("address")).value_or(QJsonObject());
    if (json.failed() ||
        !json.onlyKeys(
            o, {QStringLiteral("switches"), QStringLiteral("names"), QStringLiteral("help")},
            QStringLiteral("address")))
        return false;
    const QString switches = json.string(o, QStringLiteral("switches")).value_or(QString());
    out->help = json.string(o, QStringLiteral("help"), false).value_or(QString());
    const QJsonArray names = json.array(o, QStringLiteral("names")).value_or(QJsonArray());
    if (json.failed())
        return false;
    for (const QJsonValue& n : names) {
        if (!n.isString() || n.toString().trimmed().isEmpty())
            return json.fail(tr("address.names: every switch needs a name"));
        out->names << n.toString();
    }
    if (switches == QLatin1String("hex-rotary"))
        out->notation = Notation::HexRotary;
    else if (switches == QLatin1String("binary-dip"))
        out->notation = Notation::BinaryDip;
    else
        return json.fail(tr("address.switches must be \"hex-rotary\" or \"binary-dip\""));
    // Machine numbers end at 247: two hexadecimal digits or eight bits at most.
    const int most = out->notation == Notation::HexRotary ? 2 : 8;
    if (out->names.isEmpty() || out->names.size() > most)
        return json.fail(tr("address.names: 1–%1 switches for this notation").arg(most));
    // The switches must reach every machine number the profile allows.
    if (out->highest() < maxSlave)
        return json.fail(tr("address: the switches (%1) cannot set machine number %2")
                             .arg(out->names.join(QStringLiteral(", ")))
                             .arg(maxSlave));
    return true;
}

} // namespace opentop
