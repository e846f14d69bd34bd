#include "ui/eol/StationLogin.h"

#include "model/access/StationAccess.h"
#include "model/io/DisplayText.h"
#include "model/io/SystemUser.h"
#include "model/station/EolStation.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStackedWidget>

namespace opentop {

namespace {

QWidget* row(QWidget* parent, std::initializer_list<QWidget*> widgets)
{
    auto* page = new QWidget(parent);
    auto* layout = new QHBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addStretch(1); // the label beside its field, at the right of the top row
    for (QWidget* w : widgets)
        layout->addWidget(w);
    return page;
}

} // namespace

StationLogin::StationLogin(EolStation* station, QWidget* parent)
    : QWidget(parent)
    , m_station(station)
{
    m_pages = new QStackedWidget(this);
    // Unmanaged: the operator's name as free text, as before users existed.
    m_operator = new QLineEdit(SystemUser::loginName(), this);
    m_operator->setPlaceholderText(tr("operator"));
    m_operator->setMaximumWidth(180);
    m_pages->addWidget(row(this, {new QLabel(tr("Operator:"), this), m_operator}));
    // Managed, nobody logged in.
    m_user = new QLineEdit(this);
    m_user->setObjectName(QStringLiteral("loginUser"));
    m_user->setPlaceholderText(tr("user name"));
    m_user->setMaximumWidth(160);
    m_password = new QLineEdit(this);
    m_password->setObjectName(QStringLiteral("loginPassword"));
    m_password->setEchoMode(QLineEdit::Password);
    m_password->setPlaceholderText(tr("password"));
    m_password->setMaximumWidth(160);
    m_login = new QPushButton(tr("Log in"), this);
    m_pages->addWidget(row(this, {new QLabel(tr("Log in:"), this), m_user, m_password, m_login}));
    setTabOrder(m_user, m_password); // a badge types name<Tab>password<Enter>
    // Managed, a user logged in.
    m_who = new QLabel(this);
    m_who->setObjectName(QStringLiteral("loggedInUser"));
    m_logout = new QPushButton(tr("Log out"), this);
    m_pages->addWidget(row(this, {m_who, m_logout}));
    for (QPushButton* b : {m_login, m_logout})
        b->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_pages);

    m_notice = new QLabel(parent);
    m_notice->setObjectName(QStringLiteral("accessNotice"));
    m_notice->setWordWrap(true);
    m_notice->setTextFormat(Qt::PlainText); // the recipe's product, a refusal quoting a name
    m_notice->hide();

    connect(m_operator, &QLineEdit::textChanged, m_station, &EolStation::setOperatorName);
    m_station->setOperatorName(m_operator->text());
    connect(m_user, &QLineEdit::returnPressed, m_password, [this] { m_password->setFocus(); });
    connect(m_password, &QLineEdit::returnPressed, this, &StationLogin::logIn);
    connect(m_login, &QPushButton::clicked, this, &StationLogin::logIn);
    connect(m_logout, &QPushButton::clicked, this, [this] { m_station->access()->logout(); });
    connect(m_station->access(), &StationAccess::changed, this, &StationLogin::refresh);
    refresh();
}

bool StationLogin::needsLogin() const
{
    return m_station->access()->isManaged() && !m_station->access()->user();
}

void StationLogin::focusUser()
{
    m_user->setFocus();
    m_user->selectAll();
}

void StationLogin::logIn()
{
    const Identity who{m_user->text().trimmed(), m_password->text()};
    m_password->clear(); // never kept on the screen
    if (who.name.isEmpty()) {
        focusUser();
        return;
    }
    m_login->setEnabled(false);
    m_station->access()->login(who, this, [this](const AccessDecision& d) {
        m_login->setEnabled(true);
        if (!d.allowed) {
            m_notice->setText(tr("Not logged in: %1").arg(DisplayText::escapedLines(d.message)));
            m_notice->setStyleSheet(QStringLiteral(
                "QLabel { background: #b3261e; color: white; padding: 4px; border-radius: 4px; "
                "}"));
            m_notice->show();
            focusUser();
            return;
        }
        m_user->clear();
        refresh();
        emit loggedIn();
    });
}

void StationLogin::refresh()
{
    const StationAccess* access = m_station->access();
    const bool managed = access->isManaged();
    const auto& user = access->user();
    m_pages->setCurrentIndex(!managed ? 0 : user ? 2 : 1);
    if (user)
        m_who->setText(tr("Logged in: <b>%1</b> (%2)")
                           .arg(DisplayText::escaped(user->displayName).toHtmlEscaped(),
                                AccessPolicy::roleText(user->role)));
    QString text;
    QString colour = QStringLiteral("#ffe08a; color: black");
    if (access->state() == StationAccess::State::Unmanaged) {
        text = tr("No users set up: anyone can run, edit and leave; set up users with "
                  "opentop-cli eol user add");
    } else if (managed && m_station->hasRecipe() && access->approvalKnown() &&
               !access->approval()) {
        text =
            RecipeApprovals::draftText(m_station->recipe().product, m_station->recipe().revision);
        colour = QStringLiteral("#b3261e; color: white");
    } else if (managed && m_station->hasRecipe() && access->approval()) {
        m_notice->hide();
        return;
    }
    m_notice->setText(DisplayText::escapedLines(text)); // may name the recipe
    m_notice->setStyleSheet(
        QStringLiteral("QLabel { background: %1; padding: 4px; border-radius: 4px; }").arg(colour));
    m_notice->setVisible(!text.isEmpty());
}

} // namespace opentop
