#include "ui/run/DbuRunCommands.h"

#include "model/profile/RoleEvaluator.h"
#include "model/session/DeviceSession.h"
#include "ui/run/SpnoSelector.h"

#include <QCoreApplication>
#include <QGridLayout>
#include <QPushButton>

namespace opentop {

namespace {

// The texts as they were before the commands moved here (their translations are in that context).
QString text(const char* source)
{
    return QCoreApplication::translate("opentop::TestRunPanel", source);
}

} // namespace

DbuRunCommands::DbuRunCommands(DeviceSession* session, QWidget* parent)
    : QWidget(parent)
{
    using A = RunControl::Action;
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    const Profile& profile = session->profile();
    const QPair<A, QString> items[] = {
        {A::Start, text(QT_TRANSLATE_NOOP("opentop::TestRunPanel", "&Start"))},
        {A::Stop, text(QT_TRANSLATE_NOOP("opentop::TestRunPanel", "S&top"))},
        {A::Cw, text(QT_TRANSLATE_NOOP("opentop::TestRunPanel", "&CW"))},
        {A::Ccw, text(QT_TRANSLATE_NOOP("opentop::TestRunPanel", "CC&W"))},
        {A::Hold, text(QT_TRANSLATE_NOOP("opentop::TestRunPanel", "&Hold"))},
        {A::Free, text(QT_TRANSLATE_NOOP("opentop::TestRunPanel", "&Free"))}};
    for (int i = 0; i < 6; ++i) {
        RunControl::Command c;
        c.action = items[i].first;
        if (!RoleEvaluator::parameter(profile, RunControl::roleOf(c.action)))
            continue;
        QPushButton* b = addButton(items[i].second, RunControl::actionName(c.action));
        connect(b, &QPushButton::clicked, this,
                [this, c] { emit commandRequested(c, c.action == A::Start); });
        if (c.action != A::Stop)
            m_whileIdle << b;
        grid->addWidget(b, i / 2, i % 2);
    }
    if (!RoleEvaluator::parameter(profile, QStringLiteral("select")))
        return;
    m_spno = new SpnoSelector(session, this);
    grid->addWidget(m_spno, 3, 0);
    QPushButton* select =
        addButton(text(QT_TRANSLATE_NOOP("opentop::TestRunPanel", "Se&lect running data")),
                  QStringLiteral("select"));
    connect(select, &QPushButton::clicked, this, [this] {
        RunControl::Command c;
        c.action = RunControl::Action::Select;
        c.select = m_spno->currentData().toInt();
        emit commandRequested(c, false);
    });
    grid->addWidget(select, 3, 1);
    m_whileIdle << m_spno << select;
    // Back to the machine's own controls, as a TOP-1 offers.
    if (const ProfileRole* io = profile.role(QStringLiteral("ioPriority")); io && io->value) {
        m_ioButton =
            addButton(text(QT_TRANSLATE_NOOP("opentop::TestRunPanel", "Return to &I/O priority")),
                      QStringLiteral("ioPriority"));
        m_ioButton->setToolTip(text(QT_TRANSLATE_NOOP(
            "opentop::TestRunPanel", "Give run, stop, direction and speed selection "
                                     "back to the drive's input terminals")));
        connect(m_ioButton, &QPushButton::clicked, this, &DbuRunCommands::ioPriorityRequested);
        grid->addWidget(m_ioButton, 4, 0, 1, 2);
        m_whileIdle << m_ioButton;
    }
}

QPushButton* DbuRunCommands::addButton(const QString& text, const QString& name)
{
    auto* button = new QPushButton(text, this);
    button->setObjectName(name);
    return button;
}

void DbuRunCommands::setBusy(bool busy)
{
    for (QWidget* w : std::as_const(m_whileIdle))
        w->setEnabled(!busy);
}

void DbuRunCommands::setIoReturnVisible(bool visible)
{
    if (m_ioButton)
        m_ioButton->setVisible(visible);
}

} // namespace opentop
