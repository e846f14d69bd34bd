#include "ui/eol/IdentityDialog.h"

#include "model/access/StationAccess.h"
#include "model/io/DisplayText.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace opentop {

IdentityDialog::IdentityDialog(StationAccess* access, Privilege privilege, const QString& what,
                               QWidget* parent)
    : QDialog(parent)
    , m_access(access)
    , m_privilege(privilege)
    , m_what(what)
{
    setObjectName(QStringLiteral("identityDialog"));
    setWindowTitle(tr("Who is it?"));
    setMinimumWidth(460); // the question and a refusal wrap, never cut
    auto* intro = new QLabel(tr("To %1 this station needs the %2 role or higher. Log in with your "
                                "user name and password.")
                                 .arg(AccessPolicy::privilegeText(privilege),
                                      AccessPolicy::roleText(AccessPolicy::minimumRole(privilege))),
                             this);
    intro->setWordWrap(true);
    m_user = new QLineEdit(this);
    m_user->setObjectName(QStringLiteral("identityUser"));
    m_password = new QLineEdit(this);
    m_password->setObjectName(QStringLiteral("identityPassword"));
    m_password->setEchoMode(QLineEdit::Password);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("identityMessage"));
    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText); // a refusal may quote a user's name
    m_message->setStyleSheet(QStringLiteral("QLabel { color: #b3261e; font-weight: bold; }"));
    auto* form = new QFormLayout;
    form->addRow(tr("User name:"), m_user);
    form->addRow(tr("Password:"), m_password);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_message);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &IdentityDialog::check);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

void IdentityDialog::check()
{
    const Identity who{m_user->text().trimmed(), m_password->text()};
    m_password->clear();
    setEnabled(false);
    auto answer = [this](const AccessDecision& d) {
        setEnabled(true);
        if (!d.allowed) {
            m_message->setText(tr("Refused: %1").arg(DisplayText::escapedLines(d.message)));
            m_password->setFocus();
            return;
        }
        emit granted(d);
        accept();
    };
    if (m_check)
        m_check(who, this, answer);
    else
        m_access->authorize(m_privilege, who, m_what, this, answer);
}

void IdentityDialog::ask(StationAccess* access, Privilege privilege, const QString& what,
                         QWidget* parent, Allowed allowed)
{
    if (!access->mayBeManaged()) {
        allowed(AccessDecision{true, false, std::nullopt, QString()});
        return;
    }
    auto* dialog = new IdentityDialog(access, privilege, what, parent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &IdentityDialog::granted, parent, allowed);
    dialog->open();
}

} // namespace opentop
