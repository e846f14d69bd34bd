#pragma once

#include "model/eol/RecipeChecker.h"

#include <QCoreApplication>

namespace opentop {

// Checks one position's test steps for RecipeChecker: each step one the family can do (by the
// profile's roles: running data selection only where there is a "select" role), its values
// allowed (through ValueCodec), its times above zero and below the sane maxima, every limit with
// lower ≤ upper and the unit of the value it measures, and the order (a hold only while the
// motor runs, a start only after taking priority where the drive needs it, a stop at the end).
class RecipeStepChecker
{
    Q_DECLARE_TR_FUNCTIONS(opentop::RecipeStepChecker)
public:
    RecipeStepChecker(const Profile& profile, const RecipePosition& position, QString path,
                      QString where);

    void check(QVector<RecipeProblem>* problems);

private:
    void checkStep(const RecipeStep& step);
    bool needsRole(const char* role);
    void checkSeconds(double seconds, double max, const QString& field, const QString& what);
    void checkSpeedUnit(const QString& unit, const QString& field);
    void checkLimit(const RecipeLimit& limit, const QString& at);
    void checkRead(const RecipeStep& step);
    void report(const QString& suffix, const QString& message);
    const ParameterMeta* roleParameter(const char* role) const;
    QString unitOf(const ParameterMeta& meta, const QString& variant) const;

    const Profile& m_profile;
    const RecipePosition& m_position;
    QString m_path;
    QString m_where;
    QStringList m_variants;
    // The step being checked: its path and its name in messages.
    QString m_stepPath;
    QString m_stepWhere;
    QVector<RecipeProblem>* m_problems = nullptr;
};

} // namespace opentop
