#include "ui/tuning/TuningRunsView.h"

#include "model/tuning/StepMetrics.h"
#include "ui/tuning/TuningChart.h"
#include "ui/tuning/TuningMetricsView.h"
#include "ui/tuning/TuningRunCsv.h"
#include "ui/tuning/TuningRunList.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>

#include <iterator>

namespace opentop {

namespace {

const QColor kColours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28),
                           QColor(0x2c, 0xa0, 0x2c), QColor(0x94, 0x67, 0xbd),
                           QColor(0xff, 0x7f, 0x0e), QColor(0x8c, 0x56, 0x4b),
                           QColor(0xe3, 0x77, 0xc2), QColor(0x17, 0xbe, 0xcf)};

} // namespace

TuningRunsView::TuningRunsView(const QString& drive, QWidget* parent)
    : QWidget(parent)
    , m_drive(drive)
    , m_chart(new TuningChart(this))
    , m_runList(new TuningRunList(this))
    , m_metrics(new TuningMetricsView(this))
    , m_saveCsv(new QPushButton(tr("Save CSV…"), this))
    , m_savePng(new QPushButton(tr("Save PNG…"), this))
    , m_redraw(new QTimer(this))
{
    m_saveCsv->setObjectName(QStringLiteral("saveCsv"));
    m_savePng->setObjectName(QStringLiteral("savePng"));
    m_saveCsv->setToolTip(tr("Saves the selected run: its samples, gains and metrics"));
    m_savePng->setToolTip(tr("Saves the chart as it is shown"));
    auto* key = new QLabel(tr("solid: speed · dotted: command · dash-dot: current (right axis) · "
                              "dashed: predicted speed"),
                           this);
    key->setWordWrap(true);
    auto* chartBox = new QWidget(this);
    auto* chartColumn = new QVBoxLayout(chartBox);
    chartColumn->setContentsMargins(0, 0, 0, 0);
    chartColumn->addWidget(m_chart, 1);
    chartColumn->addWidget(key);
    auto* bottomBox = new QWidget(this);
    auto* bottom = new QHBoxLayout(bottomBox);
    bottom->setContentsMargins(0, 0, 0, 0);
    bottom->addWidget(m_runList, 3);
    auto* metricsColumn = new QVBoxLayout;
    metricsColumn->addWidget(m_metrics);
    auto* saves = new QHBoxLayout;
    saves->addWidget(m_saveCsv);
    saves->addWidget(m_savePng);
    metricsColumn->addLayout(saves);
    metricsColumn->addStretch();
    bottom->addLayout(metricsColumn, 2);
    auto* split = new QSplitter(Qt::Vertical, this);
    // The runs and figures scroll when the window is short (a laptop with docks open, CJK rows).
    auto* bottomScroll = new QScrollArea(this);
    bottomScroll->setWidget(bottomBox);
    bottomScroll->setWidgetResizable(true);
    bottomScroll->setFrameShape(QFrame::NoFrame);
    bottomScroll->setMinimumHeight(90);
    // The chart and its wrapped legend line whole: a splitter does not ask a wrapped label
    // for its height, and squeezed them on top of each other with docks open.
    chartBox->setMinimumHeight(m_chart->minimumHeight() + 2 * fontMetrics().lineSpacing() +
                               chartColumn->contentsMargins().top() +
                               chartColumn->contentsMargins().bottom() + chartColumn->spacing());
    split->addWidget(chartBox);
    split->addWidget(bottomScroll);
    // The chart takes what the runs and figures leave.
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 0);
    split->setChildrenCollapsible(false);
    m_runList->setMinimumHeight(60);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(split);

    m_redraw->setInterval(150);
    connect(m_redraw, &QTimer::timeout, this, &TuningRunsView::redraw);
    connect(m_saveCsv, &QPushButton::clicked, this, &TuningRunsView::saveCsvAsked);
    connect(m_savePng, &QPushButton::clicked, this, &TuningRunsView::savePngAsked);
    connect(m_runList, &TuningRunList::visibilityChanged, this, [this](int id, bool visible) {
        if (TuningRun* r = run(id))
            r->visible = visible;
        redraw();
    });
    connect(m_runList, &TuningRunList::runSelected, this, &TuningRunsView::redraw);
    redraw();
}

TuningRun* TuningRunsView::run(int id)
{
    for (TuningRun& r : m_runs) {
        if (r.id == id)
            return &r;
    }
    return nullptr;
}

const TuningRun* TuningRunsView::selectedRun() const
{
    for (const TuningRun& r : m_runs) {
        if (r.id == m_runList->selectedRun())
            return &r;
    }
    return m_runs.isEmpty() ? nullptr : &m_runs.last();
}

void TuningRunsView::setSpeedUnit(const QString& unit)
{
    m_chart->setSpeedUnit(unit);
}

TuningRun& TuningRunsView::addRun(TuningRun::Kind kind, const QString& title, const PidGains& gains)
{
    TuningRun r;
    r.id = m_nextId++;
    r.kind = kind;
    r.title = title;
    r.gains = gains;
    r.color = kColours[(r.id - 1) % int(std::size(kColours))];
    m_runs << r;
    m_runList->addRun(r);
    return m_runs.last();
}

void TuningRunsView::runChanged(int id)
{
    if (TuningRun* r = run(id)) {
        m_runList->updateRun(*r);
        m_runList->selectRun(id);
    }
    redraw();
}

void TuningRunsView::setRecording(bool recording)
{
    m_recording = recording;
    if (recording)
        m_redraw->start();
    else
        m_redraw->stop();
    redraw();
}

void TuningRunsView::beginLive(const QString& title, const PidGains& gains, double from, double to,
                               const QString& unit)
{
    TuningRun& run = addRun(TuningRun::Kind::Step, title, gains);
    run.live = true;
    run.result.from = from;
    run.result.to = to;
    run.result.speedUnit = unit;
    m_liveId = run.id;
    runChanged(run.id);
    setRecording(true);
}

void TuningRunsView::addLiveSample(const TuningSample& sample)
{
    if (TuningRun* r = run(m_liveId))
        r->result.samples << sample;
}

void TuningRunsView::endLive(const TuningRunner::Result& result, const QString& unit)
{
    if (TuningRun* r = run(m_liveId)) {
        r->live = false;
        r->result = result;
        r->result.speedUnit = result.speedUnit.isEmpty() ? unit : result.speedUnit;
        if (result.ok || !result.samples.isEmpty())
            r->gains = result.gains;
        runChanged(r->id);
    }
    m_liveId = -1;
    setRecording(false);
}

void TuningRunsView::addPrediction(const QString& title, const TuningRunner::Result& autotune,
                                   double from, double to, const QString& unit)
{
    TuningRun& run = addRun(TuningRun::Kind::Prediction, title, autotune.proposal);
    run.result.samples = autotune.predicted;
    run.result.from = from;
    run.result.to = to;
    run.result.speedUnit = autotune.speedUnit.isEmpty() ? unit : autotune.speedUnit;
    run.result.metrics = StepMetrics::measure(autotune.predicted, from, to);
    runChanged(run.id);
}

void TuningRunsView::redraw()
{
    QVector<const TuningRun*> shown;
    for (const TuningRun& r : m_runs) {
        if (r.visible)
            shown << &r;
    }
    m_chart->setRuns(shown);
    m_metrics->showRun(selectedRun());
    m_saveCsv->setEnabled(!m_runs.isEmpty() && !m_recording);
    m_savePng->setEnabled(!m_runs.isEmpty());
}

bool TuningRunsView::saveCsv(const QString& path, QString* error) const
{
    const TuningRun* r = selectedRun();
    if (!r) {
        *error = tr("no run to save");
        return false;
    }
    return TuningRunCsv::write(path, *r, m_drive, error);
}

bool TuningRunsView::savePng(const QString& path) const
{
    return m_chart->grab().save(path, "PNG");
}

void TuningRunsView::saveCsvAsked()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save run as CSV"), QString(),
                                                      tr("CSV files (*.csv)"));
    QString error;
    if (!path.isEmpty() && !saveCsv(path, &error))
        QMessageBox::warning(this, tr("Save run as CSV"), error);
}

void TuningRunsView::savePngAsked()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save chart as PNG"), QString(),
                                                      tr("PNG images (*.png)"));
    if (!path.isEmpty() && !savePng(path))
        QMessageBox::warning(this, tr("Save chart as PNG"), tr("Could not write %1.").arg(path));
}

} // namespace opentop
