#include "ui/files/BackupViewer.h"

#include "model/io/DisplayText.h"
#include "model/profile/ProfileRegistry.h"
#include "ui/widgets/ClearOfStopAll.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace opentop {

BackupViewer::BackupViewer(QWidget* parent)
    : QDialog(parent)
    , m_header(new QLabel)
    , m_errorLabel(new QLabel)
    , m_tree(new QTreeWidget)
{
    setWindowTitle(tr("Backup file"));
    m_header->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_header->setWordWrap(true);
    m_errorLabel->setWordWrap(true);
    // The file's own texts (its tool, where it was read), and errors quoting it.
    m_header->setTextFormat(Qt::PlainText);
    m_errorLabel->setTextFormat(Qt::PlainText);
    m_errorLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_errorLabel->setStyleSheet(QStringLiteral("color: #c00000; font-weight: bold;"));
    m_errorLabel->hide();
    m_tree->setColumnCount(ColumnCount);
    m_tree->setHeaderLabels({tr("Parameter"), tr("Label"), tr("Value"), tr("Registers")});
    m_tree->setAlternatingRowColors(true);
    m_tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);

    auto* openButton = new QPushButton(tr("&Open…"));
    openButton->setToolTip(tr("Open another backup file"));
    auto* close = new QPushButton(tr("C&lose"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(openButton);
    buttons->addStretch();
    buttons->addWidget(close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_header);
    layout->addWidget(m_errorLabel);
    layout->addWidget(m_tree, 1);
    layout->addLayout(buttons);
    resize(820, 560);
    ClearOfStopAll::keep(this);
    connect(openButton, &QPushButton::clicked, this, &BackupViewer::chooseFile);
    connect(close, &QPushButton::clicked, this, &QDialog::accept);
}

bool BackupViewer::open(const QString& path)
{
    m_path = path;
    m_error.clear();
    if (!QFileInfo(path).isFile())
        m_error = tr("%1: no such file").arg(path);
    else
        m_file = BackupFile::load(path, ProfileRegistry::builtIn(), &m_error);
    if (!m_error.isEmpty())
        m_file.reset();
    else if (!m_file)
        m_error = tr("the file could not be read");
    setWindowTitle(tr("Backup file %1").arg(QFileInfo(path).fileName()));
    fill();
    return m_file.has_value();
}

void BackupViewer::chooseFile()
{
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open backup file"), QFileInfo(m_path).absolutePath(),
                                     tr("OpenTOP backups (*.json);;All files (*)"));
    if (!path.isEmpty())
        open(path);
}

QString BackupViewer::registersText(const QVector<quint16>& registers)
{
    QStringList parts;
    for (quint16 r : registers)
        parts << QStringLiteral("%1 (0x%2)").arg(r).arg(r, 4, 16, QLatin1Char('0'));
    return parts.join(QStringLiteral(", "));
}

QString BackupViewer::headerText() const
{
    return m_header->text();
}

void BackupViewer::fill()
{
    m_tree->clear();
    if (!m_file) {
        m_header->setText(tr("File: %1").arg(m_path));
        m_errorLabel->setText(tr("Refused: %1").arg(m_error));
        m_errorLabel->show();
        return;
    }
    m_errorLabel->hide();
    const BackupFile::Connection& c = m_file->connection;
    QString where = c.kind;
    if (!c.port.isEmpty())
        where += QLatin1Char(' ') + c.port;
    if (!c.host.isEmpty())
        where += QLatin1Char(' ') + c.host;
    if (!c.sim.isEmpty())
        where += QLatin1Char(' ') + c.sim;
    if (c.baud > 0)
        where +=
            tr(", %1 bit/s, parity %2, %3 stop bit(s)").arg(c.baud).arg(c.parity).arg(c.stopBits);
    m_header->setText(
        tr("File: %1\nWritten by %2 on %3 (UTC)\nRead from: %4\nDrives: %5")
            .arg(DisplayText::escaped(m_path), DisplayText::escaped(m_file->tool),
                 m_file->created.toUTC().toString(QStringLiteral("yyyy-MM-dd hh:mm:ss")), where)
            .arg(m_file->devices.size()));
    for (const BackupDevice& device : m_file->devices) {
        const Profile* profile = ProfileRegistry::builtIn().family(device.family);
        auto* top = new QTreeWidgetItem(m_tree);
        top->setText(Name, device.title());
        top->setText(Label,
                     tr("%1 %2, firmware %3")
                         // The file's own texts (DisplayText).
                         .arg(DisplayText::escaped(device.family),
                              device.variant.isEmpty() ? tr("(variant unknown)")
                                                       : DisplayText::escaped(device.variant),
                              DisplayText::escaped(device.firmware)));
        top->setText(Value, tr("%n setting(s)", nullptr, int(device.parameters.size())));
        top->setData(Name, Qt::UserRole, device.slave);
        QFont bold = top->font(Name);
        bold.setBold(true);
        top->setFont(Name, bold);
        for (const BackupParameter& p : device.parameters) {
            const ParameterMeta* meta = profile ? profile->parameter(p.name) : nullptr;
            auto* item = new QTreeWidgetItem(top);
            item->setText(Name, p.name);
            item->setText(Label, meta ? meta->label : QString());
            item->setText(Value, profile ? device.text(*profile, p.name) : QString());
            item->setText(Registers, registersText(p.registers));
        }
        top->setExpanded(true);
    }
}

QString BackupViewer::cellText(int slave, const QString& parameter, Column column) const
{
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        const QTreeWidgetItem* top = m_tree->topLevelItem(i);
        if (top->data(Name, Qt::UserRole).toInt() != slave)
            continue;
        for (int j = 0; j < top->childCount(); ++j) {
            if (top->child(j)->text(Name) == parameter)
                return top->child(j)->text(column);
        }
    }
    return QString();
}

} // namespace opentop
