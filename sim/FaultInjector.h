#pragma once

#include <QCoreApplication>
#include <QString>
#include <optional>
#include <random>

namespace opentop {

// Rates (0..1) of the faults FaultInjector draws; they add up to at most 1.
struct FaultRates
{
    double drop = 0;
    double crc = 0;
    double late = 0;
    double busy = 0;
    int lateMs = 1000;
};

// Random communication faults with fixed rates, reproducible from a seed. One draw per reply:
// drop (the device executed the request but its reply is lost), crc (the reply's CRC is
// corrupted), late (the reply comes after lateMs), busy (the device refuses without executing).
class FaultInjector
{
    Q_DECLARE_TR_FUNCTIONS(opentop::FaultInjector)
public:
    enum class Fault
    {
        None,
        Drop,
        Crc,
        Late,
        Busy
    };

    using Rates = FaultRates;

    FaultInjector();
    explicit FaultInjector(const Rates& rates, quint32 seed = 1);

    // "drop=0.02,crc=0.01,late=0.01,busy=0.01[,late_ms=1500]"; empty text: no faults.
    static std::optional<Rates> parse(const QString& text, QString* error);

    const Rates& rates() const { return m_rates; }
    bool isActive() const;
    Fault next();
    int lateMs() const { return m_rates.lateMs; }
    static QString faultName(Fault fault);

private:
    Rates m_rates;
    std::mt19937 m_random;
    std::uniform_real_distribution<double> m_uniform{0.0, 1.0};
};

} // namespace opentop
