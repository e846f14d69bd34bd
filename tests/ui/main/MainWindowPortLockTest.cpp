// Two programs, one port, in the window (issue 11, section 5): connecting to a serial port that
// another program holds is refused with a message naming it, the bus one works on stays, and
// nothing goes out on the port.
#include "tests/ui/main/MainWindowFixture.h"
#include "transport/PortLockFile.h"

#include <QProcess>
#include <QTemporaryDir>
#include <cerrno>
#include <fcntl.h>
#include <pty.h>
#include <unistd.h>

using MainWindowPortLockTest = opentop::test::MainWindowFixture;
using namespace opentop::test;

namespace {

struct Pty
{
    int master = -1;
    int slave = -1;
    QString path;
    Pty()
    {
        char name[256] = {};
        if (::openpty(&master, &slave, name, nullptr, nullptr) == 0)
            path = QString::fromLocal8Bit(name);
        ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
    }
    ~Pty()
    {
        ::close(master);
        ::close(slave);
    }
    // Bytes a program sent on the port.
    QByteArray sent() const
    {
        QByteArray all;
        char buffer[256];
        ssize_t n;
        while ((n = ::read(master, buffer, sizeof buffer)) > 0)
            all.append(buffer, int(n));
        return all;
    }
};

// Connects the window to `port` and returns the "Cannot connect" message's text.
QString refusal(MainWindow* window, const QString& port)
{
    QString text;
    QTimer dismiss;
    QObject::connect(&dismiss, &QTimer::timeout, [&] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            text = box->text();
            box->accept();
        }
    });
    dismiss.start(20);
    ConnectionSettings serial;
    serial.port = port;
    serial.timeoutMs = 100;
    window->connectTo(serial);
    waitFor([&] { return !text.isEmpty(); }, 5000);
    return text;
}

// Whether the menu and toolbar action with this text can be used.
bool actionEnabled(MainWindow* window, const QString& text)
{
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text() == text)
            return action->isEnabled();
    ADD_FAILURE() << "no action " << qPrintable(text);
    return false;
}

const QStringList kNeedABus = {QStringLiteral("&Scan bus"), QStringLiteral("&Write all pending"),
                               QStringLiteral("&Re-read all")};

} // namespace

TEST_F(MainWindowPortLockTest, APortAnotherProgramLocksIsRefusedNamingIt)
{
    Pty pty;
    ASSERT_FALSE(pty.path.isEmpty());
    // util-linux flock(1) holds the device lock, as another OpenTOP would.
    QProcess holder;
    holder.start(QStringLiteral("flock"), {QStringLiteral("--nonblock"), pty.path,
                                           QStringLiteral("sleep"), QStringLiteral("30")});
    ASSERT_TRUE(holder.waitForStarted(5000));
    ASSERT_TRUE(waitFor(
        [&] {
            QFile locks(QStringLiteral("/proc/locks"));
            return locks.open(QIODevice::ReadOnly) &&
                   locks.readAll().contains(" " + QByteArray::number(holder.processId()) + " ");
        },
        5000));
    const QString text = refusal(window.get(), pty.path);
    EXPECT_TRUE(text.contains(QStringLiteral("%1 is in use by flock (PID %2); close it first.")
                                  .arg(pty.path)
                                  .arg(holder.processId())))
        << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("Still connected to"))) << qPrintable(text);
    EXPECT_TRUE(window->isConnected()) << "the simulated bus stays";
    // The status bar's full text (its tooltip; the label itself is elided).
    EXPECT_TRUE(window->connectionLabel()->toolTip().contains(QStringLiteral("in use by flock")))
        << qPrintable(window->connectionLabel()->toolTip());
    EXPECT_TRUE(pty.sent().isEmpty()) << "nothing may go out on a port another program holds";
    holder.kill();
    holder.waitForFinished(2000);
}

TEST_F(MainWindowPortLockTest, APortWithALiveProgramsLockFileIsRefusedNamingIt)
{
    Pty pty;
    QTemporaryDir locks;
    qputenv("OPENTOP_LOCK_DIR", locks.path().toLocal8Bit());
    QProcess minicom; // a terminal program that wrote the conventional lock file
    minicom.start(QStringLiteral("sleep"), {QStringLiteral("30")});
    ASSERT_TRUE(minicom.waitForStarted(5000));
    QFile file(locks.path() + QLatin1Char('/') + PortLockFile::fileName(pty.path));
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(QByteArray::number(minicom.processId()).rightJustified(10, ' ') + '\n');
    file.close();
    const QString text = refusal(window.get(), pty.path);
    qunsetenv("OPENTOP_LOCK_DIR");
    EXPECT_TRUE(text.contains(QStringLiteral("%1 is in use by sleep (PID %2); close it first.")
                                  .arg(pty.path)
                                  .arg(minicom.processId())))
        << qPrintable(text);
    EXPECT_TRUE(window->isConnected());
    EXPECT_TRUE(pty.sent().isEmpty());
    EXPECT_TRUE(file.exists()) << "another program's lock file is left alone";
    minicom.kill();
    minicom.waitForFinished(2000);
}

TEST_F(MainWindowPortLockTest, ReconnectingToTheSamePortIsNotRefusedByItsOwnLock)
{
    // The window holds the port; connecting again with other line settings closes it first,
    // so its own lock never refuses it.
    Pty pty;
    QTemporaryDir locks;
    qputenv("OPENTOP_LOCK_DIR", locks.path().toLocal8Bit());
    QString box;
    QTimer dismiss;
    QObject::connect(&dismiss, &QTimer::timeout, [&] {
        if (auto* b = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            box = b->text();
            b->accept();
        }
    });
    dismiss.start(20);
    ConnectionSettings serial;
    serial.port = pty.path;
    serial.timeoutMs = 100;
    window->connectTo(serial);
    const auto connectedTo = [&](const QString& line) {
        return waitFor([&] {
            return window->isConnected() &&
                   // ... followed by what the serial driver accepted
                   window->connectionLabel()->toolTip().startsWith(
                       QStringLiteral("Connected: %1 %2 — ").arg(pty.path, line));
        });
    };
    EXPECT_TRUE(connectedTo(QStringLiteral("19200 8N1")))
        << qPrintable(window->connectionLabel()->toolTip() + box);
    EXPECT_EQ(QDir(locks.path()).entryList(QDir::Files).size(), 1);
    serial.baud = 9600;
    window->connectTo(serial);
    EXPECT_TRUE(connectedTo(QStringLiteral("9600 8N1")))
        << qPrintable(window->connectionLabel()->toolTip() + box);
    EXPECT_TRUE(box.isEmpty()) << qPrintable(box);
    qunsetenv("OPENTOP_LOCK_DIR");
}

TEST_F(MainWindowPortLockTest, ARefusedPortWithNoBusBeforeOffersNoScanAndNoDrives)
{
    // Started with --port on a port another program holds: nothing is connected, so nothing
    // may offer to scan or to restore the drives last seen on it.
    Pty pty;
    QTemporaryDir locks;
    qputenv("OPENTOP_LOCK_DIR", locks.path().toLocal8Bit());
    QProcess other;
    other.start(QStringLiteral("sleep"), {QStringLiteral("30")});
    ASSERT_TRUE(other.waitForStarted(5000));
    QFile file(locks.path() + QLatin1Char('/') + PortLockFile::fileName(pty.path));
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(QByteArray::number(other.processId()).rightJustified(10, ' ') + '\n');
    file.close();
    for (const QString& text : kNeedABus)
        EXPECT_TRUE(actionEnabled(window.get(), text)) << qPrintable(text) << " while connected";
    window->disconnectBus();
    ASSERT_TRUE(waitFor([&] { return !window->isConnected() && !window->busPanel(); }));
    const QString text = refusal(window.get(), pty.path);
    qunsetenv("OPENTOP_LOCK_DIR");
    EXPECT_TRUE(text.contains(QStringLiteral("in use by sleep"))) << qPrintable(text);
    EXPECT_TRUE(waitFor([&] { return !window->busPanel() && !window->recallBar(); }))
        << "a bus that never opened shows no Scan button and no recall bar";
    EXPECT_FALSE(window->isConnected());
    EXPECT_TRUE(window->connectionLabel()->toolTip().startsWith(QStringLiteral("Not connected")))
        << qPrintable(window->connectionLabel()->toolTip());
    EXPECT_TRUE(pty.sent().isEmpty());
    for (const QString& name : kNeedABus)
        EXPECT_FALSE(actionEnabled(window.get(), name)) << qPrintable(name) << " without a bus";
    other.kill();
    other.waitForFinished(2000);
}
