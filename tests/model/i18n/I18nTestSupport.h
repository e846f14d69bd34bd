#pragma once

#include "model/profile/ProfileRegistry.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>
#include <gtest/gtest.h>

// What the profile-translation tests share: the languages and the registries they compare.
inline QStringList profileLanguages()
{
    return {QStringLiteral("zh_TW"), QStringLiteral("zh_CN"), QStringLiteral("ko"),
            QStringLiteral("ja")};
}

inline QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

inline QString builtInTranslationPath(const QString& family, const QString& language)
{
    return QStringLiteral(":/profiles/i18n/%1.%2.json").arg(family, language);
}

inline QJsonObject builtInTranslationJson(const QString& family, const QString& language)
{
    return QJsonDocument::fromJson(readAll(builtInTranslationPath(family, language))).object();
}

// A registry in `language`, failing the test (not aborting) when it cannot load.
inline opentop::ProfileRegistry registryIn(const QString& language)
{
    QString error;
    std::optional<opentop::ProfileRegistry> r = opentop::ProfileRegistry::load(language, &error);
    EXPECT_TRUE(r.has_value()) << qPrintable(error);
    return r ? *r : opentop::ProfileRegistry({});
}
