#include "ui/connection/ConnectionDialog.h"

#include "model/bus/BusSpec.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/SerialPortList.h"
#include "ui/connection/DriveFormatsField.h"
#include "ui/connection/SerialLineFields.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QStackedWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>

namespace opentop {

namespace {

using Kind = ConnectionSettings::Kind;

const QVector<int> kBauds = {1200, 2400, 4800, 9600, 14400, 19200, 28800, 38400, 57600, 115200};

QString key(const char* name)
{
    return QStringLiteral("connection/") + QLatin1String(name);
}

QString kindName(Kind kind)
{
    switch (kind) {
    case Kind::Serial:
        return QStringLiteral("serial");
    case Kind::Tcp:
        return QStringLiteral("tcp");
    case Kind::Simulated:
        return QStringLiteral("sim");
    }
    return QString();
}

void selectData(QComboBox* combo, const QVariant& data)
{
    const int i = combo->findData(data);
    if (i >= 0)
        combo->setCurrentIndex(i);
}

} // namespace

ConnectionDialog::ConnectionDialog(QWidget* parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Connect to a bus"));
    auto* layout = new QVBoxLayout(this);

    auto* kinds = new QHBoxLayout;
    m_kind = new QButtonGroup(this);
    const QStringList labels = {tr("&Serial port"), tr("Modbus &TCP gateway"),
                                tr("Si&mulated bus")};
    for (int i = 0; i < labels.size(); ++i) {
        auto* b = new QRadioButton(labels[i], this);
        m_kind->addButton(b, i);
        kinds->addWidget(b);
    }
    kinds->addStretch(1);
    layout->addLayout(kinds);

    m_pages = new QStackedWidget(this);
    m_pages->addWidget(makeSerialPage());
    m_pages->addWidget(makeTcpPage());
    m_pages->addWidget(makeSimPage());
    layout->addWidget(m_pages);

    m_advancedToggle = new QToolButton(this);
    m_advancedToggle->setText(tr("&Advanced"));
    m_advancedToggle->setCheckable(true);
    m_advancedToggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_advancedToggle->setArrowType(Qt::RightArrow);
    layout->addWidget(m_advancedToggle);
    m_advanced = makeAdvanced();
    m_advanced->setVisible(false);
    layout->addWidget(m_advanced);
    connect(m_advancedToggle, &QToolButton::toggled, this, [this](bool on) {
        m_advanced->setVisible(on);
        m_advancedToggle->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
    });

    m_error = new QLabel(this);
    m_error->setObjectName(QStringLiteral("connectionError"));
    m_error->setWordWrap(true);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_error->setStyleSheet(QStringLiteral("color: #b01c1c;"));
    m_error->setVisible(false);
    layout->addWidget(m_error);
    layout->addStretch(1);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Connect"));
    connect(buttons, &QDialogButtonBox::accepted, this, &ConnectionDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &ConnectionDialog::reject);
    layout->addWidget(buttons);

    connect(m_kind, &QButtonGroup::idClicked, this, &ConnectionDialog::kindChanged);
    setSettings(remembered());
}

QWidget* ConnectionDialog::makeSerialPage()
{
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    auto* portRow = new QHBoxLayout;
    m_port = new QComboBox(page);
    m_port->setObjectName(QStringLiteral("port"));
    m_port->setEditable(true);
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setMinimumContentsLength(24);
    m_port->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_port->setToolTip(SerialPortList::typedPathHint());
    auto* refresh = new QPushButton(tr("&Refresh"), page);
    refresh->setToolTip(tr("List the serial ports again (after plugging in an adapter)"));
    connect(refresh, &QPushButton::clicked, this, &ConnectionDialog::refreshPorts);
    portRow->addWidget(m_port, 1);
    portRow->addWidget(refresh);
    // A row holding a layout gets no buddy from QFormLayout, and "&Port:" would show its "&".
    auto* portLabel = new QLabel(tr("&Port:"), page);
    portLabel->setObjectName(QStringLiteral("portLabel"));
    portLabel->setBuddy(m_port);
    form->addRow(portLabel, portRow);
    auto* hint = new QLabel(SerialPortList::typedPathHint(), page);
    hint->setWordWrap(true);
    form->addRow(QString(), hint);

    m_family = new QComboBox(page);
    m_family->addItem(tr("Custom"), QString());
    for (const Profile& p : ProfileRegistry::builtIn().profiles())
        m_family->addItem(tr("%1 (%2 %3%4%5)")
                              .arg(p.name)
                              .arg(p.serial.baud)
                              .arg(8)
                              .arg(QLatin1Char(p.serial.parity))
                              .arg(p.serial.stopBits),
                          p.family);
    m_family->setToolTip(tr("Fills in the factory line settings of a drive family"));
    connect(m_family, qOverload<int>(&QComboBox::activated), this,
            [this](int i) { applyFamilyDefaults(m_family->itemData(i).toString()); });
    form->addRow(tr("&Family defaults:"), m_family);

    m_baud = new QComboBox(page);
    for (int b : kBauds)
        m_baud->addItem(tr("%1 bit/s").arg(b), b);
    form->addRow(tr("&Baud rate:"), m_baud);
    m_parity = new QComboBox(page);
    m_parity->addItem(tr("None (N)"), QStringLiteral("N"));
    m_parity->addItem(tr("Even (E)"), QStringLiteral("E"));
    m_parity->addItem(tr("Odd (O)"), QStringLiteral("O"));
    form->addRow(tr("P&arity:"), m_parity);
    m_stopBits = new QComboBox(page);
    m_stopBits->addItem(tr("1 bit"), 1);
    m_stopBits->addItem(tr("2 bits"), 2);
    form->addRow(tr("S&top bits:"), m_stopBits);
    // A manual change no longer matches a preset.
    for (QComboBox* c : {m_baud, m_parity, m_stopBits})
        connect(c, qOverload<int>(&QComboBox::activated), this,
                [this] { m_family->setCurrentIndex(0); });
    m_driveFormats = new DriveFormatsField(page, form);
    m_line = new SerialLineFields(page, form);
    return page;
}

QWidget* ConnectionDialog::makeTcpPage()
{
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    m_host = new QLineEdit(page);
    m_host->setObjectName(QStringLiteral("host"));
    m_host->setPlaceholderText(tr("e.g. 192.168.1.10"));
    form->addRow(tr("&Host:"), m_host);
    m_tcpPort = new QSpinBox(page);
    m_tcpPort->setRange(1, 65535);
    m_tcpPort->setToolTip(tr("Modbus TCP uses port 502"));
    form->addRow(tr("TCP p&ort:"), m_tcpPort);
    return page;
}

QWidget* ConnectionDialog::makeSimPage()
{
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    m_simSpec = new QLineEdit(page);
    m_simSpec->setObjectName(QStringLiteral("simSpec"));
    m_simSpec->setPlaceholderText(QStringLiteral("dbu200@1,dbu400@150,dcpid@7"));
    m_simSpec->setToolTip(
        tr("Device types and machine numbers: TYPE@NUMBER, comma separated. "
           "Types: %1")
            .arg(ProfileRegistry::builtIn().deviceTypes().join(QStringLiteral(", "))));
    form->addRow(tr("&Devices:"), m_simSpec);
    m_simCheck = new QLabel(page);
    m_simCheck->setWordWrap(true);
    form->addRow(QString(), m_simCheck);
    connect(m_simSpec, &QLineEdit::textChanged, this, &ConnectionDialog::checkSimSpec);
    return page;
}

QWidget* ConnectionDialog::makeAdvanced()
{
    auto* box = new QWidget(this);
    auto* form = new QFormLayout(box);
    m_timeout = new QSpinBox(box);
    m_timeout->setRange(10, 10000);
    m_timeout->setSuffix(tr(" ms"));
    m_timeout->setToolTip(tr("How long to wait for each reply"));
    form->addRow(tr("Response &timeout:"), m_timeout);
    m_retries = new QSpinBox(box);
    m_retries->setRange(0, 10);
    m_retries->setToolTip(tr("Extra attempts after a request got no valid reply"));
    form->addRow(tr("R&etries:"), m_retries);
    return box;
}

void ConnectionDialog::refreshPorts()
{
    const QString current = m_port->currentText();
    m_port->clear();
    for (const SerialPortList::Port& p : SerialPortList::available())
        m_port->addItem(p.oneLine(), p.systemLocation);
    m_port->setEditText(current);
}

void ConnectionDialog::kindChanged(int kind)
{
    m_pages->setCurrentIndex(kind);
    showError(QString());
}

void ConnectionDialog::checkSimSpec()
{
    QString error;
    const QString text = m_simSpec->text().trimmed();
    const bool ok = text.isEmpty() || BusSpec::parse(text, &error).has_value();
    m_simCheck->setText(ok ? QString() : error);
    m_simCheck->setStyleSheet(ok ? QString() : QStringLiteral("color: #b01c1c;"));
}

QString ConnectionDialog::portFromText() const
{
    // A listed adapter shows its description; the path is the item's data.
    const QString text = m_port->currentText().trimmed();
    const int i = m_port->findText(text);
    return i >= 0 ? m_port->itemData(i).toString() : text;
}

ConnectionSettings ConnectionDialog::settings() const
{
    ConnectionSettings s;
    s.kind = Kind(std::max(0, m_kind->checkedId()));
    s.port = portFromText();
    s.baud = m_baud->currentData().toInt();
    s.parity = m_parity->currentData().toString().at(0).toLatin1();
    s.stopBits = m_stopBits->currentData().toInt();
    m_line->applyTo(&s);
    if (s.kind == Kind::Serial)
        m_driveFormats->applyTo(&s);
    s.host = m_host->text().trimmed();
    s.tcpPort = m_tcpPort->value();
    s.simSpec = m_simSpec->text().trimmed();
    s.timeoutMs = m_timeout->value();
    s.retries = m_retries->value();
    return s;
}

void ConnectionDialog::setSettings(const ConnectionSettings& s)
{
    if (QAbstractButton* b = m_kind->button(int(s.kind)))
        b->setChecked(true);
    m_pages->setCurrentIndex(int(s.kind));
    refreshPorts();
    const int listed = m_port->findData(s.port);
    if (listed >= 0)
        m_port->setCurrentIndex(listed);
    else
        m_port->setEditText(s.port);
    if (m_baud->findData(s.baud) < 0) // remembered from elsewhere: keep it selectable
        m_baud->addItem(tr("%1 bit/s").arg(s.baud), s.baud);
    selectData(m_baud, s.baud);
    selectData(m_parity, QString(QLatin1Char(s.parity)));
    selectData(m_stopBits, s.stopBits);
    m_line->setSettings(s);
    m_driveFormats->setSettings(s);
    m_host->setText(s.host);
    m_tcpPort->setValue(s.tcpPort);
    m_simSpec->setText(s.simSpec);
    m_timeout->setValue(s.timeoutMs);
    m_retries->setValue(s.retries);
    m_family->setCurrentIndex(0);
    for (int i = 1; i < m_family->count(); ++i) {
        const Profile* p = ProfileRegistry::builtIn().family(m_family->itemData(i).toString());
        if (p && p->serial.baud == s.baud && p->serial.parity == s.parity &&
            p->serial.stopBits == s.stopBits) {
            m_family->setCurrentIndex(i);
            break;
        }
    }
}

void ConnectionDialog::applyFamilyDefaults(const QString& family)
{
    const Profile* p = ProfileRegistry::builtIn().family(family);
    if (!p)
        return;
    selectData(m_baud, p->serial.baud);
    selectData(m_parity, QString(QLatin1Char(p->serial.parity)));
    selectData(m_stopBits, p->serial.stopBits);
    selectData(m_family, family);
}

QString ConnectionDialog::problem() const
{
    const ConnectionSettings s = settings();
    QString error = s.kind == Kind::Serial ? m_driveFormats->problem(s.baud) : QString();
    if (error.isEmpty())
        error = s.validate();
    if (error.isEmpty() && s.kind == Kind::Simulated && !BusSpec::parse(s.simSpec, &error))
        return error.isEmpty() ? tr("The device list is not valid.") : error;
    return error;
}

QString ConnectionDialog::errorText() const
{
    return m_error->text();
}

void ConnectionDialog::showError(const QString& text)
{
    m_error->setText(text);
    m_error->setVisible(!text.isEmpty());
}

void ConnectionDialog::accept()
{
    const QString error = problem();
    if (!error.isEmpty()) {
        showError(error);
        return;
    }
    showError(QString());
    remember(settings());
    QDialog::accept();
}

ConnectionSettings ConnectionDialog::remembered(bool* found)
{
    QSettings q;
    ConnectionSettings s;
    if (found)
        *found = q.contains(key("kind"));
    const QString kind = q.value(key("kind"), kindName(s.kind)).toString();
    s.kind = kind == kindName(Kind::Tcp)         ? Kind::Tcp
             : kind == kindName(Kind::Simulated) ? Kind::Simulated
                                                 : Kind::Serial;
    s.port = q.value(key("port"), s.port).toString();
    s.baud = q.value(key("baud"), s.baud).toInt();
    const QString parity = q.value(key("parity"), QString(QLatin1Char(s.parity))).toString();
    s.parity = parity.isEmpty() ? 'N' : parity.at(0).toLatin1();
    s.stopBits = q.value(key("stopBits"), s.stopBits).toInt();
    SerialLineFields::recall(q, &s);
    if (s.kind == Kind::Serial)
        DriveFormatsField::recall(q, &s);
    s.host = q.value(key("host"), s.host).toString();
    s.tcpPort = q.value(key("tcpPort"), s.tcpPort).toInt();
    s.simSpec = q.value(key("simSpec"), QStringLiteral("dbu200@1,dbu400@150,dcpid@7")).toString();
    s.timeoutMs = q.value(key("timeoutMs"), s.timeoutMs).toInt();
    s.retries = q.value(key("retries"), s.retries).toInt();
    return s;
}

void ConnectionDialog::remember(const ConnectionSettings& s)
{
    QSettings q;
    q.setValue(key("kind"), kindName(s.kind));
    q.setValue(key("port"), s.port);
    q.setValue(key("baud"), s.baud);
    q.setValue(key("parity"), QString(QLatin1Char(s.parity)));
    q.setValue(key("stopBits"), s.stopBits);
    SerialLineFields::remember(q, s);
    DriveFormatsField::remember(q, s);
    q.setValue(key("host"), s.host);
    q.setValue(key("tcpPort"), s.tcpPort);
    q.setValue(key("simSpec"), s.simSpec);
    q.setValue(key("timeoutMs"), s.timeoutMs);
    q.setValue(key("retries"), s.retries);
}

} // namespace opentop
