#include "sim/DcMotor.h"

#include <QRegularExpression>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace opentop {

namespace {

constexpr double kDt = 0.001; // s
constexpr double kTwoPi = 6.283185307179586;

struct Key
{
    const char* name;
    double DcMotor::Model::*field;
    double min;
    double max;
};
const Key kKeys[] = {
    {"supply", &DcMotor::Model::supplyV, 9, 36},
    {"resistance", &DcMotor::Model::resistanceOhm, 0.01, 100},
    {"no_load", &DcMotor::Model::noLoadCommutation, 10, 2000},
    {"commutations", &DcMotor::Model::commutationsPerRev, 1, 1000},
    {"inertia", &DcMotor::Model::inertia, 1e-7, 1},
    {"viscous", &DcMotor::Model::viscous, 0, 1},
    {"coulomb", &DcMotor::Model::coulomb, 0, 10},
    {"load", &DcMotor::Model::loadTorque, 0, 10},
    {"gate", &DcMotor::Model::gateMs, 1, 100},
    {"tacho", &DcMotor::Model::tachoVoltsPerCommutation, 0.0001, 1},
};

double sign(double v)
{
    return v > 0 ? 1 : v < 0 ? -1 : 0;
}

} // namespace

QStringList DcMotor::Model::keys()
{
    QStringList names;
    for (const Key& k : kKeys)
        names << QString::fromLatin1(k.name);
    return names;
}

std::optional<DcMotor::Model> DcMotor::Model::parse(const QString& text, const Model& base,
                                                    QString* error)
{
    Model m = base;
    for (const QString& item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const int eq = item.indexOf(QLatin1Char('='));
        const QString key = item.left(eq).trimmed().toLower();
        const Key* found = nullptr;
        for (const Key& k : kKeys) {
            if (key == QLatin1String(k.name))
                found = &k;
        }
        if (eq < 0 || !found) {
            *error = tr("unknown motor setting '%1'; settings: %2")
                         .arg(item.trimmed(), keys().join(QStringLiteral(", ")));
            return std::nullopt;
        }
        bool ok = false;
        const double v = item.mid(eq + 1).trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v) || v < found->min || v > found->max) {
            *error = tr("motor setting %1 must be a number %2..%3, got '%4'")
                         .arg(key)
                         .arg(found->min)
                         .arg(found->max)
                         .arg(item.mid(eq + 1).trimmed());
            return std::nullopt;
        }
        m.*(found->field) = v;
    }
    return m;
}

QString DcMotor::Model::toString() const
{
    QStringList items;
    for (const Key& k : kKeys)
        items << QStringLiteral("%1=%2").arg(QLatin1String(k.name)).arg(this->*(k.field));
    return items.join(QLatin1Char(','));
}

DcMotor::DcMotor()
{
    reset();
}

void DcMotor::reset()
{
    m_omega = 0;
    m_current = 0;
    m_duty = 0;
    m_gate.fill(0, std::max(1, int(std::lround(m_model.gateMs))));
    m_gateNext = 0;
    m_gateSum = 0;
}

double DcMotor::ke() const
{
    const double noLoadOmega = m_model.noLoadCommutation * kTwoPi / m_model.commutationsPerRev;
    return m_model.supplyV / noLoadOmega;
}

double DcMotor::commutation() const
{
    return m_omega * m_model.commutationsPerRev / kTwoPi;
}

double DcMotor::measuredCommutation() const
{
    return m_gateSum / m_gate.size();
}

void DcMotor::step(const Input& in)
{
    const double k = ke();
    const double r = m_model.resistanceOhm;
    const double emf = k * m_omega;
    const double vs = m_model.supplyV;
    const auto limit = [](double i, double max) { return max > 0 ? std::clamp(i, -max, max) : i; };
    double i = 0;
    switch (in.drive) {
    case Drive::Duty:
        i = limit((std::clamp(in.duty, -1.0, 1.0) * vs - emf) / r, in.maxCurrentA);
        break;
    case Drive::Current:
        i = limit(std::clamp(in.currentA, (-vs - emf) / r, (vs - emf) / r), in.maxCurrentA);
        break;
    case Drive::Brake:
        i = limit(-emf / r, in.brakeCurrentA);
        break;
    case Drive::Hold:
        i = -emf / r;
        break;
    case Drive::Coast:
        break;
    }
    m_current = i;
    m_duty = in.drive == Drive::Duty || in.drive == Drive::Current ? (i * r + emf) / vs : 0;

    // Mechanics: friction and load oppose the motion; at rest they hold the shaft until the
    // motor's torque overcomes them.
    const double drive = k * i;
    const double resisting = m_model.coulomb + m_model.loadTorque;
    double omega = m_omega;
    if (omega == 0 && std::abs(drive) <= resisting) {
        omega = 0;
    } else {
        const double direction = omega != 0 ? sign(omega) : sign(drive);
        const double torque = drive - m_model.viscous * omega - direction * resisting;
        const double next = omega + torque / m_model.inertia * kDt;
        // Friction alone stops the shaft; it never turns it back.
        omega = (sign(next) != direction && std::abs(drive) <= resisting) ? 0 : next;
    }
    if (in.drive == Drive::Hold && std::abs(omega) < 1)
        omega = 0;
    if (in.maxCommutation) {
        const double maxOmega = *in.maxCommutation * kTwoPi / m_model.commutationsPerRev;
        omega = std::clamp(omega, -maxOmega, maxOmega);
    }
    m_omega = omega;

    const int gate = std::max(1, int(std::lround(m_model.gateMs)));
    if (m_gate.size() != gate) {
        m_gate.fill(commutation(), gate);
        m_gateSum = commutation() * gate;
        m_gateNext = 0;
    }
    m_gateSum += commutation() - m_gate[m_gateNext];
    m_gate[m_gateNext] = commutation();
    m_gateNext = (m_gateNext + 1) % gate;
}

} // namespace opentop
