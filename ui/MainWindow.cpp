#include "MainWindow.h"

#include "BusListModel.h"
#include "DeviceIdentifier.h"
#include "ModbusClient.h"
#include "ProfileRegistry.h"

#include <QAction>
#include <QCloseEvent>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTableView>
#include <QToolBar>

namespace opentop {

MainWindow::MainWindow(ModbusClient* client, const QVector<int>& expected, QWidget* parent)
    : QMainWindow(parent)
    , m_client(client)
    , m_expected(expected)
    , m_model(new BusListModel(this))
    , m_identifier(new DeviceIdentifier(client, ProfileRegistry::builtIn(), this))
    , m_table(new QTableView(this))
    , m_connectionLabel(new QLabel(this))
{
    setWindowTitle(tr("OpenTOP — %1").arg(client->describe()));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setAlternatingRowColors(true);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    setCentralWidget(m_table);

    QToolBar* toolbar = addToolBar(tr("Bus"));
    toolbar->setObjectName(QStringLiteral("busToolbar"));
    QAction* identify = toolbar->addAction(tr("&Identify drives"));
    identify->setShortcut(QKeySequence::Refresh);
    identify->setToolTip(tr("Ask every known machine number who it is (F5)"));
    connect(identify, &QAction::triggered, this, &MainWindow::identifyAll);

    statusBar()->addPermanentWidget(m_connectionLabel);
    m_connectionLabel->setText(tr("Connecting to %1…").arg(client->describe()));
    connect(client, &ModbusClient::opened, this, &MainWindow::onOpened);
    connect(client, &ModbusClient::connectionLost, this, [this](const QString& error) {
        m_connectionLabel->setText(tr("Connection lost: %1").arg(error));
    });

    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("mainWindow/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("mainWindow/state")).toByteArray());
    if (!settings.contains(QStringLiteral("mainWindow/geometry")))
        resize(960, 560);
    client->open();
}

MainWindow::~MainWindow() = default;

void MainWindow::closeEvent(QCloseEvent* event)
{
    QSettings settings;
    settings.setValue(QStringLiteral("mainWindow/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("mainWindow/state"), saveState());
    event->accept();
}

void MainWindow::onOpened(bool ok, const QString& error)
{
    if (!ok) {
        m_connectionLabel->setText(tr("Not connected"));
        QMessageBox::warning(this, tr("Cannot connect"),
                             tr("Could not open %1:\n%2").arg(m_client->describe(), error));
        return;
    }
    m_connectionLabel->setText(tr("Connected: %1").arg(m_client->describe()));
    identifyAll();
}

void MainWindow::identifyAll()
{
    if (m_outstanding > 0)
        return;
    for (int slave : m_expected) {
        DeviceInfo pending;
        pending.slave = slave;
        m_model->upsert(pending);
        ++m_outstanding;
        m_identifier->identify(slave, [this](DeviceInfo info) {
            applyAssignedVariant(&info);
            m_model->upsert(info);
            if (--m_outstanding == 0) {
                int present = 0;
                for (int row = 0; row < m_model->rowCount(); ++row)
                    present += m_model->device(row)->state == DeviceInfo::State::Present ? 1 : 0;
                statusBar()->showMessage(tr("%n drive(s) answering", nullptr, present), 5000);
            }
        });
    }
}

} // namespace opentop

namespace opentop {

void MainWindow::applyAssignedVariant(DeviceInfo* info) const
{
    if (info->state != DeviceInfo::State::Present || !info->variant.isEmpty())
        return;
    QString variant;
    const Profile* profile =
        ProfileRegistry::builtIn().forDeviceType(m_assignedTypes.value(info->slave), &variant);
    if (!profile || profile->family != info->family || variant.isEmpty())
        return;
    info->variant = variant;
    info->model = profile->variant(variant)->model;
    info->detail =
        tr("The drive does not report its variant; %1 is the configured one.").arg(info->model);
}

} // namespace opentop
