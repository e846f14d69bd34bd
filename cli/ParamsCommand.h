#pragma once

#include "cli/CliCommand.h"

#include <QJsonObject>

namespace opentop {

struct ParameterMeta;
class Profile;

// `params [--family F]`: every parameter of the built-in profiles. The --json form is a stable
// interface (schema 1) other tools rely on: fields are only ever added.
class ParamsCommand : public CliCommand
{
public:
    QString name() const override { return QStringLiteral("params"); }
    QString synopsis() const override { return QStringLiteral("params [--family F]"); }
    QString summary() const override;
    int run(CliContext& context, const QStringList& args) override;

    static QJsonObject toJson(const Profile& profile);
    static QJsonObject toJson(const ParameterMeta& meta);
};

} // namespace opentop
