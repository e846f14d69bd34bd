#include "model/access/StationAccess.h"

#include "model/eol/ResultWriter.h"

#include <QSettings>
#include <memory>

namespace opentop {

namespace {
constexpr char kManagedKey[] = "eol/managed"; // this station was managed when it last knew
}

StationAccess::StationAccess(ResultWriter* writer, QObject* parent)
    : QObject(parent)
    , m_writer(writer)
{
}

void StationAccess::refresh(const QString& checksum)
{
    struct Answer
    {
        int managed = -1;
        std::optional<RecipeApproval> approval;
        QString error;
    };
    auto answer = std::make_shared<Answer>();
    const QString station = m_station;
    if (checksum != m_checksum) { // another recipe: never the last one's approval
        m_approval.reset();
        m_approvalKnown = false;
    }
    m_checksum = checksum;
    m_writer->run(
        this,
        [answer, station, checksum](ResultDatabase* db) {
            if (!db)
                return;
            answer->managed = AccessCheck(*db, station).managed(&answer->error);
            if (answer->managed > 0 && !checksum.isEmpty())
                answer->approval = RecipeApprovals(*db).current(checksum, &answer->error);
        },
        [this, answer, checksum] {
            if (checksum != m_checksum)
                return; // a later refresh answers
            m_error = answer->error;
            if (answer->managed < 0 || !answer->error.isEmpty()) {
                // The database out of reach (results go to the spool meanwhile) changes no user
                // and no approval: what was known stays.
                emit changed();
                return;
            }
            m_state = answer->managed > 0 ? State::Managed : State::Unmanaged;
            if (m_state != State::Managed)
                m_user.reset(); // users were removed meanwhile: nobody to be logged in as
            QSettings().setValue(QLatin1String(kManagedKey), m_state == State::Managed);
            m_approval = answer->approval;
            m_approvalKnown = true;
            emit changed();
        });
}

void StationAccess::login(const Identity& who, QObject* context, Done done)
{
    auto decision = std::make_shared<AccessDecision>();
    const QString station = m_station;
    m_writer->run(
        this,
        [decision, station, who](ResultDatabase* db) {
            if (db)
                *decision = AccessCheck(*db, station).login(who);
            else
                decision->message = tr("the results database is not open");
        },
        [this, decision, context = QPointer<QObject>(context), done] {
            if (decision->allowed && decision->user)
                m_user = decision->user;
            emit changed();
            if (context && done)
                done(*decision);
        });
}

void StationAccess::logout()
{
    if (!m_user)
        return;
    audit(QStringLiteral("logout"), QString());
    m_user.reset();
    emit changed();
}

void StationAccess::authorize(Privilege privilege, const Identity& who, const QString& what,
                              QObject* context, Done done)
{
    auto decision = std::make_shared<AccessDecision>();
    const QString station = m_station;
    m_writer->run(
        this,
        [decision, station, who, privilege, what](ResultDatabase* db) {
            if (db)
                *decision = AccessCheck(*db, station).authorize(privilege, who, what);
            else
                decision->message = tr("the results database is not open, so nobody can be "
                                       "identified");
        },
        [decision, context = QPointer<QObject>(context), done] {
            if (context && done)
                done(*decision);
        });
}

void StationAccess::approve(const Identity& who, const QString& recipeName, const QString& revision,
                            const QString& checksum, QObject* context, Done done)
{
    auto decision = std::make_shared<AccessDecision>();
    auto approval = std::make_shared<std::optional<RecipeApproval>>();
    const QString station = m_station;
    m_writer->run(
        this,
        [=](ResultDatabase* db) {
            if (db)
                *decision = AccessCheck(*db, station)
                                .approveRecipe(who, recipeName, revision, checksum, approval.get());
            else
                decision->message = tr("the results database is not open");
        },
        [this, decision, approval, checksum, context = QPointer<QObject>(context), done] {
            if (decision->allowed && checksum == m_checksum) {
                m_approval = *approval;
                m_approvalKnown = true;
                emit changed();
            }
            if (context && done)
                done(*decision);
        });
}

void StationAccess::audit(const QString& action, const QString& detail)
{
    const QString station = m_station;
    const QString user = m_user ? m_user->name : QString();
    m_writer->run(
        this,
        [station, user, action, detail](ResultDatabase* db) {
            if (db)
                AccessCheck(*db, station).audit(user, action, detail);
        },
        [] {});
}

QString StationAccess::runRefusal(const QString& recipeName, const QString& revision) const
{
    switch (m_state) {
    case State::Unmanaged:
        return QString();
    case State::Unknown:
        return m_error.isEmpty()
                   ? tr("the station's users are being read from the results database")
                   : tr("the station's users cannot be read: %1").arg(m_error);
    case State::Managed:
        break;
    }
    if (!m_user)
        return tr("nobody is logged in: log in with your user name and password (or badge)");
    if (!AccessPolicy::allows(m_user->role, Privilege::RunUnits))
        return AccessCheck::refusedText(*m_user, Privilege::RunUnits);
    if (!m_approvalKnown)
        return tr("the recipe's approval is being read from the results database");
    if (!m_approval)
        return RecipeApprovals::draftText(recipeName, revision);
    return QString();
}

bool StationAccess::mayBeManaged() const
{
    return m_state == State::Managed ||
           (m_state == State::Unknown && QSettings().value(QLatin1String(kManagedKey)).toBool());
}

QString StationAccess::operatorName() const
{
    return m_user ? m_user->name : QString();
}

} // namespace opentop
