#pragma once

#include "ui/workspace/ParameterPage.h"

#include <QHash>
#include <QVector>

class QLabel;
class QPushButton;

namespace opentop {

class ParameterField;

// Running data SPno1–SPno8 as one grid: a row per SPno, columns speed, acceleration,
// deceleration, direction and an Initialize button. SPno1's speed comes from the external VR
// and its times from the SS/SD trimmers, so that row shows the speed read-only and has no
// time registers. The allowed speed range of the drive's variant is shown above the grid, the
// fields' messages below it (in room kept for them, so that the rows never move).
class RunningDataPage : public ParameterPage
{
    Q_OBJECT
public:
    explicit RunningDataPage(DeviceParameters* parameters, QWidget* parent = nullptr);

    // All SPno settings and the SPno1 speed; the init commands are not page parameters.
    QStringList parameterNames() const override { return m_names; }

    ParameterField* field(const QString& name) const { return m_fields.value(name); }
    QPushButton* initializeButton(int spno) const;
    QString rangeText() const;
    // The manual's deceleration advice for the values as they will be written; empty if none.
    QString decelerationWarning() const;
    // The fields' messages, one line each with the setting's label, as shown under the grid.
    QString fieldMessages() const;

    // Asks for confirmation (naming what is reset to which defaults), sends spnoN.init as an
    // explicit command and reads the row again. Emits operationFinished when done.
    void initializeRow(int spno);

protected:
    void parameterChanged(const QString& name) override;
    void showEvent(QShowEvent* event) override;

private:
    void updateDecelerationWarning();
    void updateFieldMessages();

    static QString nameOf(int spno, const char* column);
    QStringList rowSettings(int spno) const;
    QString resetSummary(int spno) const;
    void finishInitialize(int spno, const QString& error);
    void updateRange();
    void setInitializing(bool on);

    QStringList m_names;
    QHash<QString, ParameterField*> m_fields;
    QVector<QPushButton*> m_init; // index spno - 1; null when the profile has no init command
    QLabel* m_range;
    QLabel* m_decelWarning = nullptr;
    QLabel* m_fieldMessages = nullptr;
    bool m_initializing = false;
};

} // namespace opentop
