#include "MainWindow.h"
#include "BackendFactory.h"
#include "BusListModel.h"
#include "ModbusClient.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QTableView>
#include <gtest/gtest.h>

using namespace opentop;

namespace {

bool waitFor(const std::function<bool()>& condition, int ms = 5000)
{
    QDeadlineTimer deadline(ms);
    while (!condition() && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    return condition();
}

} // namespace

TEST(MainWindow, ListsTheSimulatedDrivesWithSwitchPositionsAndVariants)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Simulated;
    settings.simSpec = QStringLiteral("dbu200@1,dbu400@150,dcpid@7");
    settings.timeoutMs = 100;
    auto made = BackendFactory::makeClient(settings);
    ASSERT_TRUE(made.client) << qPrintable(made.error);
    MainWindow window(made.client.get(), {1, 7, 150, 42});
    window.setAssignedTypes({{1, QStringLiteral("dbu200")}, {150, QStringLiteral("dbu400")}});
    window.show();
    BusListModel* model = window.busModel();
    ASSERT_TRUE(waitFor([&] {
        if (model->rowCount() != 4)
            return false;
        for (int r = 0; r < 4; ++r) {
            if (model->device(r)->state == DeviceInfo::State::Unknown)
                return false;
        }
        return true;
    }));
    auto text = [&](int row, int column) { return model->index(row, column).data().toString(); };
    EXPECT_EQ(text(0, BusListModel::MachineNumber), QStringLiteral("1"));
    EXPECT_EQ(text(0, BusListModel::Model), QStringLiteral("DBU200-D"));
    EXPECT_EQ(text(1, BusListModel::Family), QStringLiteral("DCPID"));
    EXPECT_EQ(text(2, BusListModel::State), DeviceInfo::stateText(DeviceInfo::State::Absent));
    EXPECT_EQ(text(3, BusListModel::Switches), QStringLiteral("96h  SW1=9 SW2=6"));
    EXPECT_EQ(text(3, BusListModel::Model), QStringLiteral("DBU400-D4"));
    EXPECT_TRUE(text(3, BusListModel::Firmware).startsWith(QStringLiteral("V")));
}

TEST(MainWindow, ABadConnectionIsRefusedWithAReason)
{
    ConnectionSettings settings;
    settings.kind = ConnectionSettings::Kind::Simulated;
    settings.simSpec = QStringLiteral("dbu999@1");
    auto made = BackendFactory::makeClient(settings);
    EXPECT_FALSE(made.client);
    EXPECT_TRUE(made.error.contains(QStringLiteral("unknown device type")))
        << qPrintable(made.error);
    settings.kind = ConnectionSettings::Kind::Serial;
    settings.port.clear();
    made = BackendFactory::makeClient(settings);
    EXPECT_FALSE(made.client);
    EXPECT_FALSE(made.error.isEmpty());
}
