#include "ui/help/UserGuideDialog.h"

#include "ui/run/StopAllButton.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

namespace opentop {

QString UserGuideDialog::installedDocumentation()
{
    // packaging/CMakeLists.txt: share/doc/opentop under the installation prefix.
    const QString path = QStringLiteral("/usr/share/doc/opentop");
    return QDir(path).exists() ? path : QString();
}

UserGuideDialog::UserGuideDialog(QWidget* parent)
    : QDialog(parent)
    , m_browser(new QTextBrowser(this))
{
    setObjectName(QStringLiteral("userGuideDialog"));
    setWindowTitle(tr("OpenTOP user guide"));
    const QString stopKeys = StopAllButton::shortcuts().first().toString(QKeySequence::NativeText) +
                             tr(" or ") +
                             StopAllButton::shortcuts().last().toString(QKeySequence::NativeText);
    QString html =
        tr("<h2>Commissioning a drive with OpenTOP</h2>"
           "<ol>"
           "<li><b>Connect.</b> Bus ▸ Connect… chooses the serial port (or USB to RS-485 adapter), "
           "a "
           "Modbus TCP gateway or a simulated bus, with the bus's baud rate, parity and stop bits. "
           "The status bar says what the program is connected to; a simulated bus is marked as "
           "such.</li>"
           "<li><b>Find the drives.</b> Bus ▸ Scan bus (F5) asks every machine number 1–247; the "
           "drives that answer are identified and listed on the left with their state and "
           "control priority.</li>"
           "<li><b>Select a drive.</b> Its pages open on the right: Monitor (live values), the "
           "parameter pages of its profile, Test run and Alarms.</li>"
           "<li><b>Edit settings.</b> An edited field is marked as pending until it is written. "
           "Write page (or Drive ▸ Write all pending, Ctrl+W) writes and reads every value back to "
           "verify it; Revert drops the edits; Re-read (Ctrl+R) reads the drive again. A value the "
           "drive would refuse is never sent: the field says why.</li>"
           "<li><b>Test-run the motor.</b> The Test run page starts, stops and reverses the drive "
           "in communication priority and asks before the first start of each drive. Return the "
           "drive to I/O priority when done, so that the machine's own inputs control it "
           "again.</li>"
           "<li><b>Stop.</b> STOP ALL on the toolbar, or %1, stops every drive on the bus at once, "
           "from any window of the program.</li>"
           "<li><b>Watch.</b> View ▸ Trends (Ctrl+G) charts speeds and loads; View ▸ Bus overview "
           "shows every drive at a glance; View ▸ Traffic log (Ctrl+T) shows each frame on the bus "
           "with its meaning.</li>"
           "<li><b>Keep the settings.</b> Files ▸ Back up saves the settings of one drive or the "
           "whole bus to a file; Files ▸ Compare shows differences between drives, files and "
           "factory defaults; Files ▸ Restore writes a backup back after a preview.</li>"
           "</ol>"
           "<p>Every keyboard shortcut is listed in Help ▸ Keyboard shortcuts.</p>"
           "<h3>More documentation</h3>"
           "<p>The command line and the simulator: <code>man opentop</code>, "
           "<code>man opentop-cli</code>, <code>man opentop-sim</code>.</p>")
            .arg(stopKeys.toHtmlEscaped());
    // Leaving a bus and coming back to one, apart from the steps above.
    html += tr("<h3>Leaving a bus, and coming back after the link drops</h3>"
               "<p><b>Leaving.</b> Quitting, Bus ▸ Disconnect or connecting elsewhere while drives "
               "run or are in communication priority names each of them and what will happen to "
               "it. The default stops every running drive, reads it back to confirm the stop, and "
               "then gives each drive back to its own inputs (I/O priority, read back), so that "
               "the machine works without OpenTOP. You may instead give control back only, leave "
               "the drives as they are, or stay.</p>"
               "<p><b>A lost link.</b> When the adapter is pulled out or the gateway goes, every "
               "live value turns grey and a message says which drives were running or in "
               "communication priority when the link dropped, with the age of what is known. "
               "OpenTOP cannot stop them over a lost link: check the drive's STOP input, the "
               "emergency stop and the power on the machine. Bus ▸ Reconnect (Ctrl+R, also in the "
               "message and in the red bar) opens the same port again with the same drives, "
               "selected drive and page, reads every drive again and says at once if one is "
               "running. While connected, Ctrl+R re-reads the drive's pages.</p>");
    const QString docs = installedDocumentation();
    if (!docs.isEmpty()) {
        // The package installs the README (the whole description of the program) there.
        const QString readme = QDir(docs).filePath(QStringLiteral("README.md"));
        const QString target = QFile::exists(readme) ? readme : docs;
        html += tr("<p>The full description of the program: <a href=\"%1\">%2</a></p>")
                    .arg(QUrl::fromLocalFile(target).toString(), target.toHtmlEscaped());
    }
    m_browser->setObjectName(QStringLiteral("userGuideText"));
    m_browser->setOpenExternalLinks(true);
    m_browser->setHtml(html);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_browser, 1);
    layout->addWidget(buttons);
    resize(640, 560);
}

} // namespace opentop
