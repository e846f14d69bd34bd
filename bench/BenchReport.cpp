#include "bench/BenchReport.h"

namespace opentop {

namespace {

QString goalText(const BenchFigure& f)
{
    if (f.goal == BenchFigure::Goal::None)
        return QString();
    const QString limit =
        QString::number(f.limit, 'f', f.decimals) +
        (f.unit.isEmpty() || f.unit == QLatin1String("x") ? f.unit : QLatin1Char(' ') + f.unit);
    return QStringLiteral("goal %1 %2: %3")
        .arg(f.goal == BenchFigure::Goal::AtMost ? QStringLiteral("<=") : QStringLiteral(">="),
             limit, f.met() ? QStringLiteral("met") : QStringLiteral("MISSED"));
}

} // namespace

BenchReport::BenchReport(QTextStream& out)
    : m_out(out)
{
}

void BenchReport::add(const BenchFigure& figure)
{
    m_figures << figure;
    QString value = QString::number(figure.value, 'f', figure.decimals);
    if (!figure.unit.isEmpty())
        value += figure.unit == QLatin1String("x") ? figure.unit : QLatin1Char(' ') + figure.unit;
    QString line = figure.name.leftJustified(34) + QLatin1Char(' ') + value.leftJustified(14);
    const QString goal = goalText(figure);
    if (!goal.isEmpty())
        line += QLatin1Char(' ') + goal.leftJustified(22);
    if (!figure.note.isEmpty())
        line += QStringLiteral("  (%1)").arg(figure.note);
    m_out << line.trimmed() << Qt::endl;
}

void BenchReport::note(const QString& text)
{
    m_out << QStringLiteral("# ") << text << Qt::endl;
}

void BenchReport::failed(const QString& benchmark, const QString& error)
{
    m_failures << QStringLiteral("%1: %2").arg(benchmark, error);
    m_out << QStringLiteral("%1: FAILED: %2").arg(benchmark, error) << Qt::endl;
}

QStringList BenchReport::missedGoals() const
{
    QStringList missed;
    for (const BenchFigure& f : m_figures) {
        if (!f.met())
            missed << f.name;
    }
    return missed;
}

void BenchReport::printSummary()
{
    int goals = 0;
    for (const BenchFigure& f : m_figures)
        goals += f.goal != BenchFigure::Goal::None;
    const QStringList missed = missedGoals();
    m_out << QStringLiteral("summary: %1 figures, %2 goals, %3 met, %4 missed%5, %6 failed")
                 .arg(m_figures.size())
                 .arg(goals)
                 .arg(goals - missed.size())
                 .arg(missed.size())
                 .arg(missed.isEmpty()
                          ? QString()
                          : QStringLiteral(" (%1)").arg(missed.join(QStringLiteral(", "))))
                 .arg(m_failures.size())
          << Qt::endl;
}

} // namespace opentop
