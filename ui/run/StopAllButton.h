#pragma once

#include "model/run/StopAll.h"

#include <QPointer>
#include <QPushButton>
#include <functional>

class QMessageBox;

namespace opentop {

class BusDrives;

// STOP ALL: big, red and always there. One click (or Pause / Ctrl+Shift+S anywhere in the
// application, modal dialogs included: see install()) broadcasts every family's stop command and
// then confirms that each drive known in the BusDrives has stopped. Never asks first: stopping is
// always allowed. The result shows in a non-modal window that names each drive still running or not
// answering.
class StopAllButton : public QPushButton
{
    Q_OBJECT
public:
    explicit StopAllButton(BusDrives* drives, QWidget* parent = nullptr);

    // The key sequences that press STOP ALL in a window with install().
    static QList<QKeySequence> shortcuts();
    // Makes shortcuts() press the window's StopAllButton from anywhere in the application,
    // modal dialogs included (StopAllKeys).
    static void install(QWidget* window);

    void setTiming(const StopConfirmer::Timing& timing) { m_timing = timing; }
    // Drives that must be checked too though no scan found them: machine number and profile
    // family (an end-of-line recipe's positions). Asked at every press.
    using ExpectedDrives = std::function<QVector<QPair<int, QString>>()>;
    void setExpectedDrives(ExpectedDrives expected) { m_expected = std::move(expected); }
    bool isStopping() const { return m_running > 0; }
    // The result of the last stop, as shown in the result window.
    QString reportText() const { return m_reportText; }
    QString reportTitle() const { return m_reportTitle; }
    // The non-modal result window of the last stop (nullptr once closed).
    QMessageBox* resultWindow() const;

public slots:
    void stopAll();

signals:
    void started();
    void finished(const opentop::StopReport& report);

private:
    void showReport(const StopReport& report);
    // `drives` names the machines by their names too ("Machine number 1 (Infeed conveyor 3)").
    static QString describe(const StopReport& report, const BusDrives* drives = nullptr);

    BusDrives* m_drives;
    StopConfirmer::Timing m_timing;
    ExpectedDrives m_expected;
    int m_running = 0;
    QString m_reportText;
    QString m_reportTitle;
    QPointer<QMessageBox> m_result;
};

} // namespace opentop
