#pragma once

#include "model/session/DeviceSession.h"
#include "model/session/ParameterInitialiser.h"

#include <QObject>
#include <QStringList>
#include <QVector>
#include <functional>
#include <optional>

namespace opentop {

// Writing a list of values to one drive by name (`opentop-cli set`): the one implementation,
// in stages a front end can ask between, each ending in a callback.
// - prepare(): every name is a writable parameter, a command only when confirmed; the values
//   the checks need are read from the drive; the values are put in dependency order (WriteOrder)
//   and each is checked (SettingCheck) against what the drive will hold once the ones before it
//   are written, the serial lock only when confirmed; warnings and the deceleration advice are
//   collected; for a parameter initialisation, its consequences and refusal.
// - checkReached(): every drive that executes this drive's writes (a group's children) allows
//   every value by its own profile and variant (ReachedDrives).
// - write(): in order, each read back and verified on the drive and every drive it reached;
//   cancel() leaves the rest unsent and says so.
// Nothing is sent before write(), and write() sends nothing when prepare() refused.
class SettingsWrite : public QObject
{
    Q_OBJECT
public:
    struct Item
    {
        QString name;
        QString text;
        const ParameterMeta* meta = nullptr;
        QVector<quint16> registers; // as validated by prepare()
        DeviceSession::Outcome outcome;
    };
    enum class Refusal
    {
        None,
        Invalid,       // a value, a name or a missing confirmation: nothing was sent
        Communication, // what the checks need could not be read: nothing was sent
    };
    struct Plan
    {
        Refusal refusal = Refusal::None;
        QStringList problems;     // why nothing may be sent, one line each
        QStringList warnings;     // allowed, but said first (recommended range, serial lock)
        QStringList advice;       // the manual's deceleration rule for the values as written
        QStringList consequences; // a parameter initialisation's, said before it is sent
    };

    SettingsWrite(DeviceSession* session, bool confirmed, QObject* parent = nullptr);

    // Adds NAME=VALUE; a name given twice is refused (which would the drive keep?) with the
    // reason, and nothing will be written.
    QString add(const QString& name, const QString& text);

    void prepare(std::function<void(const Plan&)> done);
    // Empty problems: every reached drive allows every value. `communication`: a reached drive
    // could not be read.
    void checkReached(std::function<void(const QStringList& problems, bool communication)> done);
    // `done` when every value was written or the write was cancelled.
    void write(std::function<void()> done);
    // Nothing more is sent; the value in flight and the rest are reported not written, and
    // write()'s `done` is not called any more.
    void cancel();

    const QVector<Item>& items() const { return m_items; }
    DeviceSession* session() const { return m_session; }
    bool cancelled() const { return m_cancelled; }
    // The parameter initialisation's plan when one is among the values (after prepare()), and
    // whether it was sent: its `afterwards` says what to do next.
    const std::optional<ParameterInitialiser::Plan>& initialisation() const { return m_init; }
    bool initialisationSent() const;

private:
    QStringList neededReads() const;
    void validate(Plan& plan);
    void writeFrom(int index, std::function<void()> done);

    DeviceSession* m_session;
    bool m_confirmed;
    QVector<Item> m_items;
    std::optional<ParameterInitialiser::Plan> m_init;
    bool m_cancelled = false;
    bool m_prepared = false;
    int m_current = -1; // the value being written
};

} // namespace opentop
