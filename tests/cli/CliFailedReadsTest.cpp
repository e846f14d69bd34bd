// A backup or restore whose reads fail must say so, never report them as done: no "69 settings
// read in 13 requests" for a drive that did not answer, no "0 of 69 settings differ" when
// nothing could be compared (issue 11, item 6).
#include "cli/ExitCode.h"
#include "sim/SimBus.h"
#include "sim/TcpSimServer.h"
#include "tests/cli/CliTestSupport.h"

#include <QFile>
#include <QRegularExpression>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

// Between opentop-cli and the simulated drive: passes the identification (function 04 at
// 0x0007 and 03 at 0x0000) and, once `failReads` is set, drops every other request unanswered,
// so the drive is found but its settings cannot be read.
class ReadDropper : public QObject
{
public:
    ReadDropper(quint16 target)
        : m_target(target)
    {
        m_server.listen(QHostAddress::LocalHost, 0);
        QObject::connect(&m_server, &QTcpServer::newConnection, this, [this] {
            QTcpSocket* client = m_server.nextPendingConnection();
            auto* drive = new QTcpSocket(client);
            drive->connectToHost(QHostAddress::LocalHost, m_target);
            drive->waitForConnected(2000);
            QObject::connect(drive, &QTcpSocket::readyRead, client,
                             [client, drive] { client->write(drive->readAll()); });
            QObject::connect(client, &QTcpSocket::readyRead, drive, [this, client, drive] {
                m_pending += client->readAll();
                while (m_pending.size() >= 7) { // MBAP: length at bytes 4-5
                    const int length = 6 + (quint8(m_pending[4]) << 8 | quint8(m_pending[5]));
                    if (length < 10 || m_pending.size() < length)
                        break;
                    const QByteArray adu = m_pending.left(length);
                    m_pending.remove(0, length);
                    const int function = quint8(adu.at(7));
                    const int address = quint8(adu.at(8)) << 8 | quint8(adu.at(9));
                    const bool identification = (function == 4 && address == 0x0007) ||
                                                (function == 3 && address == 0x0000);
                    if (failReads && !identification)
                        ++dropped;
                    else
                        drive->write(adu);
                }
            });
        });
    }
    quint16 port() const { return m_server.serverPort(); }

    bool failReads = false;
    int dropped = 0;

private:
    quint16 m_target;
    QTcpServer m_server;
    QByteArray m_pending;
};

class CliFailedReads : public ::testing::Test
{
protected:
    void SetUp() override
    {
        QString error;
        bus = SimBus::fromSpec(QStringLiteral("dbu200@1"), &error);
        ASSERT_TRUE(bus) << qPrintable(error);
        server = std::make_unique<TcpSimServer>(bus, WireTiming(), false);
        ASSERT_TRUE(server->listen(QHostAddress::LocalHost, 0, &error)) << qPrintable(error);
        proxy = std::make_unique<ReadDropper>(server->port());
        ASSERT_TRUE(dir.isValid());
    }

    CliRun cli(QStringList args)
    {
        return runCli(QStringList{QStringLiteral("--tcp"),
                                  QStringLiteral("127.0.0.1:%1").arg(proxy->port()),
                                  QStringLiteral("--variant"), QStringLiteral("1=dbu200"),
                                  QStringLiteral("--bus-drives"), QStringLiteral("1"),
                                  QStringLiteral("--timeout"), QStringLiteral("50"),
                                  QStringLiteral("--retries"), QStringLiteral("0")} +
                      args);
    }

    int held(const char* address)
    {
        const QStringList words =
            bus->control(1, {QStringLiteral("get"), QString::fromLatin1(address)})
                .text.split(QLatin1Char(' '));
        return words.value(int(words.indexOf(QStringLiteral("="))) + 1).toInt();
    }

    std::shared_ptr<SimBus> bus;
    std::unique_ptr<TcpSimServer> server;
    std::unique_ptr<ReadDropper> proxy;
    QTemporaryDir dir;
};

} // namespace

TEST_F(CliFailedReads, BackupOfADriveWhoseReadsFailDoesNotClaimTheSettingsRead)
{
    proxy->failReads = true;
    const QString file = dir.filePath(QStringLiteral("drive.json"));
    const CliRun r =
        cli({QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("-o"), file});
    EXPECT_GT(proxy->dropped, 0);
    EXPECT_EQ(r.code, ExitCommunication) << qPrintable(r.out + r.err);
    EXPECT_FALSE(r.out.contains(QStringLiteral("settings read in"))) << qPrintable(r.out);
    static const QRegularExpression failed(
        QStringLiteral("drive 1 \\(DBU200-D\\): reading failed, \\d+ of 69 settings read"));
    EXPECT_TRUE(r.out.contains(failed)) << qPrintable(r.out);
    EXPECT_FALSE(QFile::exists(file)) << "no backup file for a drive that was not read";
}

TEST_F(CliFailedReads, RestoreWhoseReadFailsComparesNothingAndWritesNothing)
{
    const QString file = dir.filePath(QStringLiteral("drive.json"));
    CliRun r = cli({QStringLiteral("backup"), QStringLiteral("1"), QStringLiteral("-o"), file});
    ASSERT_EQ(r.code, ExitOk) << qPrintable(r.out + r.err);
    ASSERT_TRUE(
        bus->control(1, {QStringLiteral("set"), QStringLiteral("0xCA03"), QStringLiteral("1500")})
            .ok); // spno2.speed differs from the file now
    proxy->failReads = true;
    for (const bool yes : {false, true}) {
        SCOPED_TRACE(yes ? "restore --yes" : "restore (plan)");
        QStringList args{QStringLiteral("restore"), file};
        if (yes)
            args << QStringLiteral("--yes");
        r = cli(args);
        EXPECT_EQ(r.code, ExitCommunication) << qPrintable(r.out + r.err);
        EXPECT_FALSE(r.out.contains(QStringLiteral("settings differ"))) << qPrintable(r.out);
        EXPECT_TRUE(r.out.contains(QStringLiteral("drive 1 (DBU200-D): the drive's settings "
                                                  "were not read; nothing compared, nothing "
                                                  "written")))
            << qPrintable(r.out);
        EXPECT_EQ(held("0xCA03"), 1500) << "nothing may be written";
    }
}
