#include "ui/tuning/AutotunePanel.h"

#include "ui/tuning/NumberField.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

AutotunePanel::AutotunePanel(const TuningSpec& spec, QWidget* parent)
    : QWidget(parent)
    , m_spec(spec)
    , m_speed(NumberField::make(QStringLiteral("autotuneSpeed"), QStringLiteral("300"), this))
    , m_amplitude(NumberField::make(QStringLiteral("relayAmplitude"), QStringLiteral("10"), this))
    , m_rule(new QComboBox(this))
    , m_speedUnit(new QLabel(this))
    , m_autotune(new QPushButton(tr("Autotune…"), this))
    , m_result(new QLabel(this))
    , m_verdict(new QLabel(this))
    , m_gains(new QGridLayout)
    , m_accept(new QPushButton(tr("Accept"), this))
    , m_reject(new QPushButton(tr("Reject"), this))
    , m_store(new QPushButton(tr("Store in the drive"), this))
{
    m_rule->setObjectName(QStringLiteral("rule"));
    for (const QString& id : TuningRules::ids())
        m_rule->addItem(TuningRules::title(*TuningRules::fromId(id)), id);
    m_rule->setCurrentIndex(
        std::max(0, m_rule->findData(TuningRules::id(TuningRules::Rule::Medium))));
    m_autotune->setObjectName(QStringLiteral("autotune"));
    m_accept->setObjectName(QStringLiteral("accept"));
    m_reject->setObjectName(QStringLiteral("reject"));
    m_store->setObjectName(QStringLiteral("store"));
    m_result->setObjectName(QStringLiteral("autotuneResult"));
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_verdict->setObjectName(QStringLiteral("acceptCheck"));
    m_verdict->setWordWrap(true);
    m_verdict->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_verdict->hide();
    m_accept->setToolTip(tr("Writes the proposed gains to the drive (temporary until stored) "
                            "and offers a step test to compare with the prediction"));
    m_reject->setToolTip(tr("Writes back the gains the drive had before"));
    m_store->setToolTip(tr("Stores the gains in the drive so that they survive a power cycle; "
                           "asks first unless the step after Accept passed the check"));

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* form = new QFormLayout;
    form->addRow(tr("Operating speed:"), NumberField::withUnit(m_speed, m_speedUnit, this));
    form->addRow(tr("Relay amplitude:"),
                 NumberField::withUnit(m_amplitude, new QLabel(tr("%"), this), this));
    form->addRow(tr("Rule:"), m_rule);
    layout->addLayout(form);
    layout->addWidget(m_autotune);
    layout->addWidget(m_result);
    m_gains->addWidget(new QLabel(tr("Present"), this), 0, 1);
    m_gains->addWidget(new QLabel(tr("Proposed"), this), 0, 2);
    const QStringList rows = {tr("P"), tr("I"), tr("D"), tr("D period")};
    for (int r = 0; r < rows.size(); ++r) {
        m_gains->addWidget(new QLabel(rows[r], this), r + 1, 0);
        for (int c = 1; c <= 2; ++c) {
            auto* value = new QLabel(QStringLiteral("–"), this);
            value->setObjectName(c == 1 ? QStringLiteral("present%1").arg(r)
                                        : QStringLiteral("proposed%1").arg(r));
            value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_gains->addWidget(value, r + 1, c);
        }
    }
    m_gains->setColumnStretch(3, 1);
    layout->addLayout(m_gains);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_accept);
    buttons->addWidget(m_reject);
    layout->addLayout(buttons);
    layout->addWidget(m_verdict);
    layout->addWidget(m_store);
    layout->addStretch();
    connect(m_autotune, &QPushButton::clicked, this, &AutotunePanel::autotuneClicked);
    connect(m_accept, &QPushButton::clicked, this, &AutotunePanel::acceptClicked);
    connect(m_reject, &QPushButton::clicked, this, &AutotunePanel::rejectClicked);
    connect(m_store, &QPushButton::clicked, this, &AutotunePanel::storeClicked);
    clearResult();
    setState(false, false, false);
}

void AutotunePanel::setSpeedUnit(const QString& unit, double feedbackScale)
{
    m_unit = unit;
    m_scale = feedbackScale > 0 ? feedbackScale : 1;
    m_speedUnit->setText(unit);
}

double AutotunePanel::speed() const
{
    return QLocale::c().toDouble(m_speed->text());
}

std::optional<TuningRunner::RelayPlan> AutotunePanel::plan(QString* error) const
{
    bool speedOk = false, amplitudeOk = false;
    TuningRunner::RelayPlan plan;
    plan.speed = QLocale::c().toDouble(m_speed->text(), &speedOk);
    plan.amplitude = QLocale::c().toDouble(m_amplitude->text(), &amplitudeOk);
    if (!speedOk || plan.speed <= 0) {
        *error = tr("Enter an operating speed above 0 %1.").arg(m_unit);
        return std::nullopt;
    }
    if (!amplitudeOk || plan.amplitude <= 0 || plan.amplitude > 50) {
        *error = tr("Enter a relay amplitude of 1–50 %.");
        return std::nullopt;
    }
    plan.rule =
        TuningRules::fromId(m_rule->currentData().toString()).value_or(TuningRules::Rule::Medium);
    return plan;
}

void AutotunePanel::showGains(int column, const std::optional<PidGains>& gains)
{
    const QLocale locale;
    const QStringList values =
        gains ? QStringList{locale.toString(gains->p, 'f', 4), locale.toString(gains->i, 'f', 4),
                            locale.toString(gains->d, 'f', 4), tr("%1 ms").arg(gains->dPeriodMs)}
              : QStringList{QStringLiteral("–"), QStringLiteral("–"), QStringLiteral("–"),
                            QStringLiteral("–")};
    for (int r = 0; r < values.size(); ++r)
        static_cast<QLabel*>(m_gains->itemAtPosition(r + 1, column)->widget())->setText(values[r]);
}

void AutotunePanel::setPresentGains(const std::optional<PidGains>& gains)
{
    showGains(1, gains);
}

void AutotunePanel::clearResult()
{
    m_proposal.reset();
    m_result->setText(tr("No autotune result yet."));
    showGains(2, std::nullopt);
}

void AutotunePanel::showResult(const TuningRunner::Result& r)
{
    if (!r.ok) {
        clearResult();
        QString text = tr("Autotune failed: %1").arg(r.error);
        if (!r.advice.isEmpty())
            text += QLatin1Char('\n') + tr("What to change: %1").arg(r.advice);
        m_result->setText(text);
        return;
    }
    const QLocale locale;
    // Register units to engineering: output counts to % duty, feedback counts to the unit.
    const double percentPerCount = 100.0 / m_spec.outputFullScale;
    const auto perUnit = [&](double ku) { return ku * percentPerCount / m_scale; };
    const double k = r.plant.gain * m_scale / percentPerCount;
    // What the relay measured through the bus, then what the model makes of the drive's loop.
    QString text = tr("Relay: Ku %1 %/%2, Tu %3 ms measured, %4 readings per period (one every "
                      "%5 ms)")
                       .arg(locale.toString(r.relay.ultimateGain * percentPerCount, 'g', 3), m_unit,
                            locale.toString(r.relay.periodMs, 'f', 1),
                            locale.toString(r.relay.readingsPerPeriod, 'f', 1),
                            locale.toString(r.relay.readingMs, 'f', 1));
    text += QLatin1Char('\n') + tr("Model: K %1 %2/%, τ %3 ms, dead time %4 ms")
                                    .arg(locale.toString(k, 'g', 3), m_unit,
                                         locale.toString(r.plant.tauMs, 'f', 1),
                                         locale.toString(r.plant.deadMs, 'f', 1));
    text += QLatin1Char('\n') + tr("The drive's own loop (model): Ku %1 %/%2, Tu %3 ms")
                                    .arg(locale.toString(perUnit(r.ultimateGain), 'g', 3), m_unit,
                                         locale.toString(r.ultimatePeriodMs, 'f', 1));
    const StepMetrics& m = r.predictedMetrics;
    text += QLatin1Char('\n') +
            tr("Proposal: the rule's P × %1, Ti × %2; predicted overshoot %3 %, settling %4")
                .arg(locale.toString(r.kpScale, 'g', 3), locale.toString(r.tiScale, 'g', 3),
                     locale.toString(m.overshootPercent, 'f', 1),
                     m.settlingMs ? tr("%1 ms").arg(locale.toString(*m.settlingMs, 'f', 0))
                                  : tr("not within the record"));
    m_result->setText(text);
    m_proposal = r.proposal;
    showGains(2, r.proposal);
}

void AutotunePanel::setState(bool busy, bool proposal, bool accepted)
{
    m_autotune->setEnabled(!busy);
    m_speed->setEnabled(!busy);
    m_amplitude->setEnabled(!busy);
    m_rule->setEnabled(!busy);
    m_accept->setEnabled(!busy && proposal && !accepted);
    m_reject->setEnabled(!busy && (proposal || accepted));
    m_store->setEnabled(!busy && accepted);
}

void AutotunePanel::setVerdict(const std::optional<TuningVerdict>& verdict)
{
    m_verdict->setVisible(verdict.has_value());
    if (!verdict) {
        m_verdict->clear();
        return;
    }
    m_verdict->setText((verdict->passed ? tr("Check after Accept: passed.")
                                        : tr("Check after Accept: FAILED. Reject writes back "
                                             "the gains the drive had.")) +
                       QLatin1Char('\n') + verdict->text());
    m_verdict->setStyleSheet(verdict->passed
                                 ? QStringLiteral("color: #1e7e34;")
                                 : QStringLiteral("color: #c0392b; font-weight: bold;"));
}

QString AutotunePanel::verdictText() const
{
    return m_verdict->text();
}

QString AutotunePanel::resultText() const
{
    return m_result->text();
}

QString AutotunePanel::proposalText() const
{
    return m_proposal ? m_proposal->toString() : QString();
}

} // namespace opentop
