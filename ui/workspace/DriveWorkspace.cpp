#include "ui/workspace/DriveWorkspace.h"

#include "model/bus/DriveName.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "ui/bus/VariantQuestion.h"
#include "ui/groups/GroupWriteCheck.h"
#include "ui/workspace/GroupPage.h"
#include "ui/workspace/SideTabWidget.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTabWidget>
#include <QVBoxLayout>

namespace opentop {

QHash<QString, DriveWorkspace::EditorFactory>& DriveWorkspace::editors()
{
    static QHash<QString, EditorFactory> registry;
    return registry;
}

void DriveWorkspace::registerEditor(const QString& id, EditorFactory factory)
{
    editors().insert(id, std::move(factory));
}

DriveWorkspace::DriveWorkspace(QWidget* parent)
    : QWidget(parent)
    , m_title(new QLabel(this))
    , m_tabs(new SideTabWidget(this))
    , m_status(new QLabel(this))
    , m_writeAll(new QPushButton(tr("Write &all pending"), this))
    , m_revertAll(new QPushButton(tr("Revert all"), this))
    , m_rereadAll(new QPushButton(tr("Re-read all"), this))
{
    auto* layout = new QVBoxLayout(this);
    QFont titleFont = m_title->font();
    titleFont.setBold(true);
    titleFont.setPointSizeF(titleFont.pointSizeF() * 1.2);
    m_title->setFont(titleFont);
    m_title->setWordWrap(true); // a long model name wraps rather than widening the window
    m_title->setTextFormat(Qt::PlainText);  // the machine's name and model, as the drive has them
    m_status->setTextFormat(Qt::PlainText); // drives' names, errors
    layout->addWidget(m_title);
    layout->addWidget(m_tabs, 1);
    auto* row = new QHBoxLayout;
    row->addWidget(m_status, 1);
    row->addWidget(m_rereadAll);
    row->addWidget(m_revertAll);
    row->addWidget(m_writeAll);
    layout->addLayout(row);
    m_writeAll->setToolTip(tr("Write every pending edit of this drive, on all pages, and verify"));
    connect(m_writeAll, &QPushButton::clicked, this, &DriveWorkspace::writeAll);
    connect(m_rereadAll, &QPushButton::clicked, this, &DriveWorkspace::refreshAll);
    connect(m_revertAll, &QPushButton::clicked, this, [this] {
        if (m_parameters)
            m_parameters->revertAll();
    });
    setDrive(nullptr, QString());
}

void DriveWorkspace::setTitle(const QString& title)
{
    if (m_parameters)
        m_title->setText(title);
}

QString DriveWorkspace::titleText() const
{
    return m_title->text();
}

void DriveWorkspace::setDrive(DeviceParameters* parameters, const QString& title)
{
    if (parameters == m_parameters && parameters)
        return;
    while (m_tabs->count() > 0) {
        QWidget* w = m_tabs->widget(0);
        m_tabs->removeTab(0);
        w->deleteLater();
    }
    if (m_parameters)
        disconnect(m_parameters, nullptr, this, nullptr);
    m_parameters = parameters;
    m_title->setText(parameters ? title : tr("Select a drive in the bus list to set it up."));
    if (!parameters)
        setStatus(QString()); // nothing of another drive's last operation
    if (parameters) {
        QStringList editorsDone;
        for (const ProfileGroup& group : parameters->profile().groups) {
            ParameterPage* page = nullptr;
            if (!group.editor.isEmpty() && editors().contains(group.editor)) {
                if (editorsDone.contains(group.editor))
                    continue; // one page for all the groups it edits
                editorsDone << group.editor;
                page = editors().value(group.editor)(parameters, m_tabs);
            } else {
                bool editable = false;
                for (const ParameterMeta* m : parameters->profile().parametersInGroup(group.id))
                    editable = editable || (m->kind == QLatin1String("setting") && m->isWritable());
                if (editable)
                    page = new GroupPage(parameters, group, m_tabs);
            }
            if (!page)
                continue;
            m_tabs->addTab(page, page->title());
            connect(page, &ParameterPage::pendingChanged, this, &DriveWorkspace::updateButtons);
        }
        connect(parameters, &DeviceParameters::entryChanged, this, &DriveWorkspace::updateButtons);
        refreshAll();
    }
    updateButtons();
}

ParameterPage* DriveWorkspace::page(const QString& title) const
{
    for (int i = 0; i < m_tabs->count(); ++i) {
        auto* p = qobject_cast<ParameterPage*>(m_tabs->widget(i));
        if (p && p->title() == title)
            return p;
    }
    return nullptr;
}

void DriveWorkspace::setStatus(const QString& text, bool problem)
{
    m_refused = false;
    m_status->setText(text);
    m_status->setStyleSheet(problem ? QStringLiteral("color: #b01c1c;") : QString());
}

void DriveWorkspace::updateRefusal()
{
    if (!m_refused || !m_parameters)
        return;
    const QStringList invalid = m_parameters->invalidNames();
    QString blocker;
    for (int i = 0; i < m_tabs->count() && invalid.isEmpty() && blocker.isEmpty(); ++i) {
        auto* page = qobject_cast<ParameterPage*>(m_tabs->widget(i));
        if (page && !page->writeBlocker().isEmpty())
            blocker = tr("%1: %2 Nothing was written.").arg(page->title(), page->writeBlocker());
    }
    if (!invalid.isEmpty())
        m_status->setText(tr("Nothing was written: %1")
                              .arg(m_parameters->invalidSummary(invalid).join(QLatin1Char(' '))));
    else if (!blocker.isEmpty())
        m_status->setText(blocker);
    else if (const int pending = int(m_parameters->pendingNames().size()); pending > 0)
        setStatus(tr("Every edit is accepted now. Nothing has been written yet: Write all "
                     "pending sends %n value(s).",
                     nullptr, pending));
    else
        setStatus(QString());
}

void DriveWorkspace::updateButtons()
{
    updateRefusal();
    // Once: every value read (a monitor's, many a second) comes here.
    const QStringList pendingNames = m_parameters ? m_parameters->pendingNames() : QStringList();
    const int pending = int(pendingNames.size());
    m_writeAll->setEnabled(pending > 0);
    m_revertAll->setEnabled(pending > 0);
    m_rereadAll->setEnabled(m_parameters != nullptr);
    m_writeAll->setText(pending ? tr("Write &all pending (%1)").arg(pending)
                                : tr("Write &all pending"));
    // Pages with pending edits carry a marker in their tab.
    for (int i = 0; i < m_tabs->count(); ++i) {
        auto* page = qobject_cast<ParameterPage*>(m_tabs->widget(i));
        if (!page || !m_parameters)
            continue;
        int onPage = 0;
        for (const QString& n : pendingNames)
            onPage += page->parameterNames().contains(n) ? 1 : 0;
        // Only on a change: every monitor sample updates entries, and a new tab text makes the
        // tab bar lay itself out again.
        const QString text = onPage ? QStringLiteral("%1 ●").arg(page->title()) : page->title();
        if (m_tabs->tabText(i) != text)
            m_tabs->setTabText(i, text);
    }
}

void DriveWorkspace::refreshAll()
{
    if (!m_parameters)
        return;
    setStatus(tr("Reading the drive…"));
    m_parameters->refresh({}, [this](int failed) {
        setStatus(failed ? tr("%n value(s) could not be read", nullptr, failed) : QString());
        emit operationFinished();
    });
}

void DriveWorkspace::writeAll()
{
    if (!m_parameters || !m_parameters->hasPending())
        return;
    // The variant first (asked once, when the model says the edits depend on it): the edits
    // are judged against it.
    if (!VariantQuestion::ensure(this, m_parameters->session(), VariantNeed::Purpose::Write,
                                 m_parameters->pendingNames())) {
        setStatus(tr("Nothing was written."));
        return;
    }
    const QStringList invalid = m_parameters->invalidNames();
    if (!invalid.isEmpty()) { // the model writes nothing then; say which and show the first
        setStatus(tr("Nothing was written: %1")
                      .arg(m_parameters->invalidSummary(invalid).join(QLatin1Char(' '))));
        m_refused = true;
        for (int i = 0; i < m_tabs->count(); ++i) {
            auto* page = qobject_cast<ParameterPage*>(m_tabs->widget(i));
            if (page && page->parameterNames().contains(invalid.first()))
                m_tabs->setCurrentIndex(i);
        }
        return;
    }
    for (int i = 0; i < m_tabs->count(); ++i) {
        auto* page = qobject_cast<ParameterPage*>(m_tabs->widget(i));
        const QString blocker = page ? page->writeBlocker() : QString();
        if (!blocker.isEmpty()) {
            setStatus(tr("%1: %2 Nothing was written.").arg(page->title(), blocker));
            m_refused = true;
            m_tabs->setCurrentIndex(i);
            return;
        }
    }
    const int count = m_parameters->pendingNames().size();
    if (!GroupWriteCheck::confirm(
            this, m_parameters->session(),
            tr("Write %n pending value(s) to machine number %1", nullptr, count)
                .arg(DriveName::listed(m_parameters->session())))) {
        setStatus(tr("Nothing was written."));
        return;
    }
    setStatus(tr("Writing %n value(s)…", nullptr, count));
    const QStringList pending = m_parameters->pendingNames();
    m_parameters->write({}, [this, pending](int failed) {
        bool problem = false;
        // Red when a write failed or was not verified on every drive it reached.
        setStatus(m_parameters->writeResultText(pending, failed, &problem), problem);
        updateButtons();
        emit operationFinished();
    });
}

} // namespace opentop
