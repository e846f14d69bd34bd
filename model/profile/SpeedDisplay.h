#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

namespace opentop {

class Profile;

// What a drive's own display shows for a motor speed, in the unit its speed display settings
// choose: shaft r/min behind a gear, linear speed of a roller in yd/min or m/min, or the time a
// roller takes for a distance. Formulas and assumptions: docs/speed-display.md.
//
// Data-driven: the settings are read from the parameters named in Names (by default the
// profile convention "unit.*"); a profile without the mode parameter has no speed display.
class SpeedDisplay
{
    Q_DECLARE_TR_FUNCTIONS(opentop::SpeedDisplay)
public:
    // Raw codes of the mode parameter and of the unit selectors (manual 12-10).
    enum class Mode
    {
        Rpm = 0,
        LinearYard = 1,
        LinearMeter = 2,
        Time = 3
    };

    // Parameter names of the settings. Corrections are ro-0..ro-3 for the speed sections
    // up to 500, 1000, 2000 and above 2000 r/min.
    struct Names
    {
        QString mode;
        QString reduction;
        QString increase;
        QString decimals;
        QString diameterYard;
        QString diameterMeter;
        QString timeDiameter;
        QString distanceUnit; // 0 = m, 1 = yd
        QString distance;
        QString timeUnit; // 0 = min (shown as m:ss), 1 = s
        QStringList corrections;

        static Names withPrefix(const QString& prefix = QStringLiteral("unit."));
        QStringList all() const;
    };

    // Engineering values of the settings. Roller diameters are in millimetres whatever the
    // display unit (docs/errata.md DBU-23).
    struct Settings
    {
        Mode mode = Mode::Rpm;
        double reduction = 1;
        double increase = 1;
        int decimals = 3;
        double diameterYard = 0;  // mm, for the yd/min display
        double diameterMeter = 0; // mm, for the m/min display
        double timeDiameter = 0;  // mm, for the time display
        bool distanceInYards = false;
        double distance = 0;
        bool timeInSeconds = false;
        int corrections[4] = {0, 0, 0, 0};
    };

    struct Shown
    {
        bool valid = false;    // false: no finite value (time at standstill, diameter 0)
        double value = 0;      // in `unit`; minutes for "min:s"
        QString text;          // as the drive shows it: "1500.000", "31.416", "2:05", "--:--"
        QString unit;          // "r/min", "yd/min", "m/min", "min:s", "s"
        QString panel;         // `text` as the drive's 5-digit panel shows it: "1500.0"
        bool overflow = false; // more digits than the panel has, even without decimals
    };

    // The digits of the drive's own speed display.
    static constexpr int kPanelDigits = 5;
    // `text` fitted to the panel's digits: decimals dropped as needed (the point takes no
    // digit, the minus does). Sets *overflow when even the integer part does not fit. The one
    // rule for what the panel shows, used by the monitor's panel mirror and every preview.
    static QString panelText(const QString& text, bool* overflow = nullptr);

    SpeedDisplay() = default;
    explicit SpeedDisplay(const Settings& settings)
        : m_settings(settings)
    {
    }

    // Whether `profile` has the settings (its mode parameter exists and is readable).
    static bool supported(const Profile& profile, const Names& names = Names::withPrefix());
    // Builds the display from decoded values (engineering numbers; enumeration codes as
    // numbers). Returns nothing and sets *error when a value is missing or out of range.
    // `nameFor` names a parameter in the error (its label in the program's windows); the
    // internal name when not given.
    static std::optional<SpeedDisplay> fromValues(
        const Names& names, const std::function<std::optional<double>(const QString&)>& value,
        QString* error = nullptr, const std::function<QString(const QString&)>& nameFor = {});

    const Settings& settings() const { return m_settings; }
    // The motor speed after the ro-n correction of its speed section (sign kept, never crosses
    // zero; a stopped motor stays 0).
    double correctedMotorRpm(double motorRpm) const;
    // Output shaft speed: corrected motor r/min ÷ reduction × increase.
    double shaftRpm(double motorRpm) const;
    // Signed motor speed (CCW or reverse negative) -> what the display shows.
    Shown show(double motorRpm) const;
    // The unit `show` uses, e.g. for column headers.
    QString unit() const;
    // Index 0..3 of the correction used at `motorRpm`, -1 at standstill.
    static int section(double motorRpm);

private:
    Settings m_settings;
};

} // namespace opentop
