#include "model/eol/RecipeFromDrives.h"

#include "model/eol/RecipeBuilder.h"
#include "model/eol/VariantCheck.h"
#include "model/profile/Profile.h"
#include "model/session/DeviceInfo.h"
#include "model/session/DeviceSession.h"

namespace opentop {

RecipeFromDrives::RecipeFromDrives(ModbusClient* client, const ProfileRegistry& registry,
                                   DriveBatchReader::Sessions sessions, QObject* parent)
    : QObject(parent)
    , m_client(client)
    , m_registry(registry)
    , m_reader(new DriveBatchReader(std::move(sessions), this))
{
    connect(m_reader, &DriveBatchReader::driveStarted, this, &RecipeFromDrives::driveStarted);
    connect(m_reader, &DriveBatchReader::driveFinished, this, &RecipeFromDrives::driveRead);
}

QString RecipeFromDrives::reportedVariant(const Profile& profile, const DeviceInfo& info)
{
    const ProfileVariant* v = profile.variant(info.variant);
    return v && !v->nameMatch.isEmpty() && info.name.startsWith(v->nameMatch) ? info.variant
                                                                              : QString();
}

void RecipeFromDrives::cancel()
{
    m_cancelled = true;
    m_reader->cancel();
}

void RecipeFromDrives::start(const QVector<Golden>& drives, const QString& product,
                             const QString& revision, const QString& operatorName, Done done)
{
    m_variants.clear();
    m_variantProblems.clear();
    m_cancelled = false;
    QHash<int, Golden> golden;
    QVector<int> slaves;
    for (const Golden& g : drives) {
        golden.insert(g.slave, g);
        slaves << g.slave;
    }
    DriveBatchReader::Options options;
    options.stopAtFailure = true;
    // The golden unit's variant becomes the recipe's: proven before its settings are read.
    options.prepare = [this, golden, operatorName](DeviceSession* session,
                                                   std::function<void(const QString&)> go) {
        const Golden g = golden.value(session->slave());
        const Profile& profile = session->profile();
        VariantDecision::Evidence evidence;
        evidence.reported = g.reportedVariant;
        evidence.asserted = g.statedVariant;
        evidence.operatorName = operatorName;
        RecipePosition position;
        position.machineNumber = g.slave;
        position.family = profile.family;
        position.variantProof = QStringLiteral("required");
        auto* check = new VariantCheck(m_client, profile, position, evidence, this);
        check->run([this, check, session, g, go](const VariantDecision::Decision& d) {
            check->deleteLater();
            if (!d.ok) {
                m_variantProblems << tr("machine number %1: %2; give its variant if you know it")
                                         .arg(g.slave)
                                         .arg(d.failure);
                go(m_variantProblems.last());
                return;
            }
            session->setVariant(d.variant);
            if (!d.variant.isEmpty())
                m_variants << tr("machine number %1: %2, %3 (%4)")
                                  .arg(g.slave)
                                  .arg(d.variant, variantSourceName(d.source), d.proof);
            go(QString());
        });
    };
    m_reader->start(
        slaves, options,
        [this, product, revision, done](const QVector<DriveBatchReader::Drive>& read) {
            Result result;
            result.variants = m_variants;
            QVector<BackupDevice> devices;
            for (const DriveBatchReader::Drive& d : read) {
                if (d.ok()) {
                    devices << d.read.device;
                    continue;
                }
                if (!d.attempted)
                    continue; // stopped by the first failure, which says why
                result.problems << d.problems();
                const bool variant = m_variantProblems.contains(d.error);
                if (variant)
                    result.unknownVariants << d.slave;
                const bool unreadable = !d.error.isEmpty() || !d.read.failures.isEmpty();
                result.failure = variant      ? Failure::Invalid
                                 : unreadable ? Failure::Communication
                                              : Failure::Invalid;
            }
            if (m_cancelled && result.failure == Failure::None && devices.size() < read.size())
                result.failure = Failure::Cancelled;
            if (result.failure == Failure::None) {
                QString error;
                result.recipe =
                    RecipeBuilder(m_registry).fromDevices(devices, product, revision, &error);
                if (!result.recipe) {
                    result.failure = Failure::Invalid;
                    result.problems << error;
                } else if (!m_variants.isEmpty()) {
                    // The recipe keeps how each variant was known when it was made.
                    result.recipe->description = tr("Made from a golden unit; variants: %1.")
                                                     .arg(m_variants.join(QStringLiteral("; ")));
                }
            }
            done(result);
        });
}

} // namespace opentop
