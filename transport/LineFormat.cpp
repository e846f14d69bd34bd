#include "transport/LineFormat.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::LineFormat", text);
}

} // namespace

QString LineFormat::frameText() const
{
    return QStringLiteral("%1%2%3").arg(dataBits).arg(QLatin1Char(parity)).arg(stopBits);
}

QString LineFormat::text() const
{
    return QStringLiteral("%1 %2").arg(baud).arg(frameText());
}

QString LineFormat::token() const
{
    return QStringLiteral("%1:%2").arg(baud).arg(frameText());
}

QString LineFormat::validate() const
{
    QStringList problems;
    if (baud < 1200 || baud > 115200)
        problems << tr("Baud rate %1 is not supported: use 1200–115200.").arg(baud);
    if (parity != 'N' && parity != 'E' && parity != 'O')
        problems << tr("Parity '%1' is not supported: use N (none), E (even) or O (odd).")
                        .arg(QLatin1Char(parity));
    if (dataBits != 7 && dataBits != 8)
        problems << tr("%1 data bits are not supported: use 7 or 8.").arg(dataBits);
    if (stopBits != 1 && stopBits != 2)
        problems << tr("%1 stop bits are not supported: use 1 or 2.").arg(stopBits);
    return problems.join(QLatin1Char(' '));
}

bool LineFormat::hears(const LineFormat& sent) const
{
    return baud == sent.baud && dataBits == sent.dataBits && parity == sent.parity;
}

double LineFormat::charTimeMs() const
{
    const int bits = 1 + dataBits + (parity == 'N' ? 0 : 1) + stopBits;
    return 1000.0 * bits / (baud > 0 ? baud : 19200);
}

std::optional<LineFormat> LineFormat::parse(const QString& text, int defaultBaud, QString* error)
{
    static const QRegularExpression re(QStringLiteral(
        "^\\s*(?:(\\d+)\\s*[: ]\\s*)?([78])([NEOneo])([12])(?:\\s*@\\s*(\\d+))?\\s*$"));
    const QRegularExpressionMatch m = re.match(text);
    if (!m.hasMatch() || (!m.captured(1).isEmpty() && !m.captured(5).isEmpty())) {
        if (error)
            *error = tr("\"%1\" is not a line format: write DATA BITS, PARITY and STOP BITS as "
                        "8N1, 8E1, 8O1 or 8N2, with the baud rate before it if it differs from "
                        "the port's (9600:8E1)")
                         .arg(text);
        return std::nullopt;
    }
    LineFormat f;
    const QString rate = m.captured(1).isEmpty() ? m.captured(5) : m.captured(1);
    f.baud = rate.isEmpty() ? defaultBaud : rate.toInt();
    f.dataBits = m.captured(2).toInt();
    f.parity = m.captured(3).toUpper().at(0).toLatin1();
    f.stopBits = m.captured(4).toInt();
    const QString invalid = f.validate();
    if (!invalid.isEmpty()) {
        if (error)
            *error = tr("\"%1\": %2").arg(text, invalid);
        return std::nullopt;
    }
    return f;
}

std::optional<QMap<int, LineFormat>> LineFormat::parseTable(const QString& text, int defaultBaud,
                                                            QString* error)
{
    QMap<int, LineFormat> table;
    for (const QString& rawItem : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const QString item = rawItem.trimmed();
        const int eq = item.indexOf(QLatin1Char('='));
        bool ok = false;
        const int slave = eq > 0 ? item.left(eq).trimmed().toInt(&ok) : 0;
        if (!ok || slave < 1 || slave > 247) {
            if (error)
                *error = tr("\"%1\": write MACHINE NUMBER=FORMAT, e.g. 7=9600:8E1 or 7=8N2 "
                            "(machine numbers 1–247)")
                             .arg(item);
            return std::nullopt;
        }
        QString why;
        const std::optional<LineFormat> f = parse(item.mid(eq + 1), defaultBaud, &why);
        if (!f) {
            if (error)
                *error = tr("machine number %1: %2").arg(slave).arg(why);
            return std::nullopt;
        }
        table.insert(slave, *f);
    }
    return table;
}

QString LineFormat::tableText(const QMap<int, LineFormat>& table)
{
    QStringList items;
    for (auto it = table.begin(); it != table.end(); ++it)
        items << QStringLiteral("%1=%2").arg(it.key()).arg(it->token());
    return items.join(QLatin1Char(','));
}

} // namespace opentop
