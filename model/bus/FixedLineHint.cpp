#include "model/bus/FixedLineHint.h"

#include <QCoreApplication>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::FixedLineHint", text);
}

} // namespace

FixedLineHint FixedLineHint::dcPotentiometer()
{
    return FixedLineHint(); // the members' defaults are the manual's (1.1)
}

bool FixedLineHint::worthRetrying(const ConnectionSettings& settings, int from, int to) const
{
    if (settings.kind == ConnectionSettings::Kind::Tcp)
        return false; // the gateway's line is not ours to set
    const bool sameLine =
        settings.baud == m_baud && settings.parity == m_parity && settings.stopBits == m_stopBits;
    return !sameLine || m_slave < from || m_slave > to;
}

ConnectionSettings FixedLineHint::applyTo(ConnectionSettings settings) const
{
    settings.baud = m_baud;
    settings.parity = m_parity;
    settings.dataBits = 8;
    settings.stopBits = m_stopBits;
    return settings;
}

QString FixedLineHint::explanation() const
{
    return tr("A DC controller in potentiometer/analog control mode talks only at %1 bit/s, "
              "8%2%3, address %4.")
        .arg(m_baud)
        .arg(QLatin1Char(m_parity))
        .arg(m_stopBits)
        .arg(m_slave);
}

QString FixedLineHint::commandLine() const
{
    return QStringLiteral("--baud %1 --parity %2 --stop-bits %3 scan --from %4 --to %4")
        .arg(m_baud)
        .arg(QLatin1Char(m_parity))
        .arg(m_stopBits)
        .arg(m_slave);
}

QString FixedLineHint::shortText() const
{
    return tr("%1 8%2%3, address %4")
        .arg(m_baud)
        .arg(QLatin1Char(m_parity))
        .arg(m_stopBits)
        .arg(m_slave);
}

} // namespace opentop
