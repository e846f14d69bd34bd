#include "ui/workspace/GroupPage.h"

#include "model/profile/RoleEvaluator.h"
#include "model/session/DeviceParameters.h"
#include "ui/workspace/ParameterField.h"
#include "ui/workspace/ParameterInitBox.h"

#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace opentop {

GroupPage::GroupPage(DeviceParameters* parameters, const ProfileGroup& group, QWidget* parent)
    : ParameterPage(parameters, group.label, parent)
{
    auto* outer = new QVBoxLayout(contentArea());
    outer->setContentsMargins(0, 0, 0, 0);
    if (!group.help.isEmpty()) {
        auto* help = new QLabel(group.help, contentArea());
        help->setWordWrap(true);
        outer->addWidget(help);
    }
    auto* scroll = new QScrollArea(contentArea());
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto* inner = new QWidget(scroll);
    auto* form = new QFormLayout(inner);
    form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    for (const ParameterMeta* meta : parameters->profile().parametersInGroup(group.id)) {
        if (!meta->safety.isEmpty() || !parameters->entry(meta->name))
            continue; // commands are no edits
        auto* field = new ParameterField(parameters, meta->name, inner);
        field->editor()->setMaximumWidth(field->editor()->fontMetrics().averageCharWidth() * 36);
        auto* label = new QLabel(meta->label + QLatin1Char(':'), inner);
        label->setBuddy(field->editor());
        form->addRow(label, field);
        if (!meta->help.isEmpty()) {
            auto* help = new QLabel(meta->help, inner);
            help->setWordWrap(true);
            help->setStyleSheet(QStringLiteral("color: palette(mid);"));
            form->addRow(QString(), help);
        }
        m_names << meta->name;
        m_fields.insert(meta->name, field);
    }
    // The page of the group that holds the drive's parameter initialisation offers it.
    const ParameterMeta* init =
        RoleEvaluator::parameter(parameters->profile(), QStringLiteral("parameterInit"));
    if (init && init->group == group.id && ParameterInitBox::supported(parameters))
        form->addRow(new ParameterInitBox(parameters, inner));
    scroll->setWidget(inner);
    outer->addWidget(scroll, 1);
}

void GroupPage::parameterChanged(const QString& name)
{
    if (ParameterField* f = m_fields.value(name))
        f->sync();
    // Fields whose allowed values depend on this one show the new choices.
    for (ParameterField* f : std::as_const(m_fields)) {
        if (parameters()->entry(f->parameterName())->meta->controllingParameters().contains(name))
            f->sync();
    }
}

} // namespace opentop
