#pragma once

#include "profile/ParamValue.h"
#include "profile/Profile.h"

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
    };

    struct Entry
    {
        const ParameterMeta* meta = nullptr;
        ParamValue device;   // what the drive holds (valid once read)
        QString pendingText; // the user's edit as typed (engineering units or label)
        QVector<quint16> pendingRegisters;
        State state = State::Unread;
        QString message; // why a write failed; why a read failed
    };

    explicit DeviceParameters(DeviceSession* session, QObject* parent = nullptr);

    DeviceSession* session() const { return m_session; }
    const Profile& profile() const;
    const Entry* entry(const QString& name) const;

    // Device path: reads `names` (all readable ones when empty); pending edits stay.
    void refresh(const QStringList& names, std::function<void(int failed)> done = {});

    // User path. Validates `text` against the profile with the values other parameters will
    // have once pending edits are written; returns the refusal (naming the allowed values),
    // empty when accepted. Nothing is sent.
    QString setPending(const QString& name, const QString& text);
    void revert(const QString& name);
    void revertAll();
    QStringList pendingNames(const QString& group = QString()) const;
    // Edits not yet confirmed on the drive: pending, being written, or failed.
    bool hasPending() const;
    // Writes the pending edits among `names` (all when empty) in dependency order: what
    // others' allowed values depend on goes first. `done` gets the number that failed.
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
    QStringList orderForWrite(QStringList names) const;

    DeviceSession* m_session;
    QHash<QString, Entry> m_entries;
};

} // namespace opentop
