#pragma once

#include "model/tuning/PidGains.h"

#include <QCoreApplication>
#include <QStringList>
#include <optional>

namespace opentop {

struct TuningSpec;

// Tuning rules from the ultimate gain Ku and period Tu, as continuous gains Kp, Ti, Td,
// converted to the controller's coefficients (TuningSpec: u = P·e + I·Σe + D·Δe over the D
// period, once per controller period):  P = Kp,  I = Kp·period/Ti,  D = Kp·Td/(D period).
class TuningRules
{
    Q_DECLARE_TR_FUNCTIONS(opentop::TuningRules)
public:
    enum class Rule
    {
        Soft,            // Ziegler–Nichols "no overshoot": 0.2 Ku, Tu/2, Tu/3
        Medium,          // Ziegler–Nichols "some overshoot": 0.33 Ku, Tu/2, Tu/3
        Stiff,           // Ziegler–Nichols classic: 0.6 Ku, Tu/2, Tu/8
        TyreusLuyben,    // Ku/2.2, 2.2 Tu, Tu/6.3: robust, little overshoot
        ZieglerNicholsPi // 0.45 Ku, Tu/1.2, no D
    };
    struct Continuous
    {
        double kp = 0;
        double tiMs = 0;
        double tdMs = 0;
    };

    static QStringList ids(); // "soft", "medium", "stiff", "tyreus-luyben", "zn-pi"
    static std::optional<Rule> fromId(const QString& id);
    static QString id(Rule rule);
    static QString title(Rule rule); // for people
    // The overshoot (% of a step) the rule promises: the proposal must not exceed it on the
    // plant's model (GainDesign).
    static double overshootBound(Rule rule);

    static Continuous continuous(Rule rule, double ku, double tuMs);
    static PidGains toController(const Continuous& c, const TuningSpec& spec, int dPeriodMs);
    static PidGains propose(Rule rule, double ku, double tuMs, const TuningSpec& spec,
                            int dPeriodMs);
};

} // namespace opentop
