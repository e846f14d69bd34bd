#pragma once

#include <QWidget>

class QLabel;
class QLineEdit;
class QPushButton;
class QStackedWidget;

namespace opentop {

class EolStation;

// Who works at the station, on the operator screen: on a station without users the operator's
// name as free text (and an amber notice that anyone can run, edit and leave); on a managed one
// a login (user name and password: a badge scanner that types "name<Tab>password<Enter>" logs
// in), then the user's name and role with Log out. The station's StationAccess decides; this
// only asks and shows. The notice also says when the loaded recipe is a draft and who approves.
class StationLogin : public QWidget
{
    Q_OBJECT
public:
    StationLogin(EolStation* station, QWidget* parent = nullptr);

    // Shown by the operator screen under its status line (the unmanaged or draft notice).
    QLabel* notice() const { return m_notice; }
    QLineEdit* userField() const { return m_user; }
    QLineEdit* passwordField() const { return m_password; }
    QLineEdit* operatorField() const { return m_operator; }
    QPushButton* logoutButton() const { return m_logout; }
    QLabel* userLabel() const { return m_who; }
    // A managed station with nobody logged in: the keys go to the user name field.
    bool needsLogin() const;
    void focusUser();
    void refresh();

signals:
    void loggedIn(); // the serial field takes the keys next

private:
    void logIn();

    EolStation* m_station;
    QStackedWidget* m_pages;
    QLineEdit* m_operator;
    QLineEdit* m_user;
    QLineEdit* m_password;
    QPushButton* m_login;
    QLabel* m_who;
    QPushButton* m_logout;
    QLabel* m_notice;
};

} // namespace opentop
