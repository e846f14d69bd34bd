#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <optional>

namespace opentop {

// The text of a drive's simulated defects, as the command line (`--defect 3:firmware=1.4`), the
// console (`defect 3 max_speed=800`) and a bus spec (`dbu200@3{stall}`) write it: a list of
// DEFECT items separated by commas. Only the syntax is checked here; whether a code or a
// parameter exists on a drive is checked against its profile by SimDefects::resolve.
//
//   firmware=MAJOR.MINOR    identification reports this firmware version (0..255 each)
//   max_speed=N             the motor ramps but saturates at N (DBU r/min, DC commutations/s)
//   stall                   the motor does not turn: speed 0, load (DC: current) high
//   load=+N | load=-N       adds N to the load rate (DBU, %) or N % to the current (DC)
//   load=xF                 multiplies the load rate / current by F (0.1..10)
//   alarm=CODE@TIME         after TIME of running: DBU alarm CODE (number or name, e.g. 0x07 or
//                           overload), DC `stall` (the stall stop brakes the motor)
//   nostick=PARAM           writes are acknowledged but not stored (name or address 0x1102)
//   nostore=PARAM           the value is taken, but lost at the next power cycle (DC: the
//                           store command does not store it)
//   turnaround=MS           with wire timing, the drive answers MS after the 3.5 character
//                           gap instead of the bus's --turnaround (a slow drive, up to 1000)
//   clear                   no defects (before the items after it)
struct SimDefectSpec
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SimDefectSpec)
public:
    std::optional<int> firmware; // raw version register: major << 8 | minor
    std::optional<int> maxSpeed;
    bool stall = false;
    std::optional<double> loadOffset;
    std::optional<double> loadScale;
    QString alarm; // code text as written: "0x07", "7", "overload", "stall"
    qint64 alarmAfterMs = 0;
    QStringList noStick; // parameter names or addresses as written
    QStringList noStore;
    std::optional<double> turnaroundMs;
    bool clear = false; // the list started from no defects

    bool isEmpty() const;
    // "firmware=1.4,max_speed=800" (normalised, clear left out).
    QString toString() const;
    // This spec with `later`'s items on top (later replaces what both set; clear resets).
    SimDefectSpec merged(const SimDefectSpec& later) const;

    // "DEFECT[,DEFECT...]".
    static std::optional<SimDefectSpec> parse(const QString& text, QString* error);
    // "ID:DEFECT[,DEFECT...]" of --defect; *slave gets the machine number (1..247).
    static std::optional<SimDefectSpec> parseOption(const QString& text, int* slave,
                                                    QString* error);
    // The allowed forms, one line each, for error messages and help.
    static QString forms();

private:
    static QString parseItem(const QString& item, SimDefectSpec* spec);
};

} // namespace opentop
