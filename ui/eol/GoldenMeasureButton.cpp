#include "ui/eol/GoldenMeasureButton.h"

#include "model/bus/BusDrives.h"
#include "model/eol/GoldenMeasure.h"
#include "model/eol/RecipeFile.h"
#include "model/profile/ProfileRegistry.h"
#include "transport/ModbusClient.h"
#include "ui/widgets/PlainText.h"

#include <QJsonDocument>
#include <QMessageBox>
#include <QProgressDialog>

namespace opentop {

namespace {

// Not modal-blocking: the run's answer may come while another window has the focus.
void tell(QWidget* parent, QMessageBox::Icon icon, const QString& title, const QString& text,
          const QString& detail)
{
    // Errors, drives and limits quote the recipe's and the drives' texts.
    auto* box = new QMessageBox(icon, title, text, QMessageBox::Ok, parent);
    box->setTextFormat(Qt::PlainText);
    box->setInformativeText(PlainText::asWritten(detail));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace

GoldenMeasureButton::GoldenMeasureButton(std::function<BusDrives*()> drives,
                                         std::function<QJsonObject()> document,
                                         std::function<void(const QJsonObject&)> apply,
                                         QWidget* parent)
    : QPushButton(tr("Measure limits…"), parent)
    , m_drives(std::move(drives))
    , m_document(std::move(document))
    , m_apply(std::move(apply))
{
    setObjectName(QStringLiteral("measureLimits"));
    setToolTip(tr("Run the golden unit on the bus through the recipe's steps once and take the "
                  "hold limits from what it measures: the measured value ± 25 % (at least 5 % of "
                  "full scale), never wider than the limits before"));
    connect(this, &QPushButton::clicked, this, &GoldenMeasureButton::measure);
}

void GoldenMeasureButton::measure()
{
    if (m_run)
        return;
    const QString title = tr("Measure limits on the golden unit");
    auto refuse = [this, &title](const QString& why) {
        tell(window(), QMessageBox::Warning, title, why, QString());
        emit finished({}, why);
    };
    QString error;
    const std::optional<Recipe> recipe = RecipeFile::fromEdited(m_document(), &error);
    if (!recipe || recipe->positions.isEmpty())
        return refuse(recipe ? tr("The recipe has no positions.")
                             : tr("The recipe cannot be read: %1").arg(error));
    BusDrives* drives = m_drives ? m_drives() : nullptr;
    for (const RecipePosition& p : recipe->positions)
        if (!drives || !drives->session(p.machineNumber) || !drives->linkUp())
            return refuse(tr("Machine number %1 is not a drive on the bus: connect to the golden "
                             "unit and scan first.")
                              .arg(p.machineNumber));

    auto* ask = new QMessageBox(QMessageBox::Warning, title,
                                tr("Run the golden unit through the recipe's steps? These motors "
                                   "turn:"),
                                QMessageBox::Yes | QMessageBox::No, window());
    ask->setInformativeText(
        PlainText::asWritten(GoldenMeasure::motionText(*recipe).join(QLatin1Char('\n'))));
    ask->setDefaultButton(QMessageBox::No);
    ask->button(QMessageBox::Yes)->setText(tr("Run the motors"));
    ask->setAttribute(Qt::WA_DeleteOnClose);
    connect(ask, &QMessageBox::finished, this, [this, ask, recipe = *recipe](int) {
        if (ask->clickedButton() == ask->button(QMessageBox::Yes))
            run(recipe);
    });
    ask->open();
}

void GoldenMeasureButton::run(const Recipe& recipe)
{
    const QString title = tr("Measure limits on the golden unit");
    BusDrives* drives = m_drives ? m_drives() : nullptr;
    if (m_run || !drives || !drives->linkUp()) {
        tell(window(), QMessageBox::Warning, title, tr("The bus is not connected."), QString());
        return;
    }
    m_run = new GoldenMeasure(drives->client(), ProfileRegistry::builtIn(), recipe,
                              GoldenLimits::Margin(), this);
    m_progress = new QProgressDialog(tr("Measuring the golden unit…"), tr("Stop"), 0, 0, window());
    m_progress->setWindowTitle(title);
    m_progress->setMinimumDuration(0);
    m_progress->setAttribute(Qt::WA_DeleteOnClose);
    m_progress->open(); // at once: the motors turn from the first step
    // Stop, Esc and closing the window all stop the motors.
    connect(m_progress, &QProgressDialog::canceled, m_run,
            [run = m_run] { run->cancel(tr("stopped by the user")); });
    connect(m_progress, &QDialog::rejected, m_run,
            [run = m_run] { run->cancel(tr("stopped by the user")); });
    connect(m_run, &GoldenMeasure::phaseChanged, m_progress,
            [progress = m_progress](int machineNumber, EolDriveRun::Phase, const QString& text) {
                progress->setLabelText(
                    PlainText::asWritten(tr("Machine number %1: %2").arg(machineNumber).arg(text)));
            });
    connect(drives->client(), &ModbusClient::connectionLost, m_run,
            [run = m_run](const QString& why) { run->connectionLost(why); });
    m_run->start(EolStepRunner::Timing(), [this, title](const GoldenMeasure::Outcome& o) {
        if (m_progress)
            m_progress->close();
        // Not running from here on, though deleted later: a second click starts a new run.
        m_run.data()->deleteLater();
        m_run.clear();
        QString stops;
        for (const QString& d : o.unconfirmedStops)
            stops += QLatin1Char('\n') + tr("%1 is not confirmed stopped.").arg(d);
        if (!o.ok) {
            tell(window(), QMessageBox::Warning, title, tr("No limits were taken: %1").arg(o.error),
                 stops.trimmed());
            emit finished({}, o.error);
            return;
        }
        QStringList lines;
        for (const GoldenLimits::Change& c : o.limits.changes)
            lines << tr("Machine number %1, step %2: %3")
                         .arg(c.machineNumber)
                         .arg(c.step + 1)
                         .arg(GoldenLimits::changeText(c));
        m_apply(QJsonDocument::fromJson(RecipeFile::toJson(o.limits.recipe)).object());
        tell(window(), QMessageBox::Information, title,
             tr("The hold limits now follow the golden unit. Check them, then save the recipe."),
             lines.join(QLatin1Char('\n')) + stops);
        emit finished(lines, QString());
    });
}

} // namespace opentop
