#pragma once

#include <QCoreApplication>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <optional>

namespace opentop {

class JsonReader;

// How a family's machine number is set on the device (profile key "address"), so that every
// place that shows a number's switches shows the family's own notation: the DBU's two
// hexadecimal rotary switches SW1/SW2 ("SW1=9 SW2=6" for 150), the DC controller's DIP switches
// 1–7 in binary ("DIP ON: 1,2,3" for 7).
class AddressSwitches
{
    Q_DECLARE_TR_FUNCTIONS(opentop::AddressSwitches)
public:
    enum class Notation
    {
        None,      // the profile does not say
        HexRotary, // one rotary switch per hexadecimal digit, high digit first
        BinaryDip, // one DIP switch per bit, lowest bit first; ON adds its value
    };

    Notation notation = Notation::None;
    QStringList names; // the switches as printed on the device: "SW1", "SW2" / "1" … "7"
    QString help;      // for people: where the switches are and how to read them

    // The switch positions for `slave`: "SW1=9 SW2=6", "DIP ON: 1,2,3"; empty for None.
    QString positions(int slave) const;
    // Whether the switches show the number in hexadecimal (then "96h" means something).
    bool showsHex() const { return notation == Notation::HexRotary; }
    // The highest machine number the switches can set (0: no limit known).
    int highest() const;

    // Reads "address" of a profile's top level (optional); false with the error in `json`.
    static bool read(const QJsonObject& root, JsonReader& json, int maxSlave, AddressSwitches* out);
};

} // namespace opentop
