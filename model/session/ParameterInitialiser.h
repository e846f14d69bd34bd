#pragma once

#include <QObject>
#include <QPointer>
#include <QStringList>
#include <functional>
#include <optional>

namespace opentop {

class DeviceSession;

// Parameter initialisation of a whole drive (the profile's "parameterInit" role, the DBU's
// 0x1025 = 1, manual 7-1-3 and 12-6): every setting returns to its factory default. check()
// reads what the consequences depend on and says them in words — what is reset, which
// communication settings change (so the drive may stop answering at this rate or follow no
// group), that control priority returns to the inputs — and refuses while the motor runs.
// run() checks again and sends the command; the caller re-reads the drive afterwards.
class ParameterInitialiser : public QObject
{
    Q_OBJECT
public:
    struct Plan
    {
        QString refusal;           // why it must not be sent now; empty when it may
        QStringList consequences;  // for people, one sentence each
        QStringList communication; // labels of communication settings whose value changes
        QString command;           // "Parameter initialisation = Initialise (1) (0x1025, …)"
        // What the user must do afterwards to reach and drive it again, one sentence each:
        // reconnect at the factory line settings, give bus control back.
        QStringList afterwards;
        // The profile's factory line settings to reconnect with when a communication setting
        // returns to a default that differs or could not be read; 0: the link stays as it is.
        int reconnectBaud = 0;
        char reconnectParity = 'N';
        int reconnectStopBits = 1;
        int powerOnDelayMs = 0;      // the profile's: wait this long after power-on
        bool busControlLost = false; // control priority returns to the drive's inputs
    };
    using PlanDone = std::function<void(const Plan&)>;

    struct Outcome
    {
        bool ok = false;
        bool sent = false;
        QString error;
    };
    using Done = std::function<void(const Outcome&)>;

    explicit ParameterInitialiser(DeviceSession* session, QObject* parent = nullptr);

    // Whether the profile has the role (a command parameter and the value that starts it).
    bool supported() const;
    void check(PlanDone done);
    // Checks again (the motor may have started meanwhile), then sends the command.
    void run(Done done);

private:
    QStringList readsNeeded() const;
    Plan plan(const std::function<std::optional<double>(const QString&)>& raw,
              const QStringList& unread) const;

    DeviceSession* m_session;
};

} // namespace opentop
