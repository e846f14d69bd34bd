#pragma once

#include "ui/workspace/ParameterPage.h"

#include <QHash>

namespace opentop {

class ParameterField;
struct ProfileGroup;

// The generic page of a profile group: one validated field per parameter, with its label and
// help beside it, so a page needs no code of its own. Read-only values are shown, commands are
// not (they are sent from dedicated controls, never as edits).
class GroupPage : public ParameterPage
{
    Q_OBJECT
public:
    GroupPage(DeviceParameters* parameters, const ProfileGroup& group, QWidget* parent = nullptr);

    QStringList parameterNames() const override { return m_names; }
    ParameterField* field(const QString& name) const { return m_fields.value(name); }

protected:
    void parameterChanged(const QString& name) override;

private:
    QStringList m_names;
    QHash<QString, ParameterField*> m_fields;
};

} // namespace opentop
