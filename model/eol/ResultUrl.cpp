#include "model/eol/ResultUrl.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QStringList>
#include <QUrl>
#include <algorithm>

namespace opentop {

namespace {

QString decoded(const QString& part)
{
    return QUrl::fromPercentEncoding(part.toUtf8());
}

// libpq's connection keywords a URL may add (docs/eol-results.md); others are refused rather
// than silently dropped.
const QStringList& passedKeywords()
{
    static const QStringList keywords{QStringLiteral("sslmode"),
                                      QStringLiteral("connect_timeout"),
                                      QStringLiteral("application_name"),
                                      QStringLiteral("sslrootcert"),
                                      QStringLiteral("sslcert"),
                                      QStringLiteral("sslkey"),
                                      QStringLiteral("target_session_attrs")};
    return keywords;
}

} // namespace

std::optional<ResultUrl> ResultUrl::parse(const QString& text, QString* error,
                                          const QProcessEnvironment& environment)
{
    auto fail = [&](const QString& why) -> std::optional<ResultUrl> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    ResultUrl url;
    if (text.trimmed().isEmpty())
        return fail(tr("no database given: name a file or a postgresql:// URL"));
    const bool postgres = text.startsWith(QLatin1String("postgresql://")) ||
                          text.startsWith(QLatin1String("postgres://"));
    if (!postgres) {
        QString path = text;
        if (path.startsWith(QLatin1String("sqlite:")))
            path = path.mid(7);
        else if (path.contains(QLatin1String("://")))
            return fail(tr("unknown database URL \"%1\": use a file path, sqlite:PATH or "
                           "postgresql://user@host/database")
                            .arg(text));
        if (path.isEmpty())
            return fail(tr("sqlite: needs a file path"));
        url.engine = Engine::Sqlite;
        url.path = QDir::cleanPath(path);
        return url;
    }
    url.engine = Engine::Postgres;
    QString rest = text.mid(text.indexOf(QLatin1String("://")) + 3);
    QString query;
    if (const int q = rest.indexOf(QLatin1Char('?')); q >= 0) {
        query = rest.mid(q + 1);
        rest.truncate(q);
    }
    QString authority = rest;
    if (const int slash = rest.indexOf(QLatin1Char('/')); slash >= 0) {
        authority = rest.left(slash);
        url.database = decoded(rest.mid(slash + 1));
    }
    if (const int at = authority.lastIndexOf(QLatin1Char('@')); at >= 0) {
        const QString userInfo = authority.left(at);
        authority = authority.mid(at + 1);
        const int colon = userInfo.indexOf(QLatin1Char(':'));
        url.user = decoded(colon >= 0 ? userInfo.left(colon) : userInfo);
        if (colon >= 0)
            url.password = decoded(userInfo.mid(colon + 1));
    }
    QString portText;
    if (authority.startsWith(QLatin1Char('['))) { // [IPv6]:port
        const int close = authority.indexOf(QLatin1Char(']'));
        if (close < 0)
            return fail(tr("the host in \"%1\" has no closing ]").arg(text));
        url.host = authority.mid(1, close - 1);
        if (authority.mid(close + 1).startsWith(QLatin1Char(':')))
            portText = authority.mid(close + 2);
    } else {
        const int colon = authority.lastIndexOf(QLatin1Char(':'));
        url.host = decoded(colon >= 0 ? authority.left(colon) : authority);
        if (colon >= 0)
            portText = authority.mid(colon + 1);
    }
    QStringList options;
    for (const QString& pair : query.split(QLatin1Char('&'), Qt::SkipEmptyParts)) {
        const int eq = pair.indexOf(QLatin1Char('='));
        const QString key = decoded(pair.left(eq));
        const QString value = eq >= 0 ? decoded(pair.mid(eq + 1)) : QString();
        if (key == QLatin1String("host"))
            url.host = value;
        else if (key == QLatin1String("port"))
            portText = value;
        else if (key == QLatin1String("user"))
            url.user = value;
        else if (key == QLatin1String("password"))
            url.password = value;
        else if (key == QLatin1String("dbname"))
            url.database = value;
        else if (passedKeywords().contains(key))
            options.append(key + QLatin1Char('=') + value);
        else
            return fail(tr("unknown connection option \"%1\" in the database URL; known: %2")
                            .arg(key, passedKeywords().join(QLatin1String(", "))));
    }
    // A server out of reach (a cable, a switched-off host) must not hold a station for TCP's
    // two minutes: its results go to the spool after this.
    if (!std::any_of(options.cbegin(), options.cend(), [](const QString& o) {
            return o.startsWith(QLatin1String("connect_timeout="));
        }))
        options.append(QStringLiteral("connect_timeout=5"));
    url.options = options.join(QLatin1Char(';'));
    auto fromEnvironment = [&](QString& part, const char* name) {
        if (part.isEmpty())
            part = environment.value(QLatin1String(name));
    };
    fromEnvironment(url.host, "PGHOST");
    fromEnvironment(portText, "PGPORT");
    fromEnvironment(url.user, "PGUSER");
    fromEnvironment(url.password, "PGPASSWORD");
    fromEnvironment(url.database, "PGDATABASE");
    if (!portText.isEmpty()) {
        bool ok = false;
        url.port = portText.toInt(&ok);
        if (!ok || url.port <= 0 || url.port > 65535)
            return fail(tr("the port \"%1\" in the database URL is not a number from 1 to 65535")
                            .arg(portText));
    }
    return url;
}

QString ResultUrl::displayText() const
{
    if (engine == Engine::Sqlite)
        return QStringLiteral("sqlite:") + path;
    QString text = QStringLiteral("postgresql://");
    if (!user.isEmpty())
        text += user + QLatin1Char('@');
    const bool socket = host.startsWith(QLatin1Char('/'));
    if (!socket)
        text += host;
    if (port > 0)
        text += QLatin1Char(':') + QString::number(port);
    text += QLatin1Char('/') + database;
    if (socket)
        text += QStringLiteral("?host=") + host;
    return text;
}

QString ResultUrl::driverName() const
{
    return engine == Engine::Sqlite ? QStringLiteral("QSQLITE") : QStringLiteral("QPSQL");
}

QString ResultUrl::defaultLocation()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation))
        .filePath(QStringLiteral("opentop/results.db"));
}

QString ResultUrl::stationLocation(const QString& url)
{
    QString where = url;
    if (where.isEmpty())
        where = qEnvironmentVariable("OPENTOP_EOL_DB");
    if (where.isEmpty()) {
        where = defaultLocation();
        QDir().mkpath(QFileInfo(where).absolutePath());
    }
    return where;
}

} // namespace opentop
