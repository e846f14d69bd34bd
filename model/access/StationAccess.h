#pragma once

#include "model/access/AccessCheck.h"
#include "model/access/RecipeApprovals.h"

#include <QObject>
#include <QPointer>
#include <functional>
#include <optional>

namespace opentop {

class ResultWriter;

// The people of one station as the operator screen sees them: whether the line has users
// (managed), who is logged in, and whether the loaded recipe's checksum is approved. Every
// question goes to AccessCheck on the results database's own thread (ResultWriter::run), so the
// screen never waits for the database; answers come back later on the caller's thread.
// EolStation asks this before each unit; the screen's pages ask it before leaving production
// mode or opening a recipe, so no page decides for itself.
class StationAccess : public QObject
{
    Q_OBJECT
public:
    enum class State
    {
        Unknown,   // the database has not answered yet: nothing is allowed
        Unmanaged, // no users: everything is allowed, as before users existed
        Managed
    };
    using Done = std::function<void(const AccessDecision&)>;

    StationAccess(ResultWriter* writer, QObject* parent = nullptr);

    void setStation(const QString& station) { m_station = station; }
    // Asks again whether the station is managed and for the approval of `checksum` (after the
    // database opened, a recipe was loaded or a unit ended); changed() answers.
    void refresh(const QString& checksum);
    State state() const { return m_state; }
    bool isManaged() const { return m_state == State::Managed; }
    // Managed, or not known now (the database out of reach) on a station that was managed the
    // last time it knew: a privilege is asked for then, never given away by an outage.
    bool mayBeManaged() const;
    const std::optional<StationUser>& user() const { return m_user; }
    // The approval of the checksum last refreshed (none: a draft, or not known yet).
    const std::optional<RecipeApproval>& approval() const { return m_approval; }
    bool approvalKnown() const { return m_approvalKnown; }

    // A login; the user stays logged in until logout() or another login.
    void login(const Identity& who, QObject* context, Done done);
    void logout();
    // A privilege asked for with an identity (a dialog), audited; the logged-in user is not
    // changed.
    void authorize(Privilege privilege, const Identity& who, const QString& what, QObject* context,
                   Done done);
    void approve(const Identity& who, const QString& recipeName, const QString& revision,
                 const QString& checksum, QObject* context, Done done);
    // A line for the audit trail, as the logged-in user.
    void audit(const QString& action, const QString& detail);

    // Why a unit of this recipe may not start now (empty: it may).
    QString runRefusal(const QString& recipeName, const QString& revision) const;
    // The name each record carries: the logged-in user when managed.
    QString operatorName() const;

signals:
    void changed();

private:
    ResultWriter* m_writer;
    QString m_station;
    State m_state = State::Unknown;
    std::optional<StationUser> m_user;
    QString m_checksum;
    std::optional<RecipeApproval> m_approval;
    bool m_approvalKnown = false;
    QString m_error;
};

} // namespace opentop
