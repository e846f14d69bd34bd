#include "ui/files/CompareSide.h"

#include "model/bus/BusDrives.h"
#include "model/bus/DriveName.h"
#include "model/profile/ProfileRegistry.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>

namespace opentop {

CompareSide::CompareSide(const QString& title, bool offerDefaults, BusDrives* drives,
                         QWidget* parent)
    : QGroupBox(title, parent)
    , m_source(new QComboBox)
    , m_drive(new QComboBox)
    , m_path(new QLineEdit)
    , m_browse(new QPushButton(tr("Browse…")))
    , m_fileDrive(new QComboBox)
    , m_drives(drives)
{
    m_source->addItem(tr("Drive on the bus"), BusDrive);
    m_source->addItem(tr("Drive in a backup file"), FileDrive);
    if (offerDefaults)
        m_source->addItem(tr("Factory defaults"), Defaults);
    if (drives) {
        for (int slave : drives->slaves()) {
            if (drives->session(slave))
                m_drive->addItem(tr("Drive %1 (%2)")
                                     .arg(slave)
                                     .arg(DriveName::nameAndModel(drives->name(slave),
                                                                  drives->info(slave).model)),
                                 slave);
        }
    }
    m_path->setPlaceholderText(tr("Backup file"));
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(m_path, 1);
    fileRow->addWidget(m_browse);
    auto* form = new QFormLayout(this);
    form->addRow(tr("Source:"), m_source);
    form->addRow(tr("Drive:"), m_drive);
    form->addRow(tr("File:"), fileRow);
    form->addRow(tr("Drive in file:"), m_fileDrive);
    // A file or no drives: start where something can be compared.
    if (m_drive->count() == 0)
        m_source->setCurrentIndex(1);
    else if (offerDefaults && m_drive->count() < 2)
        m_source->setCurrentIndex(2);
    connect(m_source, &QComboBox::currentIndexChanged, this, [this] {
        updateEnabled();
        emit driveChanged();
    });
    connect(m_drive, &QComboBox::currentIndexChanged, this, &CompareSide::driveChanged);
    connect(m_fileDrive, &QComboBox::currentIndexChanged, this, &CompareSide::driveChanged);
    connect(m_fileDrive, &QComboBox::activated, this, [this] { m_filePicked = true; });
    connect(m_browse, &QPushButton::clicked, this, &CompareSide::browse);
    connect(m_path, &QLineEdit::editingFinished, this, [this] {
        if (m_path->text() != QString())
            emit fileChosen(m_path->text());
    });
    updateEnabled();
}

CompareSide::Source CompareSide::source() const
{
    return Source(m_source->currentData().toInt());
}

int CompareSide::busSlave() const
{
    return m_drive->currentData().toInt();
}

void CompareSide::updateEnabled()
{
    const int source = m_source->currentData().toInt();
    m_drive->setEnabled(source == BusDrive);
    m_path->setEnabled(source == FileDrive);
    m_browse->setEnabled(source == FileDrive);
    m_fileDrive->setEnabled(source == FileDrive);
}

void CompareSide::chooseBusDrive(int slave)
{
    m_source->setCurrentIndex(m_source->findData(BusDrive));
    m_drive->setCurrentIndex(m_drive->findData(slave));
}

void CompareSide::chooseDefaults()
{
    m_source->setCurrentIndex(m_source->findData(Defaults));
}

bool CompareSide::loadFile(const QString& path, int slave, QString* error)
{
    m_source->setCurrentIndex(m_source->findData(FileDrive));
    m_path->setText(path);
    m_fileDrive->clear();
    m_filePicked = slave > 0;
    m_file = BackupFile::load(path, ProfileRegistry::builtIn(), error);
    if (!m_file)
        return false;
    for (const BackupDevice& d : m_file->devices)
        m_fileDrive->addItem(d.title(), d.slave);
    if (slave <= 0 && m_otherSlave > 0)
        slave = m_file->counterpartOf(m_otherSlave, m_otherFamily);
    if (slave > 0)
        m_fileDrive->setCurrentIndex(std::max(0, m_fileDrive->findData(slave)));
    return true;
}

void CompareSide::follow(int slave, const QString& family)
{
    m_otherSlave = slave;
    m_otherFamily = family;
    if (!m_file || m_filePicked || slave <= 0)
        return;
    const int index = m_fileDrive->findData(m_file->counterpartOf(slave, family));
    if (index >= 0)
        m_fileDrive->setCurrentIndex(index);
}

int CompareSide::shownSlave() const
{
    switch (source()) {
    case BusDrive:
        return busSlave();
    case FileDrive:
        return fileDevice() ? fileDevice()->slave : 0;
    case Defaults:
        break;
    }
    return 0;
}

QString CompareSide::shownFamily() const
{
    if (source() == BusDrive)
        return m_drives && busSlave() > 0 ? m_drives->info(busSlave()).family : QString();
    if (source() == FileDrive && fileDevice())
        return fileDevice()->family;
    return QString();
}

const BackupDevice* CompareSide::fileDevice() const
{
    return m_file ? m_file->device(m_fileDrive->currentData().toInt()) : nullptr;
}

QString CompareSide::fileName() const
{
    return QFileInfo(m_path->text()).fileName();
}

void CompareSide::setResolved(const BackupDevice& device, const QString& title)
{
    m_device = device;
    m_title = title;
}

void CompareSide::browse()
{
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open backup file"), m_path->text(),
                                     tr("OpenTOP backups (*.json);;All files (*)"));
    if (!path.isEmpty())
        emit fileChosen(path);
}

} // namespace opentop
