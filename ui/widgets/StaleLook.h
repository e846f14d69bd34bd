#pragma once

#include "model/session/Freshness.h"

#include <QColor>
#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <QVector>
#include <functional>

class QWidget;

namespace opentop {

// The one look of a live value that is no longer live (monitor/Freshness), for every view:
// greyed text and the time of the last answer. A widget's "stale" property tells which look it
// has (for style sheets, accessibility checks and tests). A StaleLook owned by a view follows
// one source (a drive's latest sample, a status), re-evaluates it a few times a second, greys
// the widgets it was given while the source is not live and tells the age ("updated 0.4 s
// ago", "last answer 10:31:05 (12 s old)") for the view to show.
class StaleLook : public QObject
{
    Q_OBJECT
public:
    // The name of the bool property set on every widget this look applies to.
    static constexpr const char* kProperty = "stale";
    // The grey of stale values and lamps (also for item models' foreground).
    static QColor grey();
    // Greys `widget`'s text (and its children's, through the palette) or gives it back its own.
    static void apply(QWidget* widget, bool stale);
    static bool isStale(const QWidget* widget);
    // "updated 0.4 s ago" for a live value, "last answer 10:31:05 (12 s old)" for a stale one,
    // "not read yet" for none.
    static QString ageText(Freshness::State state, const QDateTime& lastAnswer,
                           const QDateTime& now);

    using StateSource = std::function<Freshness::State(const QDateTime& now)>;
    using TimeSource = std::function<QDateTime()>;

    StaleLook(StateSource state, TimeSource lastAnswer, QObject* parent);

    // Widgets greyed while the source is not live.
    void addWidget(QWidget* widget);
    Freshness::State state() const { return m_state; }
    QString ageText() const;
    // Evaluates the source now (also done on every tick).
    void update();

signals:
    // The source turned live, stale or unread.
    void stateChanged(opentop::Freshness::State state);
    // Every evaluation (for views that show more than the age label).
    void evaluated();

private:
    StateSource m_source;
    TimeSource m_lastAnswer;
    QVector<QPointer<QWidget>> m_widgets;
    Freshness::State m_state = Freshness::State::None;
    QTimer m_tick;
};

} // namespace opentop
