#pragma once

#include <QSet>
#include <QStringList>
#include <QWidget>

class QLabel;
class QPushButton;

namespace opentop {

class DeviceParameters;

// A page of a drive's workspace: some of its parameters, edited through DeviceParameters.
// The base class gives every page the same bottom row — Write page, Revert, Re-read — and a
// status line; subclasses lay out their fields in contentArea() and list their parameters.
// Edits stay pending (marked) until written; device values never overwrite an edit.
class ParameterPage : public QWidget
{
    Q_OBJECT
public:
    ParameterPage(DeviceParameters* parameters, const QString& title, QWidget* parent = nullptr);

    DeviceParameters* parameters() const { return m_parameters; }
    QString title() const { return m_title; }
    // Every parameter this page shows (read on refresh, written by Write page).
    virtual QStringList parameterNames() const = 0;

    void refresh(); // reads the page's parameters; pending edits stay
    // Writes the page's pending edits, verified; with any of them not accepted, writes nothing
    // and says which and why in the status line (each field says it too).
    void writePage();
    void revertPage();
    bool busy() const { return m_busy; }
    QString statusText() const;
    // Why the page's edits must not be written as they are (e.g. terminals whose function is
    // not valid in the control mode being written); empty when they may.
    virtual QString writeBlocker() const { return QString(); }
    // Asked before the page's `pending` edits are written (after they were all accepted); false
    // writes nothing. The DC controller's page asks before setting its serial lock.
    virtual bool confirmWrite(const QStringList& pending)
    {
        Q_UNUSED(pending);
        return true;
    }

signals:
    void pendingChanged();    // the number of pending edits on this page changed
    void operationFinished(); // a refresh or write completed (for tests and the status bar)

protected:
    QWidget* contentArea() const { return m_content; }
    void setStatus(const QString& text, bool error = false);
    // Called when a parameter's device value, edit or state changed.
    virtual void parameterChanged(const QString& name) = 0;
    void showEvent(QShowEvent* event) override;

private:
    // Why the status says nothing was written, while that lasts: it follows the fields (a field
    // corrected, reverted, or the page's blocker gone), so that a refusal never outlives its
    // cause.
    enum class Refusal
    {
        None,
        Invalid, // fields not accepted
        Blocker, // writeBlocker()
    };
    void updateButtons();
    QStringList pendingOnPage() const;
    void showRefusal(Refusal refusal);
    void updateRefusal();
    Refusal m_refusal = Refusal::None;

    DeviceParameters* m_parameters;
    QString m_title;
    QWidget* m_content;
    QLabel* m_status;
    QPushButton* m_write;
    QPushButton* m_revert;
    QPushButton* m_reread;
    bool m_busy = false;
    int m_pending = 0;      // edits pending on this page, as the buttons show
    QSet<QString> m_unseen; // changed while the page was behind another tab
};

} // namespace opentop
