#include "model/profile/JsonReader.h"

#include <QCoreApplication>
#include <QStringList>
#include <cmath>

namespace opentop {

namespace {
QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::JsonReader", text);
}
} // namespace

bool JsonReader::fail(const QString& message)
{
    if (!m_failed && m_error)
        *m_error = message;
    m_failed = true;
    return false;
}

std::optional<QString> JsonReader::string(const QJsonObject& o, const QString& key, bool required)
{
    const QJsonValue v = o.value(key);
    if (v.isUndefined() || v.isNull()) {
        if (required)
            fail(tr("\"%1\" is missing").arg(key));
        return std::nullopt;
    }
    if (!v.isString()) {
        fail(tr("\"%1\" must be a string").arg(key));
        return std::nullopt;
    }
    return v.toString();
}

std::optional<double> JsonReader::number(const QJsonObject& o, const QString& key, bool required)
{
    const QJsonValue v = o.value(key);
    if (v.isUndefined() || v.isNull()) {
        if (required)
            fail(tr("\"%1\" is missing").arg(key));
        return std::nullopt;
    }
    if (!v.isDouble()) {
        fail(tr("\"%1\" must be a number").arg(key));
        return std::nullopt;
    }
    return v.toDouble();
}

std::optional<qint64> JsonReader::integerValue(const QJsonValue& v, const QString& where)
{
    if (v.isDouble()) {
        const double d = v.toDouble();
        if (d != std::floor(d)) {
            fail(tr("%1 must be a whole number").arg(where));
            return std::nullopt;
        }
        // Converting a double beyond qint64 is undefined behaviour (found by FuzzProfileLoader).
        if (!(std::fabs(d) < 9.0e15)) {
            fail(tr("%1 is out of range").arg(where));
            return std::nullopt;
        }
        return static_cast<qint64>(d);
    }
    if (v.isString()) {
        QString s = v.toString().trimmed();
        bool ok = false;
        qint64 value = 0;
        if (s.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
            value = s.mid(2).toLongLong(&ok, 16);
        else
            value = s.toLongLong(&ok, 10);
        if (ok)
            return value;
    }
    fail(tr("%1 must be an integer or a \"0x...\" string").arg(where));
    return std::nullopt;
}

std::optional<qint64> JsonReader::integer(const QJsonObject& o, const QString& key, bool required)
{
    const QJsonValue v = o.value(key);
    if (v.isUndefined() || v.isNull()) {
        if (required)
            fail(tr("\"%1\" is missing").arg(key));
        return std::nullopt;
    }
    return integerValue(v, QLatin1Char('"') + key + QLatin1Char('"'));
}

std::optional<QJsonArray> JsonReader::array(const QJsonObject& o, const QString& key, bool required)
{
    const QJsonValue v = o.value(key);
    if (v.isUndefined() || v.isNull()) {
        if (required)
            fail(tr("\"%1\" is missing").arg(key));
        return std::nullopt;
    }
    if (!v.isArray()) {
        fail(tr("\"%1\" must be an array").arg(key));
        return std::nullopt;
    }
    return v.toArray();
}

std::optional<QJsonObject> JsonReader::object(const QJsonObject& o, const QString& key,
                                              bool required)
{
    const QJsonValue v = o.value(key);
    if (v.isUndefined() || v.isNull()) {
        if (required)
            fail(tr("\"%1\" is missing").arg(key));
        return std::nullopt;
    }
    if (!v.isObject()) {
        fail(tr("\"%1\" must be an object").arg(key));
        return std::nullopt;
    }
    return v.toObject();
}

bool JsonReader::onlyKeys(const QJsonObject& o, const QStringList& known, const QString& where)
{
    for (auto it = o.begin(); it != o.end(); ++it) {
        if (!known.contains(it.key()))
            return fail(tr("%1: unknown key \"%2\"").arg(where, it.key()));
    }
    return true;
}

} // namespace opentop
