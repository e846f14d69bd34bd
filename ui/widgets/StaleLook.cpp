#include "ui/widgets/StaleLook.h"

#include <QLocale>
#include <QPalette>
#include <QVariant>
#include <QWidget>

namespace opentop {

namespace {

// Often enough for an age in tenths of a second to look alive, rarely enough to cost nothing.
constexpr int kTickMs = 250;

} // namespace

QColor StaleLook::grey()
{
    return QColor(0x8a, 0x8a, 0x8a);
}

void StaleLook::apply(QWidget* widget, bool stale)
{
    if (!widget)
        return;
    const QVariant was = widget->property(kProperty);
    if (was.isValid() && was.toBool() == stale)
        return;
    widget->setProperty(kProperty, stale);
    if (stale) {
        QPalette p = widget->palette();
        for (QPalette::ColorRole role :
             {QPalette::WindowText, QPalette::Text, QPalette::ButtonText, QPalette::BrightText})
            p.setColor(role, grey());
        widget->setPalette(p);
    } else {
        widget->setPalette(QPalette()); // the inherited one again
    }
    widget->update();
}

bool StaleLook::isStale(const QWidget* widget)
{
    return widget && widget->property(kProperty).toBool();
}

QString StaleLook::ageText(Freshness::State state, const QDateTime& lastAnswer,
                           const QDateTime& now)
{
    switch (state) {
    case Freshness::State::None:
        return tr("not read yet");
    case Freshness::State::Live: {
        const qint64 ms = std::max<qint64>(0, lastAnswer.msecsTo(now));
        return tr("updated %1 s ago").arg(QLocale().toString(ms / 1000.0, 'f', 1));
    }
    case Freshness::State::Stale:
        return Freshness::staleText(lastAnswer, now);
    }
    return QString();
}

StaleLook::StaleLook(StateSource state, TimeSource lastAnswer, QObject* parent)
    : QObject(parent)
    , m_source(std::move(state))
    , m_lastAnswer(std::move(lastAnswer))
{
    m_tick.setInterval(kTickMs);
    connect(&m_tick, &QTimer::timeout, this, &StaleLook::update);
    m_tick.start();
}

void StaleLook::addWidget(QWidget* widget)
{
    m_widgets << widget;
    apply(widget, m_state == Freshness::State::Stale);
}

QString StaleLook::ageText() const
{
    return ageText(m_state, m_lastAnswer(), QDateTime::currentDateTimeUtc());
}

void StaleLook::update()
{
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const Freshness::State state = m_source(now);
    const bool changed = state != m_state;
    m_state = state;
    for (const QPointer<QWidget>& w : std::as_const(m_widgets))
        apply(w, state == Freshness::State::Stale);
    if (changed)
        emit stateChanged(state);
    emit evaluated();
}

} // namespace opentop
