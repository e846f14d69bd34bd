#pragma once

#include "model/tuning/TuningRunner.h"
#include "ui/tuning/TuningRun.h"

#include <QVector>
#include <QWidget>
#include <optional>

class QTabWidget;

namespace opentop {

class AutotunePanel;
class DeviceSession;
class ProposalFlow;
class StepTestPanel;
class TuningDriveSettings;
class TuningGains;
class TuningLimitsBox;
class TuningRunsView;
class TuningStatusRow;

// "Speed loop tuning" for a drive whose profile has a TuningSpec: step tests overlaid on one
// chart (each run with its gains, shown or hidden, its metrics), the relay autotune with its
// proposal and predicted step, Accept / Reject / Store of the gains. Nothing moves without the
// user's confirmation naming the drive; each test runs within the page's limits; STOP cancels
// the running test (the runner stops the motor and confirms it). Gains the page wrote and that
// are not stored go back to what the drive had when a test is cancelled or the proposal
// rejected. Everything runs through the TuningRunner's callbacks.
class TuningPage : public QWidget
{
    Q_OBJECT
public:
    // `drive` names the drive for people: "drive 7 (DCPID-20A)".
    TuningPage(DeviceSession* session, const TuningSpec& spec, const QString& drive,
               QWidget* parent = nullptr);
    ~TuningPage() override;

    TuningRunner* runner() const { return m_runner; }
    TuningGains* gains() const { return m_gains; }
    TuningRunsView* runsView() const { return m_runs; }
    AutotunePanel* autotunePanel() const { return m_autotune; }
    StepTestPanel* stepPanel() const { return m_step; }
    const QVector<TuningRun>& runs() const;
    QString phaseText() const;
    QString stopReport() const;
    bool isBusy() const;
    // Shows the step test or the autotune side.
    void showStepTest();
    void showAutotune();

public slots:
    // Asks, then runs (the Run and Autotune buttons).
    void runStep();
    void runAutotune();
    // Cancels the running test; when none runs, sends the stop command.
    void stop();
    // Cancels the running test, if any (STOP ALL: it stops every drive itself).
    void cancelTest();

protected:
    void showEvent(QShowEvent* event) override;

private:
    void readDrive();
    void settingsRead();
    void updateAutoLimits();
    QString confirmLimits(const TuningRunner::Limits& limits) const;
    void startStep(const TuningRunner::StepPlan& plan, const TuningRunner::Limits& limits);
    void startAutotune(const TuningRunner::RelayPlan& plan, const TuningRunner::Limits& limits);
    void stepDone(const TuningRunner::Result& result);
    void autotuneDone(const TuningRunner::Result& result);
    void updateState();

    DeviceSession* m_session;
    TuningSpec m_spec;
    QString m_drive;
    TuningRunner* m_runner;
    TuningGains* m_gains;
    TuningDriveSettings* m_settings;
    bool m_testing = false;
    bool m_cancelled = false; // the user stopped the running test

    TuningStatusRow* m_status;
    TuningLimitsBox* m_limits;
    QTabWidget* m_sides;
    StepTestPanel* m_step;
    AutotunePanel* m_autotune;
    TuningRunsView* m_runs;
    ProposalFlow* m_flow;
};

} // namespace opentop
