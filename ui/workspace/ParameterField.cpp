#include "ui/workspace/ParameterField.h"

#include "model/bus/BusDrives.h"
#include "model/profile/ValueCodec.h"
#include "model/session/DeviceParameters.h"
#include "model/session/DeviceSession.h"
#include "ui/bus/VariantQuestion.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QTimer>
#include <QVBoxLayout>

namespace opentop {

namespace {

bool isEnumeration(const ValueSpec& spec)
{
    return spec.ranges.isEmpty() && !spec.options.isEmpty();
}

// The label a code has in any context (a Mode2 input code while Mode1 is pending), or the code.
QString anyLabel(const ParameterMeta& meta, qint64 code)
{
    for (const EnumOption& o : meta.spec.options) {
        if (o.value == code)
            return o.label;
    }
    for (const ValueCondition& c : meta.conditions) {
        for (const EnumOption& o : c.spec.options) {
            if (o.value == code)
                return o.label;
        }
    }
    return QString::number(code);
}

} // namespace

ParameterField::ParameterField(DeviceParameters* parameters, const QString& name, QWidget* parent)
    : QWidget(parent)
    , m_parameters(parameters)
    , m_name(name)
    , m_unit(new QLabel(this))
    , m_message(new QLabel(this))
{
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->setSpacing(2);
    auto* layout = new QHBoxLayout;
    outer->addLayout(layout);
    m_message->setObjectName(name + QStringLiteral("#message"));
    m_message->setWordWrap(true);
    m_message->setStyleSheet(QStringLiteral("color: #b01c1c;"));
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->hide();
    outer->addWidget(m_message);
    const DeviceParameters::Entry* e = parameters->entry(name);
    const ParameterMeta& meta = *e->meta;
    const ValueSpec& spec = meta.specFor(parameters->session()->context());
    if (isEnumeration(spec) && meta.isWritable()) {
        m_combo = new QComboBox(this);
        m_combo->setObjectName(name);
        layout->addWidget(m_combo, 1);
        connect(m_combo, qOverload<int>(&QComboBox::activated), this,
                [this](int index) { commit(m_combo->itemData(index).toString()); });
    } else {
        m_edit = new QLineEdit(this);
        m_edit->setObjectName(name);
        m_edit->setReadOnly(!meta.isWritable());
        layout->addWidget(m_edit, 1);
        connect(m_edit, &QLineEdit::textEdited, this, &ParameterField::check);
        connect(m_edit, &QLineEdit::editingFinished, this, [this] {
            if (m_edit->isModified())
                commit(m_edit->text());
            m_edit->setModified(false);
        });
    }
    layout->addWidget(m_unit);
    setFocusProxy(editor());
    sync();
}

ParameterField::~ParameterField()
{
    // ~QWidget takes the focus from the line edit, which then reports editingFinished to a
    // field that is half destroyed (UBSan, issue 11): nothing is committed on the way out.
    if (m_edit)
        m_edit->disconnect(this);
    if (m_combo)
        m_combo->disconnect(this);
}

QWidget* ParameterField::editor() const
{
    return m_combo ? static_cast<QWidget*>(m_combo) : m_edit;
}

void ParameterField::enter(const QString& text)
{
    if (m_combo) {
        commit(text);
        return;
    }
    m_edit->setText(text);
    check(text);
    commit(text);
}

void ParameterField::setContextProvider(std::function<ValueContext()> provider)
{
    m_contextProvider = std::move(provider);
    sync();
}

ValueContext ParameterField::context() const
{
    return m_contextProvider ? m_contextProvider() : m_parameters->session()->context();
}

void ParameterField::check(const QString& text)
{
    const DeviceParameters::Entry* e = m_parameters->entry(m_name);
    const ValueCodec::Encoded encoded = ValueCodec::encodeText(*e->meta, text, context());
    // A group parent's children execute the write too: their own ranges count as well.
    const QString error = encoded.ok
                              ? m_parameters->session()->reachedProblem(m_name, encoded.registers)
                              : encoded.error;
    m_problem = text.trimmed().isEmpty() ? QString() : m_parameters->withoutName(m_name, error);
    m_typingWarning = text.trimmed().isEmpty() || !encoded.ok
                          ? QString()
                          : m_parameters->withoutName(m_name, encoded.warning);
    applyStyle();
}

void ParameterField::commit(const QString& text)
{
    if (m_syncing || text.trimmed().isEmpty() || m_askingVariant)
        return;
    // Its allowed values depend on the variant of a drive that does not report it: the variant
    // is asked first (once), so that the edit is judged against the drive's own limits. Later,
    // not inside the line edit's own focus change (the question takes the focus).
    const BusDrives* drives = BusDrives::of(m_parameters->session());
    if (drives && VariantNeed::needed(*drives, m_parameters->session()->slave(),
                                      VariantNeed::Purpose::Write, {m_name})) {
        m_askingVariant = true;
        QPointer<ParameterField> self(this);
        QTimer::singleShot(0, this, [self, text] {
            if (!self)
                return;
            const bool go = VariantQuestion::ensure(self, self->m_parameters->session(),
                                                    VariantNeed::Purpose::Write, {self->m_name});
            self->m_askingVariant = false;
            if (go)
                self->commitNow(text);
            else
                self->sync(); // cancelled: the edit is dropped, the drive's value shown again
        });
        return;
    }
    commitNow(text);
}

void ParameterField::commitNow(const QString& text)
{
    m_problem.clear(); // the model has the edit now, accepted or refused (kept as invalid)
    m_typingWarning.clear();
    m_parameters->setPending(m_name, text);
    applyStyle(); // the field keeps a refused text so the user can correct or revert it
}

QString ParameterField::warning() const
{
    if (!problem().isEmpty())
        return QString();
    if (!m_typingWarning.isEmpty())
        return m_typingWarning;
    return m_parameters->warningText(m_name);
}

QString ParameterField::problem() const
{
    if (!m_problem.isEmpty())
        return m_problem;
    const DeviceParameters::Entry* e = m_parameters->entry(m_name);
    return e->message.isEmpty() ? QString() : m_parameters->problemText(m_name);
}

void ParameterField::sync()
{
    const DeviceParameters::Entry* e = m_parameters->entry(m_name);
    const ParameterMeta& meta = *e->meta;
    const ValueContext context = this->context();
    const ValueSpec& spec = meta.specFor(context);
    m_syncing = true;
    m_unit->setText(spec.unit);
    m_unit->setVisible(!spec.unit.isEmpty());
    const bool pending = e->state == DeviceParameters::State::Pending ||
                         e->state == DeviceParameters::State::Invalid ||
                         (e->state == DeviceParameters::State::Failed && !e->pendingText.isEmpty());
    if (m_combo) {
        // The options follow the context (the I/O functions of the current control mode).
        QVector<QPair<QString, QString>> items;
        for (const EnumOption& o : spec.options)
            items << qMakePair(o.label, QString::number(o.value));
        const QVector<quint16> shown = pending ? e->pendingRegisters : e->device.registers;
        int index = -1;
        if (!shown.isEmpty()) {
            const QString code = QString::number(qint64(ValueCodec::registersToRaw(meta, shown)));
            for (int i = 0; i < items.size() && index < 0; ++i)
                index = items[i].second == code ? i : -1;
            if (index < 0) { // a code this context does not offer: show it, marked
                items << qMakePair(tr("%1 (not valid now)").arg(anyLabel(meta, code.toLongLong())),
                                   code);
                index = int(items.size()) - 1;
            }
        }
        // A value the monitor reads many times a second keeps its list: rebuilt on a change.
        bool same = m_combo->count() == items.size();
        for (int i = 0; same && i < items.size(); ++i)
            same = m_combo->itemText(i) == items[i].first &&
                   m_combo->itemData(i).toString() == items[i].second;
        if (!same) {
            m_combo->clear();
            for (const auto& [label, code] : items)
                m_combo->addItem(label, code);
        }
        m_combo->setCurrentIndex(index);
    } else if (!m_edit->hasFocus() || !m_edit->isModified()) {
        m_problem.clear(); // the text comes from the model again, and so does its problem
        m_typingWarning.clear();
        if (pending) {
            m_edit->setText(e->pendingText);
        } else if (e->device.valid) {
            QString text = ValueCodec::format(meta, e->device, context);
            if (!spec.unit.isEmpty() && text.endsWith(QLatin1Char(' ') + spec.unit))
                text.chop(spec.unit.size() + 1);
            m_edit->setText(text);
        } else {
            m_edit->clear();
        }
        m_edit->setPlaceholderText(e->device.valid ? QString() : tr("not read"));
    }
    m_syncing = false;
    QString tip =
        QStringLiteral("<b>%1</b> (%2)").arg(meta.label.toHtmlEscaped(), meta.addressText());
    if (!meta.help.isEmpty())
        tip += QStringLiteral("<br>") + meta.help.toHtmlEscaped();
    if (meta.isWritable())
        tip += QStringLiteral("<br>") +
               tr("Allowed: %1").arg(ValueCodec::allowedText(meta, context).toHtmlEscaped());
    if (e->device.valid)
        tip += QStringLiteral("<br>") +
               tr("On the drive: %1")
                   .arg(ValueCodec::format(meta, e->device, context).toHtmlEscaped());
    if (!e->message.isEmpty())
        tip += QStringLiteral("<br><span style='color:#b01c1c'>%1</span>")
                   .arg(m_parameters->problemText(m_name).toHtmlEscaped());
    if (editor()->toolTip() != tip)
        editor()->setToolTip(tip);
    applyStyle();
}

void ParameterField::applyStyle()
{
    const DeviceParameters::Entry* e = m_parameters->entry(m_name);
    QString style;
    const QString problem = this->problem();
    if (!problem.isEmpty() || e->state == DeviceParameters::State::Failed ||
        e->state == DeviceParameters::State::Invalid)
        style = QStringLiteral("border: 2px solid #c62828; background: #fdecea;");
    else if (e->state == DeviceParameters::State::Pending)
        style =
            QStringLiteral("border: 2px solid #ef8f00; background: #fff4de; font-weight: bold;");
    else if (e->state == DeviceParameters::State::Writing)
        style = QStringLiteral("border: 2px solid #1565c0;");
    if (editor()->styleSheet() != style)
        editor()->setStyleSheet(style);
    editor()->setAccessibleDescription(problem);
    // In words at the field, not only in a tooltip.
    // An allowed value outside the recommended range: said at the field too, in amber.
    const QString warning = this->warning();
    const QString message = problem.isEmpty() ? warning
                            : e->state == DeviceParameters::State::Invalid || !m_problem.isEmpty()
                                ? tr("Not accepted: %1").arg(problem)
                                : problem;
    const QString messageStyle = problem.isEmpty() && !warning.isEmpty()
                                     ? QStringLiteral("color: #a05000;")
                                     : QStringLiteral("color: #b01c1c;");
    if (m_message->styleSheet() != messageStyle)
        m_message->setStyleSheet(messageStyle);
    if (problem.isEmpty() && !warning.isEmpty())
        editor()->setAccessibleDescription(warning);
    const bool changed = m_message->text() != message;
    if (changed)
        m_message->setText(message);
    m_message->setVisible(!message.isEmpty() && !m_messageOutside);
    if (!m_problem.isEmpty())
        editor()->setToolTip(m_problem);
    if (changed)
        emit messageChanged();
}

QString ParameterField::messageText() const
{
    return m_message->text();
}

void ParameterField::setMessageOutside(bool outside)
{
    m_messageOutside = outside;
    m_message->setVisible(!m_message->text().isEmpty() && !outside);
}

} // namespace opentop
