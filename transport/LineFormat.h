#pragma once

#include <QMap>
#include <QString>
#include <optional>

namespace opentop {

// The character format and rate a drive talks at: "19200 8N1", "9600 8E1". One port may carry
// drives of different formats (a DBU works only at 8N1, a DC controller at 8E1, 8O1 or 8N2):
// a request can carry the format of the drive it goes to, and the RTU backend switches the
// port between transactions. An unset format (baud 0) means the port's own.
struct LineFormat
{
    int baud = 0; // 0: not set (the port's format)
    char parity = 'N';
    int dataBits = 8;
    int stopBits = 1;

    bool isSet() const { return baud > 0; }
    // "8E1"
    QString frameText() const;
    // "9600 8E1" for people; "9600:8E1" for specs and options (token()).
    QString text() const;
    QString token() const;
    // Empty when usable; otherwise what is wrong and what is allowed.
    QString validate() const;
    // Whether a receiver set to this format takes characters sent in `sent`: same rate, data
    // bits and parity. Stop bits do not matter: a UART checks only the first stop bit, so 8N2
    // and 8N1 hear each other (the DC controller has no 8N1; its 8N2 joins an 8N1 bus).
    bool hears(const LineFormat& sent) const;
    // Start + data + parity + stop bits, in ms.
    double charTimeMs() const;

    // "8E1" (with `baud`), "9600:8E1", "9600 8E1" or "8E1@9600"; nothing (and *error) when
    // it is none of them or not allowed.
    static std::optional<LineFormat> parse(const QString& text, int defaultBaud,
                                           QString* error = nullptr);
    // "7=9600:8E1,9=8N2" (a baud left out is `defaultBaud`): machine number → format.
    static std::optional<QMap<int, LineFormat>> parseTable(const QString& text, int defaultBaud,
                                                           QString* error = nullptr);
    static QString tableText(const QMap<int, LineFormat>& table);

    bool operator==(const LineFormat& o) const
    {
        return baud == o.baud && parity == o.parity && dataBits == o.dataBits &&
               stopBits == o.stopBits;
    }
    bool operator!=(const LineFormat& o) const { return !(*this == o); }
};

} // namespace opentop
