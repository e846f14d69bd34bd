#include "ui/groups/GroupWriteCheck.h"

#include "model/bus/BusGroupTracker.h"
#include "model/session/DeviceSession.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QPushButton>
#include <QStringList>

namespace opentop {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("opentop::GroupWriteCheck", text);
}

} // namespace

QString GroupWriteCheck::reachText(const BusGroupTracker* tracker, int slave)
{
    return tracker ? tracker->groups().alsoReachesText(slave) : QString();
}

QString GroupWriteCheck::reachText(const DeviceSession* session)
{
    return session ? reachText(BusGroupTracker::of(session), session->slave()) : QString();
}

bool GroupWriteCheck::confirm(QWidget* parent, const DeviceSession* session, const QString& what)
{
    if (!session)
        return true;
    return confirm(parent, BusGroupTracker::of(session), {session->slave()}, what);
}

bool GroupWriteCheck::confirm(QWidget* parent, const BusGroupTracker* tracker,
                              const QVector<int>& slaves, const QString& what)
{
    if (!tracker)
        return true;
    QStringList reached;
    QVector<int> children;
    for (int slave : slaves) {
        const QString text = reachText(tracker, slave);
        if (text.isEmpty())
            continue;
        reached << (slaves.size() > 1 ? tr("Machine number %1: %2").arg(slave).arg(text) : text);
        for (int child : tracker->groups().childrenOf(slave)) {
            if (!children.contains(child))
                children << child;
        }
    }
    if (reached.isEmpty())
        return true;
    std::sort(children.begin(), children.end());
    QMessageBox box(QMessageBox::Warning, tr("Communication group"), what + QLatin1Char('?'),
                    QMessageBox::NoButton, parent);
    box.setObjectName(QStringLiteral("groupWriteQuestion"));
    box.setTextFormat(Qt::PlainText); // `what` names the drive
    box.setInformativeText(reached.join(QLatin1Char('\n')) + QLatin1Char('\n') +
                           tr("Their values are read back afterwards."));
    QPushButton* yes = box.addButton(tr("Send, also to %1").arg(BusGroups::andListText(children)),
                                     QMessageBox::AcceptRole);
    yes->setObjectName(QStringLiteral("groupWriteYes"));
    QPushButton* cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(cancel);
    box.exec();
    return box.clickedButton() == yes;
}

} // namespace opentop
