#pragma once

#include "model/session/DeviceParameters.h"
#include "ui/workspace/ParameterPage.h"

#include <QHash>
#include <functional>

class QFrame;
class QGridLayout;
class QLabel;
class QPushButton;

namespace opentop {

class MonitorHub;
class ParameterField;
class RunLiveState;
class StoreTracker;

// The DC controller's settings (manual 1.3.4–1.3.8): speed mode, currents, limits, stop times,
// speed loop PID, preset speed and AI1/AI2 as digital ports. Written settings act at once but
// are lost at power-off until a store command is written (errata DC-7..DC-9): each group says
// so, and after such a write a banner offers the store commands (explicit, confirmed) and the
// reload of the stored configuration until they have been stored.
class DcControllerPage : public ParameterPage
{
    Q_OBJECT
public:
    // Asked before a store or reload is sent; true to go ahead.
    using Confirm = std::function<bool(const QString& title, const QString& text)>;

    explicit DcControllerPage(DeviceParameters* parameters, QWidget* parent = nullptr);

    QStringList parameterNames() const override;
    ParameterField* field(const QString& name) const { return m_fields.value(name); }
    void setConfirm(Confirm confirm) { m_confirm = std::move(confirm); }

    // Store commands owed for settings written since ("store.config", "store.pid", ...).
    QStringList unstored() const;
    bool bannerShown() const;
    // The note shown while the controller's communication loss stop is off; empty otherwise.
    QString commLossNote() const;
    // Shows what the controller does now (output duty, speed, running or stopped) from `hub`,
    // watching the drive while the page is visible.
    void setMonitorHub(MonitorHub* hub);
    RunLiveState* liveState() const { return m_live; }
    // Asks, then writes `command` = 1 (store.config, store.pid or store.preset).
    void store(const QString& command);
    // Asks, then writes store.config = 0 and reads the configuration again.
    void reloadStoredConfiguration();

    // Asks before a write that sets the serial configuration lock (SerialLock: it can shut the
    // program out of the configuration over this line; the question says how to undo it).
    bool confirmWrite(const QStringList& pending) override;

signals:
    void storeFinished(bool ok);

protected:
    void parameterChanged(const QString& name) override;

private:
    struct Row
    {
        QString name;
        QString label;
    };
    void addGroup(QGridLayout* grid, int row, int column, const QString& title,
                  const QVector<Row>& rows, const QString& note);
    void updateBanner();
    void updateCommLossNote();
    void updatePresetRange();
    void sendStore(const QString& command, const QString& value, const QString& doneText);
    QString storedWhat(const QString& command) const;
    QString storeNote(const QString& command) const;

    QStringList m_names;
    QHash<QString, ParameterField*> m_fields;
    StoreTracker* m_tracker = nullptr;
    QFrame* m_banner;
    QLabel* m_bannerText;
    QHash<QString, QPushButton*> m_storeButtons;
    QPushButton* m_reload;
    QLabel* m_presetRange = nullptr;
    QLabel* m_commLossNote = nullptr;
    RunLiveState* m_live = nullptr;
    Confirm m_confirm;
    bool m_storing = false;
};

} // namespace opentop
