#include "ui/run/CommandReadBack.h"

#include <QLocale>
#include <QPointer>
#include <QTime>

namespace opentop {

CommandReadBack::CommandReadBack(QWidget* parent)
    : QLabel(parent)
{
    setTextInteractionFlags(Qt::TextSelectableByMouse);
    setWordWrap(true);
    setTextFormat(Qt::PlainText); // the group's drives by their names
}

void CommandReadBack::readAfter(RunControl* control, DeviceSession* session,
                                const QVector<DeviceSession*>& group, int settleMs,
                                std::function<void(bool allRun)> done)
{
    QPointer<CommandReadBack> self(this);
    control->readState(
        session,
        [self, group, done](const RunControl::State& state) {
            if (!self)
                return;
            self->showState(state);
            if (group.isEmpty()) {
                done(true);
                return;
            }
            GroupFollowers::readAfter(group, [self, done](const QVector<GroupFollowers::Drive>& d) {
                if (self)
                    done(self->showGroup(d));
            });
        },
        settleMs);
}

void CommandReadBack::showState(const RunControl::State& state)
{
    QStringList lines{
        tr("Read back after the command at %1:")
            .arg(QLocale().toString(QTime::currentTime(), QStringLiteral("HH:mm:ss")))};
    if (state.running)
        lines << (*state.running ? tr("The motor is running.") : tr("The motor is stopped."));
    for (const auto& item : state.items)
        lines << tr("%1: %2").arg(item.first, item.second);
    if (!state.error.isEmpty())
        lines << tr("(not read: %1)").arg(state.error);
    setText(lines.join(QLatin1Char('\n')));
}

bool CommandReadBack::showGroup(const QVector<GroupFollowers::Drive>& drives)
{
    QStringList lines{text(), QString(),
                      tr("The drives of its communication group, read after the command:")};
    lines += GroupFollowers::afterLines(drives);
    setText(lines.join(QLatin1Char('\n')));
    bool allRun = true;
    for (const GroupFollowers::Drive& d : drives)
        allRun = allRun && d.running.value_or(false);
    return allRun;
}

} // namespace opentop
