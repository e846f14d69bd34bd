#pragma once

#include <QPointer>
#include <QPushButton>
#include <functional>

namespace opentop {

class StationAccess;

// The recipe editor's "Approve…": the saved file's checksum approved in the results database by
// an engineer who identifies themselves (IdentityDialog over StationAccess::approve). A recipe
// edited after that has another checksum and is a draft again until approved.
class RecipeApproveButton : public QPushButton
{
    Q_OBJECT
public:
    // `savedPath`: the file the editor last saved or opened (empty: not saved yet).
    RecipeApproveButton(StationAccess* access, std::function<QString()> savedPath, QWidget* parent);

private:
    void approve();

    QPointer<StationAccess> m_access;
    std::function<QString()> m_savedPath;
};

} // namespace opentop
