#pragma once

#include "model/eol/Recipe.h"
#include "model/files/DriveBatchReader.h"

#include <QCoreApplication>
#include <QObject>
#include <functional>
#include <optional>

namespace opentop {

class ModbusClient;
class Profile;
class ProfileRegistry;
struct DeviceInfo;

// A recipe from a golden unit's drives on the bus, the one home of that workflow for
// `eol recipe create --drives` and the recipe editor's "New from drives": each drive's variant
// is proven first (VariantCheck: reported, probed, or stated by the person; never guessed),
// then its settings are read (DriveBatchReader), and RecipeBuilder makes the recipe, whose
// description says how each variant was known. The first drive that fails stops the rest.
class RecipeFromDrives : public QObject
{
    Q_OBJECT
public:
    struct Golden
    {
        int slave = 0;
        QString reportedVariant; // the drive's own identification names it (empty: it does not)
        QString statedVariant;   // given by the person making the recipe (--variant)
    };
    enum class Failure
    {
        None,
        Communication, // a drive not on the bus or not read
        Invalid,       // a variant not known, a value the profile does not allow
        Cancelled
    };
    struct Result
    {
        std::optional<Recipe> recipe;
        Failure failure = Failure::None;
        QStringList problems;         // one line each, for people
        QStringList variants;         // "machine number 1: dbu200, probed (…)"
        QVector<int> unknownVariants; // drives whose variant could not be known
    };
    using Done = std::function<void(const Result&)>;

    RecipeFromDrives(ModbusClient* client, const ProfileRegistry& registry,
                     DriveBatchReader::Sessions sessions, QObject* parent = nullptr);

    // The variant a drive's identification names, when its profile can tell from the name
    // (empty when the drive reports only its family, as a DBU does).
    static QString reportedVariant(const Profile& profile, const DeviceInfo& info);

    void start(const QVector<Golden>& drives, const QString& product, const QString& revision,
               const QString& operatorName, Done done);
    void cancel();

signals:
    void driveStarted(int slave, int index, int total);
    void driveRead(const opentop::DriveBatchReader::Drive& drive);

private:
    ModbusClient* m_client;
    const ProfileRegistry& m_registry;
    DriveBatchReader* m_reader;
    QStringList m_variants;
    QStringList m_variantProblems;
    bool m_cancelled = false;
};

} // namespace opentop
