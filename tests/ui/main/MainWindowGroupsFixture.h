// The real window with drives 2 and 150 to be made children of drive 1's communication group,
// and what the group tests do as the user: answer a question, read the groups, find a field.
#pragma once
#include "model/bus/BusGroupTracker.h"
#include "tests/ui/main/MainWindowFixture.h"
#include "ui/groups/GroupsView.h"

#include <memory>

namespace opentop::test {

class MainWindowGroupsFixture : public MainWindowFixture
{
protected:
    // Answers the next message box named `name` with the button named `button` (Cancel when
    // empty), after running `whileAsked`; returns the box's text.
    std::shared_ptr<QString> answer(const QString& name, const QString& button,
                                    std::function<void()> whileAsked = {})
    {
        auto text = std::make_shared<QString>();
        auto* timer = new QTimer(window.get());
        timer->setInterval(10);
        QObject::connect(timer, &QTimer::timeout, window.get(), [=] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box || box->objectName() != name)
                return;
            timer->stop();
            timer->deleteLater();
            *text = box->text() + QLatin1Char('\n') + box->informativeText();
            if (whileAsked)
                whileAsked();
            QAbstractButton* b = button.isEmpty() ? box->button(QMessageBox::Cancel)
                                                  : box->findChild<QPushButton*>(button);
            ASSERT_NE(b, nullptr);
            b->click();
        });
        timer->start();
        return text;
    }

    void setGroupInSimulator(int slave, int group)
    {
        ASSERT_TRUE(bus->control(slave, {QStringLiteral("set"), QStringLiteral("0x00F5"),
                                         QString::number(group)})
                        .ok);
    }

    // The group view's "Read groups again", and the window knowing the result.
    void readGroups()
    {
        GroupsView* view = window->groupsView();
        ASSERT_NE(view, nullptr);
        view->readAgain();
        ASSERT_TRUE(waitFor([&] { return !view->busy(); }));
    }

    // Drives 2 and 150 follow drive 1.
    void makeGroupOfOne()
    {
        setGroupInSimulator(2, 1);
        setGroupInSimulator(150, 1);
        readGroups();
        ASSERT_EQ(window->groups()->groups().childrenOf(1), (QVector<int>{2, 150}));
    }

    // The field on the shown drive's Running data page (pages of a drive shown before may
    // still wait for their deletion).
    ParameterField* field(const QString& name)
    {
        ParameterPage* page = window->workspace()->page(QStringLiteral("Running data"));
        if (!page)
            return nullptr;
        for (ParameterField* f : page->findChildren<ParameterField*>())
            if (f->parameterName() == name)
                return f;
        return nullptr;
    }

    double deviceNumber(int slave, const QString& name)
    {
        const DeviceParameters::Entry* e = window->drives()->parameters(slave)->entry(name);
        return e && e->device.valid ? e->device.number : -1;
    }
};

} // namespace opentop::test
