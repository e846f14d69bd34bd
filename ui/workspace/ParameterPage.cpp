#include "ui/workspace/ParameterPage.h"

#include "model/bus/DriveName.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "ui/bus/VariantQuestion.h"
#include "ui/groups/GroupWriteCheck.h"
#include "ui/workspace/ParameterField.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QTimer>
#include <QVBoxLayout>
#include <utility>

namespace opentop {

ParameterPage::ParameterPage(DeviceParameters* parameters, const QString& title, QWidget* parent)
    : QWidget(parent)
    , m_parameters(parameters)
    , m_title(title)
    , m_content(new QWidget(this))
    , m_status(new QLabel(this))
    , m_write(new QPushButton(tr("&Write page"), this))
    , m_revert(new QPushButton(tr("Re&vert"), this))
    , m_reread(new QPushButton(tr("Re-&read"), this))
{
    auto* layout = new QVBoxLayout(this);
    // A page larger than the window scrolls, rather than making the window larger than a
    // laptop's screen or squeezing its fields on top of each other.
    auto* scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("pageScroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(m_content);
    layout->addWidget(scroll, 1);
    auto* buttons = new QHBoxLayout;
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    buttons->addWidget(m_status, 1);
    buttons->addWidget(m_reread);
    buttons->addWidget(m_revert);
    buttons->addWidget(m_write);
    layout->addLayout(buttons);
    m_write->setToolTip(
        tr("Write this page's pending edits to the drive and verify them by reading back"));
    m_revert->setToolTip(tr("Discard this page's pending edits"));
    m_reread->setToolTip(tr("Read this page's values from the drive again (edits stay)"));
    connect(m_write, &QPushButton::clicked, this, &ParameterPage::writePage);
    connect(m_revert, &QPushButton::clicked, this, &ParameterPage::revertPage);
    connect(m_reread, &QPushButton::clicked, this, &ParameterPage::refresh);
    connect(parameters, &DeviceParameters::entryChanged, this, [this](const QString& name) {
        if (parameterNames().contains(name)) {
            // A page behind another tab of a shown window shows the value when it comes into
            // view: the monitor's values arrive many times a second for every page.
            if (window()->isVisible() && !isVisible())
                m_unseen.insert(name);
            else
                parameterChanged(name);
            // Mostly a value read again (a monitor's, many a second): the edits stay.
            const int pending = m_pending;
            updateButtons();
            if (m_pending != pending)
                emit pendingChanged();
            if (m_refusal != Refusal::None)
                updateRefusal();
        }
    });
    // parameterNames() is the subclass's: ask it once construction is complete.
    QTimer::singleShot(0, this, [this] { updateButtons(); });
}

void ParameterPage::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    if (m_unseen.isEmpty())
        return;
    // In the page's own order: a value other fields depend on (a mode) comes first.
    const QSet<QString> unseen = std::exchange(m_unseen, {});
    for (const QString& name : parameterNames()) {
        if (unseen.contains(name))
            parameterChanged(name);
    }
}

void ParameterPage::setStatus(const QString& text, bool error)
{
    m_refusal = Refusal::None;
    m_status->setText(text);
    m_status->setStyleSheet(error ? QStringLiteral("color: #b01c1c;") : QString());
}

QString ParameterPage::statusText() const
{
    return m_status->text();
}

QStringList ParameterPage::pendingOnPage() const
{
    QStringList pending;
    for (const QString& n : m_parameters->pendingNames()) {
        if (parameterNames().contains(n))
            pending << n;
    }
    return pending;
}

void ParameterPage::showRefusal(Refusal refusal)
{
    const QStringList pending = pendingOnPage();
    if (refusal == Refusal::Invalid) {
        const QStringList invalid = m_parameters->invalidNames(pending);
        setStatus(
            tr("Nothing was written: %n field(s) not accepted. %1", nullptr, int(invalid.size()))
                .arg(m_parameters->invalidSummary(invalid).join(QLatin1Char(' '))),
            true);
    } else {
        setStatus(writeBlocker(), true); // nothing is sent
    }
    m_refusal = refusal;
}

void ParameterPage::updateRefusal()
{
    const QStringList pending = pendingOnPage();
    const bool gone = m_refusal == Refusal::Invalid ? m_parameters->invalidNames(pending).isEmpty()
                                                    : writeBlocker().isEmpty();
    if (!gone) {
        showRefusal(m_refusal); // the fields still refused, as they are now
        return;
    }
    // The cause is gone: say where things stand, not what stopped an earlier click.
    setStatus(pending.isEmpty()
                  ? QString()
                  : tr("Every field is accepted now. Nothing has been written yet: Write page "
                       "sends %n value(s).",
                       nullptr, int(pending.size())));
}

void ParameterPage::updateButtons()
{
    const QStringList pending = pendingOnPage();
    m_pending = int(pending.size());
    m_write->setEnabled(!m_busy && !pending.isEmpty());
    m_revert->setEnabled(!m_busy && !pending.isEmpty());
    m_reread->setEnabled(!m_busy);
    m_write->setText(pending.isEmpty() ? tr("&Write page")
                                       : tr("&Write page (%1)").arg(pending.size()));
}

void ParameterPage::refresh()
{
    QStringList readable;
    for (const QString& n : parameterNames()) {
        const auto* e = m_parameters->entry(n);
        if (e && e->meta->isReadable())
            readable << n;
    }
    m_busy = true;
    updateButtons();
    setStatus(tr("Reading…"));
    m_parameters->refresh(readable, [this](int failed) {
        m_busy = false;
        updateButtons();
        setStatus(failed ? tr("%n value(s) could not be read", nullptr, failed) : QString(),
                  failed > 0);
        emit operationFinished();
    });
}

void ParameterPage::writePage()
{
    const QStringList pending = pendingOnPage();
    if (pending.isEmpty())
        return;
    // Values whose allowed set depends on the variant: a drive that does not report it is
    // asked once (the model decides when), before the edits are judged against it.
    if (!VariantQuestion::ensure(this, m_parameters->session(), VariantNeed::Purpose::Write,
                                 pending)) {
        setStatus(tr("Nothing was written."));
        return;
    }
    // All or nothing: with a field not accepted, no field of the page is written.
    const QStringList invalid = m_parameters->invalidNames(pending);
    if (!invalid.isEmpty()) {
        showRefusal(Refusal::Invalid);
        for (ParameterField* f : findChildren<ParameterField*>()) {
            if (f->parameterName() == invalid.first() && f->isEnabled()) {
                f->setFocus();
                break;
            }
        }
        emit operationFinished();
        return;
    }
    if (!writeBlocker().isEmpty()) {
        showRefusal(Refusal::Blocker); // nothing is sent
        return;
    }
    if (!confirmWrite(pending)) {
        setStatus(tr("Nothing was written."));
        return;
    }
    // A group parent's write is executed by its children too: named and asked first.
    if (!GroupWriteCheck::confirm(this, m_parameters->session(),
                                  tr("Write %n value(s) of the page %1 to machine number %2",
                                     nullptr, int(pending.size()))
                                      .arg(m_title)
                                      .arg(DriveName::listed(m_parameters->session())))) {
        setStatus(tr("Nothing was written."));
        return;
    }
    m_busy = true;
    updateButtons();
    setStatus(tr("Writing %n value(s)…", nullptr, pending.size()));
    m_parameters->write(pending, [this, pending](int failed) {
        m_busy = false;
        updateButtons();
        bool problem = false;
        const QString result = m_parameters->writeResultText(pending, failed, &problem);
        setStatus(result, problem);
        emit operationFinished();
    });
}

void ParameterPage::revertPage()
{
    for (const QString& n : m_parameters->pendingNames()) {
        if (parameterNames().contains(n))
            m_parameters->revert(n);
    }
    setStatus(QString());
}

} // namespace opentop
