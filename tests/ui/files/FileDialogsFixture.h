#pragma once

// Backup, restore and compare dialogs against the simulated bus: a BusDrives over the
// fixture's client with every simulated drive identified, a temporary directory for files.

#include "model/bus/BusDrives.h"
#include "sim/SimDevice.h"
#include "tests/ui/UiSimFixture.h"
#include "ui/files/BackupDialog.h"

#include <QFile>
#include <QTemporaryDir>

namespace opentop::test {

class FileDialogsFixture : public UiSimFixture
{
protected:
    void start(const QString& spec, const QVector<int>& slaves)
    {
        startBus(spec);
        drives = identifiedDrives(slaves);
        settings.kind = ConnectionSettings::Kind::Simulated;
        settings.simSpec = bus->spec();
    }
    void TearDown() override
    {
        drives.reset();
        DriveSimFixture::TearDown();
    }

    QString path(const QString& name) const { return dir.filePath(name); }

    // Backs `slaves` up through the dialog and returns whether the file was saved.
    bool backUp(const QVector<int>& slaves, const QString& file)
    {
        BackupDialog dialog(drives.get(), settings);
        const bool finished = runUntil(&dialog, &BackupDialog::backupFinished,
                                       [&] { dialog.startBackup(slaves, file); });
        EXPECT_TRUE(finished);
        EXPECT_TRUE(dialog.notRead().isEmpty()) << qPrintable(dialog.message());
        return dialog.isSaved();
    }

    static quint16 address(const QString& family, const QString& name)
    {
        return ProfileRegistry::builtIn().family(family)->parameter(name)->address;
    }

    // A setting changed behind the program's back, as if someone had used the drive's keys.
    void setRegister(int slave, quint16 address, int raw)
    {
        control(slave, {QStringLiteral("set"),
                        QStringLiteral("0x%1").arg(address, 4, 16, QLatin1Char('0')),
                        QString::number(raw)});
    }

    static void writeFile(const QString& file, const QByteArray& data)
    {
        QFile f(file);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(data);
    }

    static QByteArray readFile(const QString& file)
    {
        QFile f(file);
        EXPECT_TRUE(f.open(QIODevice::ReadOnly));
        return f.readAll();
    }

    QTemporaryDir dir;
    ConnectionSettings settings;
    std::unique_ptr<BusDrives> drives;
};

} // namespace opentop::test
