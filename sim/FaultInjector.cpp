#include "sim/FaultInjector.h"

#include <QStringList>
#include <cmath>

namespace opentop {

FaultInjector::FaultInjector()
    : FaultInjector(Rates())
{
}

FaultInjector::FaultInjector(const Rates& rates, quint32 seed)
    : m_rates(rates)
    , m_random(seed)
{
}

std::optional<FaultInjector::Rates> FaultInjector::parse(const QString& text, QString* error)
{
    Rates rates;
    const QString allowed = QStringLiteral("drop, crc, late, busy (rates 0..1), late_ms (ms)");
    const QStringList items = text.split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString& item : items) {
        const QStringList kv = item.trimmed().split(QLatin1Char('='));
        const QString key = kv.first().trimmed();
        if (kv.size() != 2 || key.isEmpty()) {
            if (error)
                *error =
                    tr("fault '%1' must be NAME=VALUE; names: %2").arg(item.trimmed(), allowed);
            return std::nullopt;
        }
        bool ok = false;
        const double value = kv.at(1).trimmed().toDouble(&ok);
        if (key == QLatin1String("late_ms")) {
            if (!ok || value < 1 || value > 60000 || value != std::floor(value)) {
                if (error)
                    *error = tr("late_ms must be a whole number of milliseconds 1..60000, got '%1'")
                                 .arg(kv.at(1));
                return std::nullopt;
            }
            rates.lateMs = int(value);
            continue;
        }
        double* target = key == QLatin1String("drop")   ? &rates.drop
                         : key == QLatin1String("crc")  ? &rates.crc
                         : key == QLatin1String("late") ? &rates.late
                         : key == QLatin1String("busy") ? &rates.busy
                                                        : nullptr;
        if (!target) {
            if (error)
                *error = tr("unknown fault '%1'; allowed: %2").arg(key, allowed);
            return std::nullopt;
        }
        if (!ok || value < 0 || value > 1) {
            if (error)
                *error = tr("fault rate %1 must be a number 0..1, got '%2'").arg(key, kv.at(1));
            return std::nullopt;
        }
        *target = value;
    }
    if (rates.drop + rates.crc + rates.late + rates.busy > 1.0 + 1e-9) {
        if (error)
            *error = tr("the fault rates add up to more than 1");
        return std::nullopt;
    }
    return rates;
}

bool FaultInjector::isActive() const
{
    return m_rates.drop + m_rates.crc + m_rates.late + m_rates.busy > 0;
}

FaultInjector::Fault FaultInjector::next()
{
    if (!isActive())
        return Fault::None;
    double u = m_uniform(m_random);
    const std::pair<double, Fault> bands[] = {{m_rates.drop, Fault::Drop},
                                              {m_rates.crc, Fault::Crc},
                                              {m_rates.late, Fault::Late},
                                              {m_rates.busy, Fault::Busy}};
    for (const auto& [rate, fault] : bands) {
        if (u < rate)
            return fault;
        u -= rate;
    }
    return Fault::None;
}

QString FaultInjector::faultName(Fault fault)
{
    switch (fault) {
    case Fault::Drop:
        return QStringLiteral("drop");
    case Fault::Crc:
        return QStringLiteral("crc");
    case Fault::Late:
        return QStringLiteral("late");
    case Fault::Busy:
        return QStringLiteral("busy");
    case Fault::None:
        break;
    }
    return QStringLiteral("none");
}

} // namespace opentop
