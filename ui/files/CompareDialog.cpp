#include "ui/files/CompareDialog.h"

#include "model/bus/BusDrives.h"
#include "model/files/BackupReader.h"
#include "model/files/Comparer.h"
#include "model/profile/ProfileRegistry.h"
#include "model/session/DeviceSession.h"
#include "ui/widgets/ClearOfStopAll.h"

#include <QCheckBox>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace opentop {

namespace {

// The row colour of a difference: visible in light and dark themes, text stays readable.
const QColor kDifferent(255, 214, 153);

} // namespace

CompareDialog::CompareDialog(BusDrives* drives, QWidget* parent)
    : QDialog(parent)
    , m_drives(drives)
    , m_table(new QTableWidget(0, ColumnCount))
    , m_differencesOnly(new QCheckBox(tr("&Differences only")))
    , m_filter(new QLineEdit)
    , m_summary(new QLabel)
    , m_notes(new QLabel)
    , m_compare(new QPushButton(tr("Co&mpare")))
{
    setWindowTitle(tr("Compare settings"));
    m_sides[A] = new CompareSide(tr("Side A"), false, drives);
    m_sides[B] = new CompareSide(tr("Side B"), true, drives);
    auto* sides = new QHBoxLayout;
    for (Side side : {A, B}) {
        sides->addWidget(m_sides[side]);
        connect(m_sides[side], &CompareSide::fileChosen, this,
                [this, side](const QString& path) { setFileSide(side, path); });
        // A file's drive follows the drive on the other side: drive 7 beside the file's drive 1
        // compares two different machines.
        CompareSide* other = m_sides[side == A ? B : A];
        connect(m_sides[side], &CompareSide::driveChanged, other, [this, side, other] {
            other->follow(m_sides[side]->shownSlave(), m_sides[side]->shownFamily());
        });
    }
    m_sides[B]->follow(m_sides[A]->shownSlave(), m_sides[A]->shownFamily());
    m_sides[A]->follow(m_sides[B]->shownSlave(), m_sides[B]->shownFamily());

    m_table->setHorizontalHeaderLabels({tr("Setting"), tr("Parameter"), tr("A"), tr("B")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_filter->setPlaceholderText(tr("Filter by setting or parameter name"));
    m_filter->setClearButtonEnabled(true);
    m_compare->setToolTip(tr("Read the chosen sides and compare them (drives are read fresh)"));
    m_compare->setDefault(true);
    m_summary->setWordWrap(true);
    m_notes->setWordWrap(true);
    // Errors and notes quote the files and the drives.
    m_summary->setTextFormat(Qt::PlainText);
    m_notes->setTextFormat(Qt::PlainText);
    m_notes->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* tools = new QHBoxLayout;
    tools->addWidget(m_compare);
    tools->addWidget(m_differencesOnly);
    tools->addWidget(m_filter, 1);
    auto* close = new QPushButton(tr("C&lose"));
    auto* bottom = new QHBoxLayout;
    bottom->addWidget(m_summary, 1);
    bottom->addWidget(close);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(sides);
    layout->addLayout(tools);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_notes);
    layout->addLayout(bottom);
    resize(900, 640);
    ClearOfStopAll::keep(this);

    connect(m_compare, &QPushButton::clicked, this, &CompareDialog::compare);
    connect(m_differencesOnly, &QCheckBox::toggled, this, &CompareDialog::applyFilter);
    connect(m_filter, &QLineEdit::textChanged, this, &CompareDialog::applyFilter);
    connect(close, &QPushButton::clicked, this, &QDialog::accept);
}

void CompareDialog::setDriveSide(Side side, int slave)
{
    m_sides[side]->chooseBusDrive(slave);
}

void CompareDialog::setDefaultsSide()
{
    m_sides[B]->chooseDefaults();
}

bool CompareDialog::setFileSide(Side side, const QString& path, int slave)
{
    QString error;
    if (!m_sides[side]->loadFile(path, slave, &error)) {
        showError(tr("%1 refused: %2").arg(QFileInfo(path).fileName(), error));
        return false;
    }
    showError(QString());
    return true;
}

void CompareDialog::compare()
{
    if (m_busy)
        return;
    const int generation = ++m_generation;
    m_busy = true;
    m_compare->setEnabled(false);
    m_summary->setText(tr("Reading…"));
    resolve(A, [this, generation](bool okA) {
        if (generation != m_generation)
            return;
        if (!okA) {
            m_busy = false;
            m_compare->setEnabled(true);
            emit compareFinished(false);
            return;
        }
        resolve(B, [this, generation](bool okB) {
            if (generation != m_generation)
                return;
            m_busy = false;
            m_compare->setEnabled(true);
            if (okB)
                fill();
            emit compareFinished(okB && m_error.isEmpty());
        });
    });
}

void CompareDialog::resolve(Side side, const std::function<void(bool)>& next)
{
    CompareSide* w = m_sides[side];
    const QString sideName = side == A ? tr("side A") : tr("side B");
    switch (w->source()) {
    case CompareSide::Defaults: {
        // Built in fill(), from side A's family and variant.
        w->setResolved(w->device(), tr("Factory defaults"));
        next(true);
        return;
    }
    case CompareSide::FileDrive: {
        const BackupDevice* d = w->fileDevice();
        if (!d) {
            showError(tr("Choose a backup file and a drive in it for %1.").arg(sideName));
            next(false);
            return;
        }
        w->setResolved(*d, tr("%1: %2").arg(w->fileName(), d->title()));
        next(true);
        return;
    }
    default:
        break;
    }
    const int slave = w->busSlave();
    DeviceSession* session = m_drives ? m_drives->session(slave) : nullptr;
    if (!session) {
        showError(tr("Choose an identified drive on the bus for %1.").arg(sideName));
        next(false);
        return;
    }
    auto* reader = new BackupReader(session, this);
    reader->read([this, reader, side, next, sideName](const BackupReader::Result& r) {
        reader->deleteLater();
        if (!r.failures.isEmpty()) {
            showError(tr("%1: cannot read %2")
                          .arg(r.device.title(), r.failures.join(QStringLiteral("; "))));
            next(false);
            return;
        }
        m_sides[side]->setResolved(r.device, r.device.title());
        next(true);
    });
}

void CompareDialog::showError(const QString& error)
{
    m_error = error;
    m_summary->setText(error);
    m_summary->setStyleSheet(error.isEmpty() ? QString() : QStringLiteral("color: #c00000;"));
}

void CompareDialog::fill()
{
    m_table->setRowCount(0);
    m_different.clear();
    m_differences.clear();
    const BackupDevice& a = m_sides[A]->device();
    const Profile* profile = ProfileRegistry::builtIn().family(a.family);
    if (!profile) {
        showError(tr("Unknown family %1").arg(a.family));
        return;
    }
    const bool defaults = m_sides[B]->source() == CompareSide::Defaults;
    BackupDevice b =
        defaults ? Comparer::factoryDefaults(*profile, a.variant) : m_sides[B]->device();
    const Comparer::Result result =
        defaults ? Comparer::compareWithDefaults(*profile, a) : Comparer::compare(*profile, a, b);
    if (!result.refusal.isEmpty()) {
        showError(result.refusal);
        m_notes->clear();
        return;
    }
    showError(QString());
    for (const Comparer::Difference& d : result.differences) {
        m_different.insert(d.parameter);
        m_differences << d.parameter;
    }
    m_table->setHorizontalHeaderLabels(
        {tr("Setting"), tr("Parameter"), tr("A: %1").arg(m_sides[A]->title()),
         tr("B: %1").arg(
             defaults ? tr("factory defaults (%1)").arg(a.variant.isEmpty() ? a.family : a.variant)
                      : m_sides[B]->title())});
    for (const ParameterMeta& meta : profile->parameters) {
        if (!meta.backup || (!a.parameter(meta.name) && !b.parameter(meta.name) &&
                             !result.noDefault.contains(meta.name)))
            continue;
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        QString textB = b.text(*profile, meta.name);
        if (textB.isEmpty())
            textB = defaults && result.noDefault.contains(meta.name) ? tr("(no documented default)")
                                                                     : tr("(not held)");
        const QString textA =
            a.parameter(meta.name) ? a.text(*profile, meta.name) : tr("(not held)");
        const QStringList cells{meta.label, meta.name, textA, textB};
        const bool differs = m_different.contains(meta.name);
        for (int c = 0; c < ColumnCount; ++c) {
            auto* item = new QTableWidgetItem(cells.at(c));
            if (differs) {
                item->setBackground(kDifferent);
                item->setForeground(QColor(Qt::black));
                QFont f = item->font();
                f.setBold(true);
                item->setFont(f);
            }
            m_table->setItem(row, c, item);
        }
    }
    m_table->resizeColumnsToContents();
    m_summary->setText(tr("%n difference(s)", nullptr, int(result.differences.size())) +
                       tr(" in %1 settings compared").arg(result.compared));
    QStringList notes;
    for (const QString& note : result.notes)
        notes << tr("Note: %1").arg(note);
    if (!result.noDefault.isEmpty()) {
        QStringList labels;
        for (const QString& name : result.noDefault) {
            const ParameterMeta* meta = profile->parameter(name);
            labels << (meta && !meta->label.isEmpty() ? meta->label : name);
        }
        notes << tr("No factory default documented (never counted as a difference): %1")
                     .arg(labels.join(QStringLiteral(", ")));
    }
    m_notes->setText(notes.join(QLatin1Char('\n')));
    applyFilter();
}

void CompareDialog::applyFilter()
{
    const QString filter = m_filter->text().trimmed();
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const QString name = m_table->item(row, Name)->text();
        bool show = !m_differencesOnly->isChecked() || m_different.contains(name);
        if (show && !filter.isEmpty())
            show = name.contains(filter, Qt::CaseInsensitive) ||
                   m_table->item(row, Label)->text().contains(filter, Qt::CaseInsensitive);
        m_table->setRowHidden(row, !show);
    }
}

void CompareDialog::setDifferencesOnly(bool on)
{
    m_differencesOnly->setChecked(on);
}

void CompareDialog::setFilterText(const QString& text)
{
    m_filter->setText(text);
}

QString CompareDialog::notesText() const
{
    return m_notes->text();
}

int CompareDialog::rowCount() const
{
    return m_table->rowCount();
}

int CompareDialog::visibleRowCount() const
{
    int n = 0;
    for (int row = 0; row < m_table->rowCount(); ++row)
        n += m_table->isRowHidden(row) ? 0 : 1;
    return n;
}

int CompareDialog::rowOf(const QString& parameter) const
{
    for (int row = 0; row < m_table->rowCount(); ++row) {
        if (m_table->item(row, Name)->text() == parameter)
            return row;
    }
    return -1;
}

bool CompareDialog::isHighlighted(const QString& parameter) const
{
    const int row = rowOf(parameter);
    return row >= 0 && m_table->item(row, Label)->background().color() == kDifferent;
}

bool CompareDialog::isRowShown(const QString& parameter) const
{
    const int row = rowOf(parameter);
    return row >= 0 && !m_table->isRowHidden(row);
}

QString CompareDialog::cellText(const QString& parameter, Column column) const
{
    const int row = rowOf(parameter);
    return row >= 0 ? m_table->item(row, column)->text() : QString();
}

} // namespace opentop
