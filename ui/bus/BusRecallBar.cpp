#include "ui/bus/BusRecallBar.h"

#include "model/bus/BusDrives.h"
#include "model/bus/BusMemory.h"
#include "model/session/DeviceSession.h"
#include "ui/widgets/BarHideButton.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace opentop {

BusRecallBar::BusRecallBar(BusDrives* drives, const ConnectionSettings& settings, bool offer,
                           QWidget* parent)
    : QFrame(parent)
    , m_drives(drives)
    , m_key(BusMemory::key(settings))
    , m_text(new QLabel(this))
    , m_restore(new QPushButton(this))
    , m_scan(new QPushButton(tr("&Scan the bus"), this))
{
    setObjectName(QStringLiteral("busRecallBar"));
    setFrameShape(QFrame::StyledPanel);
    setStyleSheet(QStringLiteral("#busRecallBar { background: #e8f0fe; }"));
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::PlainText); // the drives' names
    auto* close = new BarHideButton(this);
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(8, 4, 4, 4);
    row->addWidget(m_text, 1);
    row->addWidget(m_restore);
    row->addWidget(m_scan);
    row->addWidget(close);
    connect(m_scan, &QPushButton::clicked, this, [this] {
        hide();
        emit scanRequested();
    });

    const QVector<BusMemory::Drive> remembered =
        offer ? BusMemory::load(m_key) : QVector<BusMemory::Drive>();
    const QString place = BusMemory::placeText(settings);
    if (!remembered.isEmpty()) {
        m_text->setText(tr("Last time on %1: %2.").arg(place, BusMemory::listText(remembered)));
        m_restore->setText(remembered.size() == 1
                               ? tr("&Restore the drive last seen")
                               : tr("&Restore the %1 drives last seen").arg(remembered.size()));
        m_restore->setToolTip(tr("Identify the drives at these machine numbers again, with the "
                                 "variants set last time"));
        const QHash<int, QString> types = BusMemory::types(remembered);
        const QMap<int, LineFormat> lines = BusMemory::lines(remembered);
        connect(m_restore, &QPushButton::clicked, this, [this, types, lines] {
            hide();
            // Drives of another format than the port's are asked in theirs, as last time.
            for (auto it = lines.begin(); it != lines.end(); ++it)
                m_drives->setLine(it.key(), *it);
            emit restoreRequested(types);
        });
    } else {
        m_restore->hide();
        m_text->setText(
            tr("No drive is known on %1 yet. Scan the bus to find the drives.").arg(place));
        // Once a drive answers (a scan from the toolbar, a drive added by number) the bar would
        // say something false: it goes.
        auto hideOnceOneAnswers = [this] {
            for (int slave : m_drives->slaves())
                if (m_drives->info(slave).state == DeviceInfo::State::Present)
                    hide();
        };
        connect(drives, &BusDrives::driveAdded, this, hideOnceOneAnswers);
        connect(drives, &BusDrives::driveChanged, this, hideOnceOneAnswers);
    }
    setVisible(offer);
    // The names given to this bus's machines, in the window or by `opentop-cli name`, and a
    // name given now is kept for next time (and for the command line) at once.
    drives->setNames(BusMemory::names(m_key));
    // The variants set here last time: offered when a variant is asked, not assumed.
    drives->setRememberedVariants(BusMemory::types(BusMemory::load(m_key)));
    connect(drives, &BusDrives::nameChanged, this, [key = m_key](int slave, const QString& name) {
        BusMemory::setName(key, slave, name);
    });
    // Writes not stored yet are kept for the bus too: a restore after a crash still stores them.
    auto keep = [drives, key = m_key](int slave) {
        if (DeviceSession* s = drives->session(slave))
            BusMemory::keep(key, s);
    };
    for (int slave : drives->slaves())
        keep(slave);
    connect(drives, &BusDrives::driveAdded, this, keep);
    connect(drives, &BusDrives::driveChanged, this, keep);
    // From now on, what is on this bus is what will be offered next time.
    connect(drives, &BusDrives::driveAdded, this, &BusRecallBar::save);
    connect(drives, &BusDrives::driveChanged, this, &BusRecallBar::save);
    connect(drives, &BusDrives::driveRemoved, this, &BusRecallBar::save);
}

QString BusRecallBar::text() const
{
    return m_text->text();
}

void BusRecallBar::save()
{
    // Until something answers, the remembered list stays as it was (a bus not yet scanned).
    bool any = false;
    for (int slave : m_drives->slaves())
        any = any || m_drives->info(slave).state == DeviceInfo::State::Present;
    if (any)
        BusMemory::save(m_key, *m_drives);
}

} // namespace opentop
