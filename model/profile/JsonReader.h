#pragma once

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <optional>

namespace opentop {

// Small typed accessors over QJsonObject that record the first error with its key, so that
// profile errors can name exactly the entry that is wrong.
class JsonReader
{
public:
    explicit JsonReader(QString* error)
        : m_error(error)
    {
    }

    bool failed() const { return m_failed; }
    bool fail(const QString& message);

    std::optional<QString> string(const QJsonObject& o, const QString& key, bool required = true);
    std::optional<double> number(const QJsonObject& o, const QString& key, bool required = true);
    // Integers may be given as numbers or as strings "0x1A2B".
    std::optional<qint64> integer(const QJsonObject& o, const QString& key, bool required = true);
    std::optional<qint64> integerValue(const QJsonValue& v, const QString& where);
    std::optional<QJsonArray> array(const QJsonObject& o, const QString& key, bool required = true);
    std::optional<QJsonObject> object(const QJsonObject& o, const QString& key,
                                      bool required = true);
    // Keys not in `known` are errors (a typo in a profile must not pass silently).
    bool onlyKeys(const QJsonObject& o, const QStringList& known, const QString& where);

private:
    QString* m_error;
    bool m_failed = false;
};

} // namespace opentop
