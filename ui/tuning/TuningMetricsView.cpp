#include "ui/tuning/TuningMetricsView.h"

#include "ui/tuning/TuningRun.h"

#include <QFormLayout>
#include <QLabel>
#include <QLocale>

namespace opentop {

TuningMetricsView::TuningMetricsView(QWidget* parent)
    : QWidget(parent)
    , m_title(new QLabel(this))
    , m_rise(new QLabel(this))
    , m_overshoot(new QLabel(this))
    , m_settling(new QLabel(this))
    , m_error(new QLabel(this))
    , m_peak(new QLabel(this))
{
    setObjectName(QStringLiteral("tuningMetrics"));
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    m_title->setWordWrap(true);
    form->addRow(m_title);
    form->addRow(tr("Rise time (10–90 %):"), m_rise);
    form->addRow(tr("Overshoot:"), m_overshoot);
    form->addRow(tr("Settling time (2 %):"), m_settling);
    form->addRow(tr("Steady-state error:"), m_error);
    form->addRow(tr("Peak current:"), m_peak);
    for (QLabel* l : {m_rise, m_overshoot, m_settling, m_error, m_peak})
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    showRun(nullptr);
}

void TuningMetricsView::showRun(const TuningRun* run)
{
    const QString none = QStringLiteral("–");
    const QLocale locale;
    if (!run || run->live || !run->result.metrics.valid) {
        m_title->setText(!run        ? tr("No run yet")
                         : run->live ? tr("%1: recording").arg(run->title)
                         : run->result.error.isEmpty()
                             ? run->title
                             : tr("%1: %2").arg(run->title, run->result.error));
        for (QLabel* l : {m_rise, m_overshoot, m_settling, m_error, m_peak})
            l->setText(none);
        return;
    }
    const StepMetrics& m = run->result.metrics;
    const QString unit = run->result.speedUnit;
    m_title->setText(run->title);
    m_rise->setText(m.riseMs ? tr("%1 ms").arg(locale.toString(*m.riseMs, 'f', 0))
                             : tr("not reached"));
    m_overshoot->setText(tr("%1 %").arg(locale.toString(m.overshootPercent, 'f', 1)));
    m_settling->setText(m.settlingMs ? tr("%1 ms").arg(locale.toString(*m.settlingMs, 'f', 0))
                                     : tr("not settled"));
    m_error->setText(tr("%1 %2").arg(locale.toString(m.steadyStateError, 'f', 1), unit).trimmed());
    m_peak->setText(tr("%1 A").arg(locale.toString(m.peakCurrent, 'f', 2)));
}

QString TuningMetricsView::text() const
{
    return tr("Rise time %1; overshoot %2; settling time %3; steady-state error %4; peak "
              "current %5")
        .arg(m_rise->text(), m_overshoot->text(), m_settling->text(), m_error->text(),
             m_peak->text());
}

} // namespace opentop
