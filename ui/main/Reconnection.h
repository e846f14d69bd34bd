#pragma once

#include "model/run/LinkLoss.h"
#include "transport/ConnectionSettings.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QVector>
#include <functional>

class QAction;
class QMessageBox;

namespace opentop {

class LinkBar;
class MainWindow;

// Coming back from a lost link. When the link drops it keeps what was known of the drives
// (LinkLoss) and says it at once, in a message and in the link bar, with Reconnect; nothing is
// sent over the dead port, and leaving asks with the drives as last known instead of offering
// a stop. Bus ▸ Reconnect (Ctrl+R) opens the last connection again with the same drives, the
// same selected drive and the same page; once every drive has been read again, the drives that
// run or are in communication priority are named before anything else is offered.
// The main window tells it each step of its connection (adopted, opened, refused, lost).
class Reconnection : public QObject
{
    Q_OBJECT
public:
    explicit Reconnection(MainWindow* window);

    // Bus ▸ Reconnect, Ctrl+R: enabled while not connected and a connection was made before.
    QAction* action() const { return m_action; }
    LinkBar* bar() const { return m_bar; }
    // The last connection the window used (the Connect dialog starts from it).
    bool hasLast() const { return m_hasLast; }
    const ConnectionSettings& last() const { return m_last; }
    // Whether `settings` reach the place of the last connection (port, gateway, simulated bus).
    bool isLastPlace(const ConnectionSettings& settings) const;
    const LinkLoss& loss() const { return m_loss; }

    // Opens the last connection again and brings back its drives, selection and page.
    void reconnect();
    // The same with other line settings (the Connect dialog to the same port); false when
    // `settings` are another place or a connection is open or being opened.
    bool reconnectWith(const ConnectionSettings& settings);

    // The question before leaving a lost link: nothing can be stopped over it.
    void askLeaving(const QString& leaving, std::function<void()> proceed);
    bool wouldAsk() const;

    // The window's connection, step by step.
    void keepView(); // before the window lets go of its drives and pages
    void adopted(const ConnectionSettings& settings);
    void opened();
    void refused(const QString& why);
    // `explanation`: what the port's error means and what to check.
    void lost(const QString& explanation);

signals:
    // A question is on screen (tests answer it through QApplication::activeModalWidget()).
    void asking();

private:
    // What the window showed on a connection: brought back on reconnecting to it.
    struct View
    {
        QString key; // BusMemory::key
        QHash<int, QString> types;
        QVector<int> selection;
        QString page; // the tab's title
    };

    void updateAction();
    void restoreView();
    void readAgain();
    void showLoss(const QString& extra = QString());

    MainWindow* m_window;
    QAction* m_action;
    LinkBar* m_bar;
    ConnectionSettings m_last;
    bool m_hasLast = false;
    bool m_connecting = false;
    bool m_restoring = false; // the connection being made is a reconnection: view to restore
    View m_view;
    LinkLoss m_loss;
    QObject* m_watch = nullptr;      // context of the watch on the drives' identification
    QPointer<QMessageBox> m_message; // the link-lost message while it is open
};

} // namespace opentop
