#pragma once

#include "model/eol/EolRun.h"
#include "model/eol/GoldenLimits.h"

#include <QCoreApplication>
#include <QObject>
#include <QPointer>
#include <functional>

namespace opentop {

class ModbusClient;
class ProfileRegistry;

// The measuring run of "recipe from a golden unit": the recipe's own steps on the golden
// drives (EolRun, nothing recorded), then GoldenLimits around what they measured. It moves
// every position's motor as its steps say; the caller names them first (motionText) and asks.
// A cancel or a lost port stops every motor as a unit run does.
class GoldenMeasure : public QObject
{
    Q_OBJECT
public:
    struct Outcome
    {
        bool ok = false;
        QString error;               // why no limits came out, in words
        UnitRecord record;           // what the golden unit measured
        GoldenLimits::Result limits; // when ok
        QStringList unconfirmedStops;
    };
    using Done = std::function<void(const Outcome&)>;

    GoldenMeasure(ModbusClient* client, const ProfileRegistry& registry, const Recipe& recipe,
                  const GoldenLimits::Margin& margin, QObject* parent = nullptr);

    // What the run does to which drive, one line per position, for the question before it.
    static QStringList motionText(const Recipe& recipe);

    void start(const EolStepRunner::Timing& timing, Done done);
    void cancel(const QString& reason = QString());
    void connectionLost(const QString& error);
    bool isRunning() const { return !m_run.isNull(); }

signals:
    void phaseChanged(int machineNumber, opentop::EolDriveRun::Phase phase, const QString& text);
    void measured(const opentop::Measurement& measurement);

private:
    ModbusClient* m_client;
    const ProfileRegistry& m_registry;
    Recipe m_recipe;
    GoldenLimits::Margin m_margin;
    QPointer<EolRun> m_run;
};

} // namespace opentop
