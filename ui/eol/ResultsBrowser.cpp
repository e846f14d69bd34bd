#include "ui/eol/ResultsBrowser.h"

#include "model/eol/CertificateHtml.h"
#include "model/eol/ResultCsv.h"
#include "model/eol/ResultDatabase.h"
#include "model/eol/ResultQueries.h"
#include "model/eol/ResultUrl.h"
#include "model/eol/ResultWriter.h"
#include "model/eol/YieldReport.h"
#include "model/io/DisplayText.h"
#include "report/CertificatePdf.h"
#include "ui/eol/ResultsFilterBar.h"
#include "ui/widgets/ClearOfStopAll.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace opentop {

namespace {

enum Column
{
    Started,
    Serial,
    RecipeColumn,
    Station,
    Operator,
    Verdict,
    Duration,
    Reason,
    ColumnCount
};

QColor verdictColour(UnitStatus status)
{
    switch (status) {
    case UnitStatus::Pass:
        return QColor(0xc8, 0xe6, 0xc9);
    case UnitStatus::Fail:
        return QColor(0xff, 0xcd, 0xd2);
    default:
        return QColor(0xff, 0xe0, 0xb2);
    }
}

} // namespace

ResultsBrowser::ResultsBrowser(const QString& url, QWidget* parent)
    : QDialog(parent)
    , m_results(std::make_unique<ResultWriter>())
{
    setWindowTitle(tr("End-of-line results"));
    setObjectName(QStringLiteral("resultsBrowser"));
    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setHorizontalHeaderLabels({tr("Started"), tr("Serial"), tr("Recipe"), tr("Station"),
                                        tr("Operator"), tr("Verdict"), tr("Time (s)"),
                                        tr("First failure")});
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_details = new QTextBrowser(this);
    m_summary = new QLabel(this);
    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText); // paths, the database's errors

    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_table);
    split->addWidget(m_details);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);

    m_csv = new QPushButton(tr("Export CSV…"), this);
    m_certificate = new QPushButton(tr("Certificate PDF…"), this);
    m_certificate->setEnabled(false);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_csv, QDialogButtonBox::ActionRole);
    buttons->addButton(m_certificate, QDialogButtonBox::ActionRole);

    m_filters = new ResultsFilterBar(this);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_filters);
    layout->addWidget(m_message);
    layout->addWidget(m_summary);
    layout->addWidget(split, 1);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_filters, &ResultsFilterBar::openAsked, this, &ResultsBrowser::openDatabase);
    connect(m_filters, &ResultsFilterBar::searchAsked, this, &ResultsBrowser::search);
    connect(m_csv, &QPushButton::clicked, this, &ResultsBrowser::chooseCsv);
    connect(m_certificate, &QPushButton::clicked, this, &ResultsBrowser::chooseCertificate);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, &ResultsBrowser::showSelected);
    resize(1100, 700);
    ClearOfStopAll::keep(this);

    QString text = url;
    if (text.trimmed().isEmpty())
        text = qEnvironmentVariable("OPENTOP_EOL_DB");
    if (text.trimmed().isEmpty())
        text = ResultUrl::defaultLocation();
    m_filters->setUrl(text);
    openDatabase(text);
}

ResultsBrowser::~ResultsBrowser() = default;

bool ResultsBrowser::openDatabase(const QString& text)
{
    ++m_generation;
    m_open = false;
    m_units.clear();
    m_selected.reset();
    m_table->setRowCount(0);
    m_details->clear();
    m_summary->clear();
    QString error;
    const std::optional<ResultUrl> url = ResultUrl::parse(text.trimmed(), &error);
    if (!url) {
        say(error, true);
        return false;
    }
    // Looking must not leave an empty database behind a mistyped name.
    if (url->engine == ResultUrl::Engine::Sqlite && !QFileInfo(url->path).isFile()) {
        say(tr("There is no results database at %1 yet: a station makes it when it records its "
               "first unit.")
                .arg(url->path),
            true);
        return false;
    }
    say(tr("Opening the results database %1…").arg(url->displayText()), false);
    const int generation = m_generation;
    m_results->open(text.trimmed(), QString(), this,
                    [this, generation](const ResultWriter::Opened& o) {
                        if (generation != m_generation)
                            return;
                        if (!o.ok) {
                            say(o.error, true);
                            emit searched(false);
                            return;
                        }
                        m_open = true;
                        say(tr("Results database %1").arg(o.displayText), false);
                        search();
                    });
    return true;
}

bool ResultsBrowser::isBusy() const
{
    return m_results->pending() > 0;
}

bool ResultsBrowser::search()
{
    const int generation = ++m_generation;
    m_units.clear();
    m_selected.reset();
    m_table->setRowCount(0);
    m_details->clear();
    m_certificate->setEnabled(false);
    if (!m_open) {
        m_summary->clear();
        return false;
    }
    const ResultFilter filter = m_filters->filter();
    m_summary->setText(tr("Searching…"));
    struct Found
    {
        std::optional<YieldReport::Tables> tables;
        QString error;
    };
    auto found = std::make_shared<Found>();
    m_results->run(
        this,
        [filter, found](ResultDatabase* db) {
            if (!db) {
                found->error = tr("the results database is not open");
                return;
            }
            found->tables = YieldReport::query(*db, filter, ShiftPlan(), &found->error);
        },
        [this, found, generation] {
            if (generation != m_generation)
                return;
            if (!found->tables) {
                m_summary->clear();
                say(found->error, true);
                emit searched(false);
                return;
            }
            showFound(*found->tables);
            emit searched(true);
        });
    return true;
}

void ResultsBrowser::showFound(const YieldReport::Tables& tables)
{
    m_units = tables.units;
    m_yield = YieldReport::total(tables.perRecipe);
    m_table->setRowCount(int(m_units.size()));
    for (int row = 0; row < m_units.size(); ++row) {
        const UnitRecord& u = m_units.at(row);
        const qint64 ms = u.ended.isValid() ? u.started.msecsTo(u.ended) : -1;
        const QStringList cells = {
            u.started.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")),
            u.serial,
            tr("%1 rev. %2").arg(u.recipeName, u.recipeRevision),
            u.station,
            u.operatorName,
            CertificateHtml::verdictText(u.status),
            ms < 0 ? tr("–") : QString::number(ms / 1000.0, 'f', 1),
            u.failureReason};
        // Every cell from the database shown escaped: one line, no bidi override (DisplayText).
        for (int c = 0; c < ColumnCount; ++c)
            m_table->setItem(row, c, new QTableWidgetItem(DisplayText::escaped(cells.at(c))));
        m_table->item(row, Verdict)->setBackground(verdictColour(u.status));
    }
    m_table->resizeColumnsToContents();
    m_summary->setText(summary());
}

QString ResultsBrowser::summary() const
{
    // The same figures as the station's screen and `eol results --yield` (YieldReport): a
    // serial tested before the period is a retest here, never a first pass.
    return tr("%n unit(s): %1 passed, %2 failed, %3 station errors · %4", nullptr,
              int(m_units.size()))
        .arg(m_yield.passed)
        .arg(m_yield.failed)
        .arg(m_yield.stationErrors)
        .arg(YieldReport::yieldText(m_yield));
}

void ResultsBrowser::showSelected()
{
    m_selected.reset();
    m_certificate->setEnabled(false);
    const int row = m_table->currentRow();
    if (!m_open || row < 0 || row >= m_units.size()) {
        m_details->setPlainText(tr("no unit is selected"));
        emit detailsShown();
        return;
    }
    m_details->setPlainText(
        tr("Reading unit %1…").arg(DisplayText::escaped(m_units.at(row).serial)));
    const QString id = m_units.at(row).id;
    const int generation = m_generation;
    struct Loaded
    {
        std::optional<UnitRecord> record;
        QVector<UnitRecord> earlier; // the serial's records before it
        QString error;
    };
    auto loaded = std::make_shared<Loaded>();
    m_results->run(
        this,
        [id, loaded](ResultDatabase* db) {
            if (db) {
                const ResultQueries queries(*db);
                loaded->record = queries.load(id, &loaded->error);
                if (loaded->record)
                    loaded->earlier = queries.earlierOf(*loaded->record, &loaded->error)
                                          .value_or(QVector<UnitRecord>());
            } else
                loaded->error = tr("the results database is not open");
        },
        [this, id, loaded, generation] {
            const int current = m_table->currentRow();
            // Another unit or search since: its own answer shows.
            if (generation != m_generation || current < 0 || current >= m_units.size() ||
                m_units.at(current).id != id)
                return;
            if (!loaded->record) {
                m_details->setPlainText(DisplayText::escapedLines(loaded->error));
            } else {
                m_selected = loaded->record;
                m_selectedEarlier = loaded->earlier;
                m_details->setHtml(CertificateHtml::html(*m_selected, m_selectedEarlier));
                m_certificate->setEnabled(true);
            }
            emit detailsShown();
        });
}

bool ResultsBrowser::exportCsv(const QString& path, QString* error) const
{
    return ResultCsv::save(path, ResultCsv::units(m_units), error);
}

bool ResultsBrowser::saveCertificate(const QString& path, QString* error)
{
    if (!m_selected) {
        *error = m_table->currentRow() < 0 ? tr("no unit is selected")
                                           : tr("the unit's record is still being read");
        return false;
    }
    return CertificatePdf::save(*m_selected, path, error, m_selectedEarlier);
}

void ResultsBrowser::chooseCsv()
{
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export units as CSV"), QStringLiteral("results.csv"), tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    QString error;
    if (exportCsv(path, &error))
        say(tr("%n unit(s) written to %1", nullptr, int(m_units.size())).arg(path), false);
    else
        say(error, true);
}

void ResultsBrowser::chooseCertificate()
{
    const int row = m_table->currentRow();
    if (row < 0 || row >= m_units.size())
        return;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save certificate"), m_units.at(row).serial + QStringLiteral(".pdf"),
        tr("PDF files (*.pdf)"));
    if (path.isEmpty())
        return;
    QString error;
    if (saveCertificate(path, &error))
        say(tr("Certificate written to %1").arg(path), false);
    else
        say(error, true);
}

void ResultsBrowser::say(const QString& text, bool error)
{
    m_message->setText(DisplayText::escapedLines(text));
    m_message->setStyleSheet(error ? QStringLiteral("color: #b71c1c; font-weight: bold")
                                   : QString());
}

} // namespace opentop
