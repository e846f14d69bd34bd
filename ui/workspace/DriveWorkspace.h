#pragma once

#include "model/session/DeviceParameters.h"

#include <QHash>
#include <QPointer>
#include <QWidget>
#include <functional>

class QLabel;
class QPushButton;
class QTabWidget;

namespace opentop {

class ParameterPage;
struct ProfileGroup;

// A drive's pages: one per profile group with settings, generated from the profile, or the
// specialised editor a group names (docs/profile-format.md, groups[].editor). Above them the
// drive's identity; below, Write all pending / Revert all / Re-read all.
class DriveWorkspace : public QWidget
{
    Q_OBJECT
public:
    using EditorFactory = std::function<ParameterPage*(DeviceParameters*, QWidget*)>;
    // Specialised editors by id; registered once at start-up (see EditorRegistry).
    static void registerEditor(const QString& id, EditorFactory factory);

    explicit DriveWorkspace(QWidget* parent = nullptr);

    // Shows `parameters` (nullptr: nothing selected). `title` is the drive's identity line.
    void setDrive(DeviceParameters* parameters, const QString& title);
    // The identity line of the drive shown (e.g. once its variant is known).
    void setTitle(const QString& title);
    QString titleText() const;
    DeviceParameters* drive() const { return m_parameters; }
    QTabWidget* tabs() const { return m_tabs; }
    ParameterPage* page(const QString& title) const;
    void refreshAll();
    void writeAll();

signals:
    void operationFinished();

private:
    void updateButtons();
    // "Nothing was written" for edits not accepted or a page's blocker follows the edits: it
    // goes (or says what is left) once its cause is gone.
    void updateRefusal();
    // `problem`: red (a write failed or was not verified on every drive it reached).
    void setStatus(const QString& text, bool problem = false);
    bool m_refused = false;

    static QHash<QString, EditorFactory>& editors();

    QPointer<DeviceParameters> m_parameters; // its drive may leave the bus list meanwhile
    QLabel* m_title;
    QTabWidget* m_tabs;
    QLabel* m_status;
    QPushButton* m_writeAll;
    QPushButton* m_revertAll;
    QPushButton* m_rereadAll;
};

} // namespace opentop
