#include "ui/tuning/TuningStatusRow.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

TuningStatusRow::TuningStatusRow(QWidget* parent)
    : QWidget(parent)
    , m_stop(new QPushButton(tr("STOP"), this))
    , m_phase(new QLabel(this))
    , m_stopReport(new QLabel(this))
{
    m_stop->setObjectName(QStringLiteral("tuningStop"));
    m_stop->setToolTip(tr("Cancels the running test: the motor is stopped and the stop confirmed"));
    m_stop->setStyleSheet(QStringLiteral("QPushButton { background: #c0392b; color: white; "
                                         "font-weight: bold; padding: 6px 18px; }"));
    m_phase->setObjectName(QStringLiteral("tuningPhase"));
    m_stopReport->setObjectName(QStringLiteral("stopReport"));
    m_phase->setWordWrap(true);
    m_stopReport->setWordWrap(true);

    // No margins of its own: the row sits in the page's layout as its layout did.
    auto* top = new QHBoxLayout(this);
    top->setContentsMargins(0, 0, 0, 0);
    top->addWidget(m_stop);
    auto* status = new QVBoxLayout;
    status->addWidget(m_phase);
    status->addWidget(m_stopReport);
    top->addLayout(status, 1);

    connect(m_stop, &QPushButton::clicked, this, &TuningStatusRow::stopClicked);
}

void TuningStatusRow::setPhase(const QString& text, bool bad)
{
    m_phase->setText(text);
    m_phase->setStyleSheet(bad ? QStringLiteral("color: #c0392b;") : QString());
}

void TuningStatusRow::showStopReport(const TuningRunner::Result& result)
{
    m_stopReport->setText(result.stopDetail);
    m_stopReport->setStyleSheet(
        result.stopConfirmed ? QString() : QStringLiteral("color: #c0392b; font-weight: bold;"));
}

void TuningStatusRow::clearStopReport()
{
    m_stopReport->clear();
}

QString TuningStatusRow::phaseText() const
{
    return m_phase->text();
}

QString TuningStatusRow::stopReport() const
{
    return m_stopReport->text();
}

} // namespace opentop
