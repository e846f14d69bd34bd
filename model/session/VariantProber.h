#pragma once

#include "model/profile/VariantProbe.h"
#include "model/session/ProbeJournal.h"

#include <QObject>
#include <QVector>
#include <functional>

namespace opentop {

class DeviceSession;
class ModbusClient;
class Profile;

// Runs a profile's VariantProbe on one drive: reads the probe's setting, writes the probe value
// (read back), writes the original value back and reads it again; a refusal with the probe's
// device error proves the other variants. Nothing else is written, nothing moves. The drive
// must not be turning (the caller checks): the setting is a limit, and it is held only for the
// two frames between the probe and its restore. While it is held, ProbeJournal keeps the
// original on disk: a probe killed half-way is put right by the next probe of that drive.
class VariantProber : public QObject
{
    Q_OBJECT
public:
    struct Result
    {
        enum class Outcome
        {
            Proven,   // `variants` is what the drive is (one variant, or the probe's group)
            Unproven, // the probe did not decide; the drive holds what it held
            Disturbed // the drive may not hold its original value: `problem` says what to do
        };
        Outcome outcome = Outcome::Unproven;
        QStringList variants;
        QString proof;    // how, for the record: "Speed lower limit = 280 r/min refused (E8h …)"
        QString problem;  // why it is unproven or disturbed
        QString repaired; // an earlier probe left unfinished and put right first, in words
        bool proven() const { return outcome == Outcome::Proven; }
    };

    VariantProber(ModbusClient* client, const Profile& profile, const VariantProbe& probe,
                  int slave, QObject* parent = nullptr,
                  const QString& journal = ProbeJournal::defaultPath());

    // `done` runs once, never before run() returns.
    void run(std::function<void(const Result&)> done);

private:
    void repair(const ProbeJournal::Entry& entry); // a probe left unfinished, then start()
    void start();
    void probe();
    void accepted(bool proves); // `proves`: the drive took the probe value
    void refused(const QString& deviceError);
    void checkOriginal(const QString& proof);
    void finish(Result::Outcome outcome, const QString& proof, const QString& problem);

    const Profile& m_profile;
    VariantProbe m_probe;
    ProbeJournal m_journal;
    QString m_port;
    int m_slave = 0;
    QString m_repaired;
    DeviceSession* m_session = nullptr;
    std::function<void(const Result&)> m_done;
    QVector<quint16> m_original;
    QString m_originalText; // as written back
    QStringList m_variants;
};

} // namespace opentop
