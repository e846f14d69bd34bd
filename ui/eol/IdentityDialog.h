#pragma once

#include "model/access/AccessCheck.h"

#include <QDialog>
#include <functional>

class QLabel;
class QLineEdit;

namespace opentop {

class StationAccess;

// Asks who does something that needs a privilege (leaving production mode, opening or editing a
// recipe): a user name and password, checked by the station's StationAccess on the database's
// thread (so the screen never waits) and audited there. A refusal is said in the dialog, which
// stays open for another identity. On a station without users it does not show: `allowed` runs
// at once.
class IdentityDialog : public QDialog
{
    Q_OBJECT
public:
    using Allowed = std::function<void(const AccessDecision&)>;

    IdentityDialog(StationAccess* access, Privilege privilege, const QString& what,
                   QWidget* parent);

    // Opens the dialog (window-modal) when the station is managed (or may be: StationAccess::
    // mayBeManaged); runs `allowed` once someone with the privilege identified themselves.
    static void ask(StationAccess* access, Privilege privilege, const QString& what,
                    QWidget* parent, Allowed allowed);

    // What is checked instead of the privilege alone (an approval: StationAccess::approve).
    using Check = std::function<void(const Identity& who, QObject* context,
                                     std::function<void(const AccessDecision&)> done)>;
    void setCheck(Check check) { m_check = std::move(check); }

    QLineEdit* userField() const { return m_user; }
    QLineEdit* passwordField() const { return m_password; }
    QLabel* messageLabel() const { return m_message; }

signals:
    void granted(const opentop::AccessDecision& decision);

private:
    void check();

    StationAccess* m_access;
    Privilege m_privilege;
    QString m_what;
    QLineEdit* m_user;
    QLineEdit* m_password;
    QLabel* m_message;
    Check m_check;
};

} // namespace opentop
