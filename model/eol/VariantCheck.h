#pragma once

#include "model/eol/VariantDecision.h"

#include <QObject>
#include <functional>

namespace opentop {

class ModbusClient;

// A position's variant on the bus: the profile's probe when the drive does not report its
// variant (VariantProber), then VariantDecision. Run after the motor was found stopped and
// before anything of the recipe is written.
class VariantCheck : public QObject
{
    Q_OBJECT
public:
    VariantCheck(ModbusClient* client, const Profile& profile, const RecipePosition& position,
                 VariantDecision::Evidence evidence, QObject* parent = nullptr);

    // Whether the probe is run (to show as a phase); "" when it is not.
    QString probeText() const;
    // `done` runs once, never before run() returns.
    void run(std::function<void(const VariantDecision::Decision&)> done);

private:
    ModbusClient* m_client;
    const Profile& m_profile;
    RecipePosition m_position;
    VariantDecision::Evidence m_evidence;
    std::optional<VariantProbe> m_probe;
};

} // namespace opentop
