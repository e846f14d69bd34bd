#include "ui/files/RestoreDialog.h"

#include "model/bus/BusDrives.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "ui/bus/VariantQuestion.h"
#include "ui/files/RestoreChoice.h"
#include "ui/files/RestorePlanTable.h"
#include "ui/files/RestoreReport.h"
#include "ui/groups/GroupWriteCheck.h"
#include "ui/widgets/ClearOfStopAll.h"
#include "ui/widgets/ConfirmBox.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QVBoxLayout>

namespace opentop {

using Item = RestorePlan::Item;

RestoreDialog::RestoreDialog(BusDrives* drives, QWidget* parent)
    : QDialog(parent)
    , m_drives(drives)
    , m_restore(new BusRestore(
          [this](int slave) { return m_drives ? m_drives->session(slave) : nullptr; }, this))
    , m_pathEdit(new QLineEdit)
    , m_choice(new RestoreChoice)
    , m_table(new RestorePlanTable)
    , m_progress(new QProgressBar)
    , m_message(new QLabel)
    , m_previewButton(new QPushButton(tr("&Preview")))
    , m_writeButton(new QPushButton(tr("&Write to drives…")))
    , m_cancelButton(new QPushButton(tr("&Cancel")))
    , m_saveButton(new QPushButton(tr("&Save report…")))
{
    setWindowTitle(tr("Restore from a backup file"));
    m_pathEdit->setReadOnly(true);
    m_pathEdit->setPlaceholderText(tr("No file chosen"));
    auto* browse = new QPushButton(tr("&Choose file…"));
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(new QLabel(tr("File:")));
    fileRow->addWidget(m_pathEdit, 1);
    fileRow->addWidget(browse);

    auto* splitter = new QSplitter(Qt::Vertical);
    splitter->addWidget(m_choice);
    splitter->addWidget(m_table->withFilter()); // "Differences only" above the plan

    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText); // paths, drives' names, errors quoting the file
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_progress->setVisible(false);
    m_previewButton->setToolTip(tr("Read the drives and show what would change; writes nothing"));
    m_writeButton->setToolTip(tr("Write the previewed changes, each verified by reading it back"));
    m_cancelButton->setToolTip(tr("Stop after the write in progress has been verified"));
    m_saveButton->setToolTip(tr("Save the report as text, or as CSV when the name ends in .csv"));
    auto* close = new QPushButton(tr("C&lose"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_previewButton);
    buttons->addWidget(m_writeButton);
    buttons->addWidget(m_cancelButton);
    buttons->addStretch();
    buttons->addWidget(m_saveButton);
    buttons->addWidget(close);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(fileRow);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_progress);
    layout->addWidget(m_message);
    layout->addLayout(buttons);
    resize(900, 680);
    ClearOfStopAll::keep(this);

    connect(browse, &QPushButton::clicked, this, &RestoreDialog::chooseFile);
    connect(m_previewButton, &QPushButton::clicked, this, &RestoreDialog::preview);
    connect(m_writeButton, &QPushButton::clicked, this, &RestoreDialog::confirmAndWrite);
    connect(m_cancelButton, &QPushButton::clicked, this, &RestoreDialog::cancel);
    connect(m_restore, &BusRestore::driveStarted, this, [this](int slave) {
        showMessage((m_dryRun ? tr("Reading drive %1…") : tr("Writing drive %1…")).arg(slave),
                    false);
        updateButtons();
    });
    connect(m_restore, &BusRestore::progress, this,
            [this](int slave, int done, int total, const QString& parameter) {
                m_progress->setRange(0, total);
                m_progress->setValue(done);
                m_progress->setFormat(tr("drive %1: %2 (%v of %m)").arg(slave).arg(parameter));
                emit progress(slave, done, total);
            });
    connect(m_saveButton, &QPushButton::clicked, this, &RestoreDialog::chooseReportPath);
    connect(close, &QPushButton::clicked, this, &QDialog::reject);
    connect(m_choice, &RestoreChoice::changed, this, &RestoreDialog::selectionChanged);
    updateButtons();
}

bool RestoreDialog::setPath(const QString& path)
{
    m_path = path;
    m_pathEdit->setText(path);
    m_error.clear();
    m_file.reset();
    m_plans.clear();
    m_choice->clear();
    m_table->setRowCount(0);
    if (!QFileInfo(path).isFile())
        m_error = tr("%1: no such file").arg(path);
    else
        m_file = BackupFile::load(path, ProfileRegistry::builtIn(), &m_error);
    if (!m_file) {
        if (m_error.isEmpty())
            m_error = tr("the file could not be read");
        showMessage(tr("Refused, nothing will be written: %1").arg(m_error), true);
        selectionChanged();
        return false;
    }
    m_choice->setFile(*m_file, m_drives);
    showMessage(tr("%n drive(s) in the file. Choose what to restore, then Preview.", nullptr,
                   int(m_file->devices.size())),
                false);
    selectionChanged();
    return true;
}

QVector<int> RestoreDialog::fileSlaves() const
{
    return m_file ? m_file->slaves() : QVector<int>();
}

bool RestoreDialog::refuse(const QVector<Job>& jobs)
{
    // Every drive is checked before any is touched: a refusal writes nothing at all.
    QVector<BusRestore::Job> check;
    for (const Job& job : jobs)
        check.append({job.busSlave, job.device});
    const QVector<RestorePlan> refusals = m_restore->check(check);
    if (refusals.isEmpty())
        return false;
    m_plans = refusals;
    QStringList text{tr("Refused, nothing written:")};
    for (const RestorePlan& plan : refusals) {
        text << tr("Drive %1 from %2: %3").arg(plan.slave).arg(plan.title, plan.reason);
        for (const QString& problem : plan.problems)
            text << QStringLiteral("  ") + problem;
    }
    m_table->showPlans(m_plans, m_written);
    showMessage(text.join(QLatin1Char('\n')), true);
    return true;
}

void RestoreDialog::preview()
{
    if (isBusy())
        return;
    start(true);
}

bool RestoreDialog::write()
{
    // Only what the user has just seen in a preview is written.
    if (!canWrite())
        return false;
    start(false);
    return true;
}

void RestoreDialog::start(bool dryRun)
{
    QString error;
    const QVector<Job> chosen = m_file ? m_choice->jobs(*m_file, m_drives, &error) : QVector<Job>();
    if (!m_file)
        error = m_error.isEmpty() ? tr("Choose a backup file first.")
                                  : tr("Refused, nothing will be written: %1").arg(m_error);
    m_plans.clear();
    m_written = false;
    m_previewed = false;
    m_table->setRowCount(0);
    // The file's values are checked against each drive's variant: asked before the preview.
    QVector<int> targets;
    for (const Job& job : chosen)
        targets << job.busSlave;
    const QString stop =
        dryRun ? VariantQuestion::ensureEach(this, m_drives, targets, VariantNeed::Purpose::Write,
                                             chosen.value(0).device.parameterNames())
               : QString();
    if (chosen.isEmpty() || !stop.isEmpty() || refuse(chosen)) {
        if (chosen.isEmpty() || !stop.isEmpty())
            showMessage(stop.isEmpty() ? error : tr("Nothing was read or written: %1.").arg(stop),
                        true);
        updateButtons();
        if (dryRun)
            emit previewFinished();
        else
            emit writeFinished();
        return;
    }
    m_written = !dryRun;
    m_dryRun = dryRun;
    m_progress->setVisible(true);
    m_progress->setRange(0, 0);
    QVector<BusRestore::Job> jobs;
    for (const Job& job : chosen)
        jobs.append({job.busSlave, job.device});
    m_restore->start(jobs, dryRun, [this, dryRun](const QVector<RestorePlan>& plans) {
        m_plans = plans;
        finish(dryRun);
    });
    updateButtons();
}

void RestoreDialog::cancel()
{
    m_restore->cancel();
}

void RestoreDialog::reject()
{
    if (!isBusy()) {
        QDialog::reject();
        return;
    }
    cancel();
    showMessage(tr("Stopping after the write in progress has been verified…"), false);
}

void RestoreDialog::finish(bool dryRun)
{
    m_progress->setVisible(false);
    bool failed = false;
    for (const RestorePlan& plan : m_plans)
        failed = failed || plan.outcome != (dryRun ? RestorePlan::Outcome::Planned
                                                   : RestorePlan::Outcome::Done);
    m_previewed = dryRun && !failed;
    m_table->showPlans(m_plans, m_written);
    QStringList text;
    for (const RestorePlan& plan : m_plans) {
        QString line =
            tr("Drive %1: %2").arg(plan.slave).arg(RestorePlan::outcomeText(plan.outcome));
        if (dryRun && plan.outcome == RestorePlan::Outcome::Planned)
            line += QStringLiteral(", ") +
                    tr("%n setting(s) to write", nullptr, plan.count(Item::Action::Write));
        else if (!dryRun && !plan.items.isEmpty())
            line += QStringLiteral(", ") + RestoreReport::summary(plan);
        if (!plan.reason.isEmpty())
            line += QStringLiteral(" (%1)").arg(plan.reason);
        text << line;
        for (const QString& note : plan.notes)
            text << tr("  Note: %1").arg(note);
    }
    if (dryRun)
        text << (m_previewed ? tr("Nothing written yet. Write to drives to apply.")
                             : tr("Nothing written."));
    showMessage(text.join(QLatin1Char('\n')), failed);
    updateButtons();
    if (dryRun)
        emit previewFinished();
    else
        emit writeFinished();
}

QString RestoreDialog::outcomeText() const
{
    return m_message->text();
}

QString RestoreDialog::reportText() const
{
    return RestoreReport::text(m_path, m_plans, m_written);
}

bool RestoreDialog::saveReport(const QString& path, QString* error) const
{
    return RestoreReport::save(path, m_path, m_plans, m_written, error);
}

void RestoreDialog::selectionChanged()
{
    // A changed choice needs a new preview before anything can be written.
    m_previewed = false;
    updateButtons();
}

void RestoreDialog::updateButtons()
{
    m_previewButton->setEnabled(m_file.has_value() && !isBusy());
    m_writeButton->setEnabled(canWrite());
    m_cancelButton->setEnabled(isBusy());
    m_saveButton->setEnabled(!m_plans.isEmpty() && !isBusy());
}

void RestoreDialog::showMessage(const QString& text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("color: #c00000;") : QString());
}

void RestoreDialog::chooseFile()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Restore from backup file"), QFileInfo(m_path).absolutePath(),
        tr("OpenTOP backups (*.json);;All files (*)"));
    if (!path.isEmpty())
        setPath(path);
}

void RestoreDialog::confirmAndWrite()
{
    if (!canWrite())
        return;
    int settings = 0;
    QStringList drives;
    QStringList reached; // group parents' children execute the writes too
    for (const RestorePlan& plan : m_plans) {
        settings += plan.count(Item::Action::Write);
        drives << (m_drives ? m_drives->listed(plan.slave) : QString::number(plan.slave));
        const QString reach =
            GroupWriteCheck::reachText(m_drives ? m_drives->session(plan.slave) : nullptr);
        if (!reach.isEmpty() && plan.count(Item::Action::Write) > 0)
            reached << tr("Drive %1: %2").arg(m_drives->listed(plan.slave)).arg(reach);
        // It can shut this program out of the drive's configuration: said before it is asked.
        if (const DeviceSession* s = m_drives ? m_drives->session(plan.slave) : nullptr) {
            const QString lock = plan.lockWarning(s->profile(), s->context());
            if (!lock.isEmpty())
                reached << tr("Drive %1: %2").arg(m_drives->listed(plan.slave)).arg(lock);
        }
    }
    QString question = tr("Write %n setting(s) to drive(s) %1, each verified by reading it back?",
                          nullptr, settings)
                           .arg(drives.join(QStringLiteral(", ")));
    if (!reached.isEmpty())
        question += QStringLiteral("\n\n") + reached.join(QLatin1Char('\n'));
    ConfirmBox::ask(this, tr("Write to drives"), question, tr("&Write"), [this] { write(); });
}

void RestoreDialog::chooseReportPath()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save restore report"), QString(),
                                                      tr("Text (*.txt);;CSV (*.csv)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!saveReport(path, &error))
        showMessage(tr("Could not save %1: %2").arg(path, error), true);
}

} // namespace opentop
