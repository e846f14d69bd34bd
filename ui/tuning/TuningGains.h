#pragma once

#include "model/tuning/PidGains.h"

#include <QObject>
#include <functional>
#include <optional>

namespace opentop {

class TuningRunner;

// The gains the tuning page works with: those in the drive now, and those it had before the
// page wrote any, so that a reject or a stopped test can write them back. Accepting a proposal
// writes it (temporary in the drive); only store() makes it permanent.
class TuningGains : public QObject
{
    Q_OBJECT
public:
    using Then = std::function<void(bool ok)>;
    explicit TuningGains(TuningRunner* runner, QObject* parent = nullptr);

    std::optional<PidGains> present() const { return m_present; }
    std::optional<PidGains> before() const { return m_before; }
    // The page wrote gains that are not stored.
    bool isChanged() const { return m_changed; }
    bool isAccepted() const { return m_accepted; }
    bool isBusy() const { return m_busy; }

    void refresh();
    // Writes `proposal`; `before` are the gains to restore later (unless the page had already
    // changed them: then the older ones stay).
    void accept(const PidGains& proposal, const PidGains& before, const Then& then);
    // Writes back the gains before, when the page changed them.
    void restore(const QString& why, const Then& then = {});
    void store(const Then& then = {});

signals:
    void presentChanged(const opentop::PidGains& gains);
    void message(const QString& text, bool bad);
    void busyChanged();

private:
    void write(const PidGains& gains, const Then& then);
    void setBusy(bool busy);

    TuningRunner* m_runner;
    std::optional<PidGains> m_present;
    std::optional<PidGains> m_before;
    bool m_changed = false;
    bool m_accepted = false;
    bool m_busy = false;
};

} // namespace opentop
