#include "ui/pages/RunningDataPage.h"

#include "model/bus/DriveName.h"
#include "model/profile/RunningData.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "ui/groups/GroupWriteCheck.h"
#include "ui/workspace/ParameterField.h"
#include "ui/workspace/PendingValues.h"

#include <QGridLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

namespace {

constexpr int kRows = 8;
const char* const kColumns[] = {"speed", "accel", "decel", "direction"};

QString defaultText(const ParameterMeta& meta, const ValueContext& context)
{
    const ValueSpec& spec = meta.specFor(context);
    const std::optional<double> raw = spec.defaultRaw ? spec.defaultRaw : meta.spec.defaultRaw;
    if (!raw)
        return QString();
    const ParamValue value =
        ValueCodec::decode(meta, ValueCodec::rawToRegisters(meta, *raw), context);
    return ValueCodec::format(meta, value, context);
}

} // namespace

RunningDataPage::RunningDataPage(DeviceParameters* parameters, QWidget* parent)
    : ParameterPage(parameters, tr("Running data"), parent)
    , m_init(kRows, nullptr)
    , m_range(new QLabel(contentArea()))
{
    for (const ParameterMeta* m :
         parameters->profile().parametersInGroup(QStringLiteral("running")))
        if (m->safety.isEmpty() && parameters->entry(m->name))
            m_names << m->name;

    auto* layout = new QVBoxLayout(contentArea());
    m_range->setWordWrap(true);
    m_range->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_range);

    auto* grid = new QGridLayout;
    const QString headers[] = {tr("Running data"), tr("Speed (r/min)"), tr("Acceleration (s)"),
                               tr("Deceleration (s)"), tr("Direction")};
    for (int c = 0; c < 5; ++c) {
        auto* header =
            new QLabel(QStringLiteral("<b>%1</b>").arg(headers[c].toHtmlEscaped()), contentArea());
        grid->addWidget(header, 0, c);
    }
    QWidget* previous = nullptr;
    auto chain = [&previous](QWidget* w) {
        if (previous)
            QWidget::setTabOrder(previous, w);
        previous = w;
    };
    for (int spno = 1; spno <= kRows; ++spno) {
        auto* rowLabel = new QLabel(tr("SPno%1").arg(spno), contentArea());
        // M0 is the lowest bit of the selection (7-1-1 remark 5: 000 = SPno1 ... 111 = SPno8).
        const int code = spno - 1;
        rowLabel->setToolTip(tr("Selected by the inputs M0 = %1, M1 = %2, M2 = %3 or by the "
                                "running data selection command")
                                 .arg(code & 1)
                                 .arg((code >> 1) & 1)
                                 .arg((code >> 2) & 1));
        grid->addWidget(rowLabel, spno, 0);
        for (int c = 0; c < 4; ++c) {
            const QString name = nameOf(spno, kColumns[c]);
            if (parameters->entry(name)) {
                auto* f = new ParameterField(parameters, name, contentArea());
                // Its message goes to the line under the grid: shown under the field, it made
                // the rows below jump away from the mouse.
                f->setMessageOutside(true);
                connect(f, &ParameterField::messageChanged, this,
                        &RunningDataPage::updateFieldMessages);
                m_fields.insert(name, f);
                grid->addWidget(f, spno, c + 1);
                chain(f->editor());
                continue;
            }
            // SPno1 has no time registers: the SS/SD trimmers on the drive set them (9, 12-2).
            auto* none = new QLabel(contentArea());
            if (spno == 1 && c == 1) {
                none->setText(tr("SS trimmer"));
                none->setToolTip(tr("SPno1 has no acceleration register: the SS trimmer on the "
                                    "drive sets it (0.5–30 s); it is not stored in the drive"));
            } else if (spno == 1 && c == 2) {
                none->setText(tr("SD trimmer"));
                none->setToolTip(tr("SPno1 has no deceleration register: the SD trimmer on the "
                                    "drive sets it (0.5 s or 2–30 s); it is not stored in the "
                                    "drive"));
            } else {
                none->setText(tr("—"));
                none->setToolTip(tr("This drive has no register for this value"));
            }
            none->setAccessibleDescription(none->toolTip());
            grid->addWidget(none, spno, c + 1);
        }
        const QString command = nameOf(spno, "init");
        if (const auto* e = parameters->entry(command); e && e->meta->isWritable()) {
            auto* button = new QPushButton(tr("Initialize"), contentArea());
            button->setObjectName(command);
            button->setToolTip(tr("Reset SPno%1 on the drive to its factory defaults").arg(spno));
            button->setAccessibleName(tr("Initialize SPno%1").arg(spno));
            connect(button, &QPushButton::clicked, this, [this, spno] { initializeRow(spno); });
            grid->addWidget(button, spno, 5);
            m_init[spno - 1] = button;
            chain(button);
        }
    }
    grid->setColumnStretch(1, 1);
    grid->setColumnStretch(2, 1);
    grid->setColumnStretch(3, 1);
    grid->setColumnStretch(4, 1);
    layout->addLayout(grid);
    // The fields' messages, in a place of their own with room for two lines kept free: a
    // message that comes or goes never moves the grid.
    m_fieldMessages = new QLabel(contentArea());
    m_fieldMessages->setObjectName(QStringLiteral("fieldMessages"));
    m_fieldMessages->setWordWrap(true);
    m_fieldMessages->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_fieldMessages->setMinimumHeight(2 * m_fieldMessages->fontMetrics().lineSpacing());
    m_fieldMessages->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    layout->addWidget(m_fieldMessages);
    // The manual's advice on deceleration from high speed, for the values as they will be.
    m_decelWarning = new QLabel(contentArea());
    m_decelWarning->setObjectName(QStringLiteral("decelerationWarning"));
    m_decelWarning->setWordWrap(true);
    m_decelWarning->setStyleSheet(QStringLiteral("color: #a05000;"));
    m_decelWarning->hide();
    layout->addWidget(m_decelWarning);

    if (m_fields.contains(nameOf(1, "speed"))) {
        auto* note = new QLabel(tr("SPno1 runs at the speed of the external speed-setting VR "
                                   "(CN3) with the SS/SD trimmer times; it is not stored in the "
                                   "drive"),
                                contentArea());
        note->setWordWrap(true);
        layout->addWidget(note);
    }
    layout->addStretch(1);
    updateRange();
    updateDecelerationWarning();
    updateFieldMessages();
}

void RunningDataPage::updateFieldMessages()
{
    // In grid order, each named by its setting's label.
    QStringList lines;
    bool problem = false;
    for (int spno = 1; spno <= kRows; ++spno) {
        for (const char* column : kColumns) {
            const ParameterField* f = m_fields.value(nameOf(spno, column));
            if (!f || f->messageText().isEmpty())
                continue;
            lines << tr("%1: %2").arg(parameters()->entry(f->parameterName())->meta->label,
                                      f->messageText());
            problem = problem || f->messageIsProblem();
        }
    }
    m_fieldMessages->setText(lines.join(QLatin1Char('\n')));
    m_fieldMessages->setStyleSheet(problem ? QStringLiteral("color: #b01c1c;")
                                           : QStringLiteral("color: #a05000;"));
}

QString RunningDataPage::fieldMessages() const
{
    return m_fieldMessages->text();
}

QString RunningDataPage::nameOf(int spno, const char* column)
{
    return QStringLiteral("spno%1.%2").arg(spno).arg(QLatin1String(column));
}

QPushButton* RunningDataPage::initializeButton(int spno) const
{
    return spno >= 1 && spno <= kRows ? m_init[spno - 1] : nullptr;
}

QString RunningDataPage::rangeText() const
{
    return m_range->text();
}

QStringList RunningDataPage::rowSettings(int spno) const
{
    const QString prefix = QStringLiteral("spno%1.").arg(spno);
    QStringList names;
    for (const QString& n : m_names) {
        if (n.startsWith(prefix) && parameters()->entry(n)->meta->kind == QLatin1String("setting"))
            names << n;
    }
    return names;
}

void RunningDataPage::parameterChanged(const QString& name)
{
    if (ParameterField* f = m_fields.value(name))
        f->sync();
    updateRange(); // the variant may have become known since
    updateDecelerationWarning();
}

QString RunningDataPage::decelerationWarning() const
{
    return m_decelWarning->isHidden() ? QString() : m_decelWarning->text();
}

void RunningDataPage::updateDecelerationWarning()
{
    const QString warning =
        RunningData::summary(parameters()->profile(), PendingValues::context(parameters()));
    m_decelWarning->setText(warning);
    m_decelWarning->setVisible(!warning.isEmpty());
}

void RunningDataPage::showEvent(QShowEvent* event)
{
    updateRange();
    ParameterPage::showEvent(event);
}

void RunningDataPage::updateRange()
{
    // The first writable speed of the grid stands for all: they share one allowed set.
    const ParameterMeta* speed = nullptr;
    for (int spno = 1; spno <= kRows && !speed; ++spno) {
        const auto* e = parameters()->entry(nameOf(spno, "speed"));
        if (e && e->meta->isWritable())
            speed = e->meta;
    }
    if (!speed) {
        m_range->clear();
        return;
    }
    const DeviceSession* session = parameters()->session();
    const ValueContext context = session->context();
    const Profile& profile = parameters()->profile();
    if (!context.variant.isEmpty()) {
        const ProfileVariant* v = profile.variant(context.variant);
        m_range->setText(
            tr("Allowed speed on this %1: %2 (0 stops the motor)")
                .arg(v ? v->model : context.variant, ValueCodec::allowedText(*speed, context)));
        return;
    }
    QStringList each;
    for (const QString& id : context.possibleVariants) {
        ValueContext one = context;
        one.variant = id;
        one.possibleVariants.clear();
        const ProfileVariant* v = profile.variant(id);
        each << tr("%1: %2").arg(v ? v->model : id, ValueCodec::allowedText(*speed, one));
    }
    m_range->setText(each.isEmpty()
                         ? tr("Allowed speed: %1").arg(ValueCodec::allowedText(*speed, context))
                         : tr("The drive's variant is not known, so a speed must suit every "
                              "variant (0 stops the motor): %1")
                               .arg(each.join(QStringLiteral("; "))));
}

QString RunningDataPage::resetSummary(int spno) const
{
    const ValueContext context = parameters()->session()->context();
    QStringList lines;
    for (const QString& n : rowSettings(spno)) {
        const ParameterMeta& meta = *parameters()->entry(n)->meta;
        const QString value = defaultText(meta, context);
        lines << tr("%1: %2").arg(meta.label, value.isEmpty() ? tr("its factory default") : value);
    }
    return lines.join(QLatin1Char('\n'));
}

void RunningDataPage::setInitializing(bool on)
{
    m_initializing = on;
    for (QPushButton* b : m_init) {
        if (b)
            b->setEnabled(!on);
    }
}

void RunningDataPage::initializeRow(int spno)
{
    const QString command = nameOf(spno, "init");
    if (m_initializing || !parameters()->entry(command))
        return;
    DeviceSession* session = parameters()->session();
    QString details = resetSummary(spno);
    if (spno == 1)
        details += QLatin1Char('\n') + tr("The SPno1 speed and times come from the external VR "
                                          "and the SS/SD trimmers; they do not change.");
    const QStringList row = rowSettings(spno);
    bool edits = false;
    for (const QString& n : row)
        edits = edits || parameters()->pendingNames().contains(n);
    if (edits)
        details += QStringLiteral("\n\n") + tr("Your unwritten edits in this row are discarded.");
    // A group parent's children execute the reset too.
    if (const QString reach = GroupWriteCheck::reachText(session); !reach.isEmpty())
        details += QStringLiteral("\n\n") + reach;

    QMessageBox box(QMessageBox::Warning, tr("Initialize SPno%1").arg(spno),
                    tr("Reset running data SPno%1 of drive %2 to these factory defaults?")
                        .arg(spno)
                        .arg(DriveName::listed(session)),
                    QMessageBox::Yes | QMessageBox::Cancel, this);
    box.setTextFormat(Qt::PlainText); // names the drive
    box.setInformativeText(details);
    box.button(QMessageBox::Yes)->setText(tr("Initialize SPno%1").arg(spno));
    box.setDefaultButton(QMessageBox::Cancel); // a reset is never the default
    if (box.exec() != QMessageBox::Yes)
        return;

    setInitializing(true);
    setStatus(tr("Initializing SPno%1…").arg(spno));
    DeviceSession::WriteOptions options;
    options.explicitCommand = true; // the user confirmed exactly this reset
    QPointer<RunningDataPage> self(this);
    session->write(command, QStringLiteral("1"), options,
                   [self, spno](const DeviceSession::Outcome& o) {
                       if (self)
                           self->finishInitialize(spno, o.ok ? QString() : o.error);
                   });
}

void RunningDataPage::finishInitialize(int spno, const QString& error)
{
    if (!error.isEmpty()) {
        setInitializing(false);
        setStatus(tr("SPno%1 was not initialized: %2").arg(spno).arg(error), true);
        emit operationFinished();
        return;
    }
    const QStringList row = rowSettings(spno);
    for (const QString& n : row)
        parameters()->revert(n); // the user chose the defaults over these edits
    QStringList readable = row;
    if (parameters()->entry(nameOf(spno, "speed")) && !readable.contains(nameOf(spno, "speed")))
        readable << nameOf(spno, "speed");
    QPointer<RunningDataPage> self(this);
    parameters()->refresh(readable, [self, spno](int failed) {
        if (!self)
            return;
        self->setInitializing(false);
        self->setStatus(
            failed ? tr("SPno%1 initialized; %n value(s) could not be read back", nullptr, failed)
                         .arg(spno)
                   : tr("SPno%1 initialized to its factory defaults").arg(spno),
            failed > 0);
        emit self->operationFinished();
    });
}

} // namespace opentop
