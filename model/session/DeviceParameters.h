#pragma once

#include "model/profile/ParamValue.h"
#include "model/profile/Profile.h"

#include <QHash>
#include <QObject>
#include <QStringList>
#include <functional>

namespace opentop {

class DeviceSession;

// One drive's parameters as an editor sees them: the value the device holds and the user's
// pending edit are kept apart (as in QGroundControl's parameter system). Device reads update
// the device value only and never overwrite or write back an edit; only write() sends, and
// only pending edits, each validated against the profile and verified by reading back.
class DeviceParameters : public QObject
{
    Q_OBJECT
public:
    enum class State
    {
        Unread,  // never read
        Clean,   // device value known, no edit
        Pending, // edited, not written
        Writing, // on its way
        Failed,  // the last write failed or read back differently (message says why)
        Invalid, // edited, refused (message says what is allowed); kept to be corrected or
                 // reverted, and nothing is written while it is
    };

    struct Entry
    {
        const ParameterMeta* meta = nullptr;
        ParamValue device;   // what the drive holds (valid once read)
        QString pendingText; // the user's edit as typed (engineering units or label)
        QVector<quint16> pendingRegisters;
        State state = State::Unread;
        QString message;     // why a write failed; why a read failed
        QString notVerified; // held here, not verified on every drive reached: which and why
    };

    explicit DeviceParameters(DeviceSession* session, QObject* parent = nullptr);

    DeviceSession* session() const { return m_session; }
    const Profile& profile() const;
    const Entry* entry(const QString& name) const;

    // Device path: reads `names` (all readable ones when empty); pending edits stay.
    void refresh(const QStringList& names, std::function<void(int failed)> done = {});

    // User path. Validates `text` against the profile with the values other parameters will
    // have once pending edits are written; returns the refusal (naming the allowed values),
    // empty when accepted. A refused text is kept as an Invalid edit. Nothing is sent.
    QString setPending(const QString& name, const QString& text);
    void revert(const QString& name);
    void revertAll();
    // Checks every edit again against what is allowed now (after the variant became known).
    void recheck();
    // Edits not yet written: pending, failed with an edit kept, or invalid.
    QStringList pendingNames(const QString& group = QString()) const;
    // Edits not yet confirmed on the drive: pending, being written, failed or invalid.
    bool hasPending() const;
    // The edits among `names` (all when empty) that are refused, in profile order.
    QStringList invalidNames(const QStringList& names = {}) const;
    // What is wrong with the invalid edits among `names`, one line each, named by label:
    // "SPno2 speed: 5000 r/min is not allowed; allowed: 0 or 250–3000 r/min".
    QStringList invalidSummary(const QStringList& names = {}) const;
    // The failed writes among `names` (all when empty), one line each, named by label.
    QStringList failedSummary(const QStringList& names = {}) const;
    // The writes among `names` (all when empty) held by the drive but not verified on every
    // drive they reached, one line each, named by label.
    QStringList notVerifiedSummary(const QStringList& names = {}) const;
    // What a write of `names` came to, for a status line: "2 values written and verified", or
    // which failed and which were not verified on every drive they reached, each saying why;
    // *problem is set when not everything was written and verified.
    QString writeResultText(const QStringList& names, int failed, bool* problem) const;
    // The warning for the value a field shows (the pending edit, else the drive's value) when it
    // is allowed but outside the profile's recommended range (ValueCodec::recommendationWarning),
    // without the parameter's name in front; empty otherwise.
    QString warningText(const QString& name) const;
    // A refusal without the parameter's own name in front, for showing at its field.
    QString problemText(const QString& name) const;
    // `message` about `name` without the name in front.
    QString withoutName(const QString& name, const QString& message) const;
    // Writes the pending edits among `names` (all when empty) in dependency order: what
    // others' allowed values depend on goes first. `done` gets the number that failed. When
    // any of them is invalid nothing at all is written and `done` gets the number invalid.
    void write(const QStringList& names, std::function<void(int failed)> done = {});

    // The device value formatted with its unit; empty before it was read.
    QString deviceText(const QString& name) const;
    // Validation text for an input field: "allowed: 0 or 250–3000 r/min".
    QString allowedText(const QString& name) const;

signals:
    void entryChanged(const QString& name);

private:
    struct WriteState;
    void writeNext(std::shared_ptr<WriteState> state);

    DeviceSession* m_session;
    QHash<QString, Entry> m_entries;
};

} // namespace opentop
