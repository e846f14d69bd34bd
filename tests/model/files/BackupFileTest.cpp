// Backup files: what is written, that it reads back identically, and every reason a file is
// refused (not JSON, not ours, a newer version, changed after writing, unknown drives or
// parameters, wrong register counts, values the profile does not allow).
#include "model/files/BackupFile.h"
#include "model/files/Comparer.h"
#include "tests/model/files/BackupTestSupport.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTimeZone>

using namespace opentop;
using namespace opentop::test;

namespace {

class BackupFileTest : public SimBusFixture
{
protected:
    void SetUp() override
    {
        SimBusFixture::SetUp();
        const BackupReader::Result dbu = backup(1);
        const BackupReader::Result dc = backup(7);
        ASSERT_TRUE(dbu.ok) << qPrintable(dbu.failures.join(QLatin1Char('\n')) +
                                          dbu.disallowed.join(QLatin1Char('\n')));
        ASSERT_TRUE(dc.ok) << qPrintable(dc.failures.join(QLatin1Char('\n')) +
                                         dc.disallowed.join(QLatin1Char('\n')));
        file.tool = BackupFile::toolName();
        file.created = QDateTime(QDate(2024, 5, 1), QTime(10, 0), QTimeZone::utc());
        file.connection = BackupFile::connectionOf(client->settings());
        file.devices << dbu.device << dc.device;
    }

    const ProfileRegistry& registry() const { return ProfileRegistry::builtIn(); }

    QJsonObject root() const { return QJsonDocument::fromJson(file.toJson(registry())).object(); }

    // The document with a correct checksum for whatever it now holds: what a tool that
    // "fixes up" a file after editing it would produce.
    static QByteArray resigned(QJsonObject document)
    {
        document.remove(QStringLiteral("checksum"));
        document.insert(QStringLiteral("checksum"), BackupFile::checksumOf(document));
        return QJsonDocument(document).toJson();
    }

    // Sets parameter `name` of device `index` to `registers` (and `value`, unless null).
    static QJsonObject edited(QJsonObject document, int index, const QString& name,
                              const QJsonArray& registers, const QJsonValue& value)
    {
        QJsonArray devices = document.value(QStringLiteral("devices")).toArray();
        QJsonObject device = devices.at(index).toObject();
        QJsonArray parameters = device.value(QStringLiteral("parameters")).toArray();
        for (int i = 0; i < parameters.size(); ++i) {
            QJsonObject p = parameters.at(i).toObject();
            if (p.value(QStringLiteral("name")).toString() != name)
                continue;
            p.insert(QStringLiteral("registers"), registers);
            if (!value.isNull())
                p.insert(QStringLiteral("value"), value);
            parameters[i] = p;
        }
        device.insert(QStringLiteral("parameters"), parameters);
        devices[index] = device;
        document.insert(QStringLiteral("devices"), devices);
        return document;
    }

    QString refusal(const QByteArray& data) const
    {
        QString error;
        EXPECT_FALSE(BackupFile::fromJson(data, registry(), &error)) << "accepted";
        return error;
    }

    BackupFile file;
};

} // namespace

TEST_F(BackupFileTest, RoundTripKeepsEveryDriveAndSetting)
{
    const QByteArray text = file.toJson(registry());
    QString error;
    const std::optional<BackupFile> loaded = BackupFile::fromJson(text, registry(), &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    EXPECT_EQ(loaded->tool, file.tool);
    EXPECT_EQ(loaded->created, file.created);
    EXPECT_EQ(loaded->connection.sim, file.connection.sim);
    ASSERT_EQ(loaded->devices.size(), 2);
    for (int d = 0; d < 2; ++d) {
        const BackupDevice& a = file.devices.at(d);
        const BackupDevice& b = loaded->devices.at(d);
        EXPECT_EQ(b.slave, a.slave);
        EXPECT_EQ(b.family, a.family);
        EXPECT_EQ(b.variant, a.variant);
        EXPECT_EQ(b.model, a.model);
        EXPECT_EQ(b.firmware, a.firmware);
        EXPECT_EQ(b.name, a.name);
        ASSERT_EQ(b.parameters.size(), a.parameters.size());
        for (int i = 0; i < a.parameters.size(); ++i) {
            EXPECT_EQ(b.parameters.at(i).name, a.parameters.at(i).name);
            EXPECT_EQ(b.parameters.at(i).registers, a.parameters.at(i).registers);
        }
    }
    // Written again, it is the same text: nothing is lost or reinterpreted.
    EXPECT_EQ(loaded->toJson(registry()), text);
}

TEST_F(BackupFileTest, IsReadableAndDiffFriendly)
{
    const QString text = QString::fromUtf8(file.toJson(registry()));
    EXPECT_TRUE(text.startsWith(QStringLiteral("{\n  \"format\": \"opentop-backup\",\n  "
                                               "\"formatVersion\": 1,\n")))
        << qPrintable(text.left(200));
    EXPECT_TRUE(text.contains(QStringLiteral(
        "{\"name\": \"spno2.accel\", \"address\": \"0x1303\", \"registers\": [5], \"value\": 0.5, "
        "\"text\": \"0.5 s\", \"unit\": \"s\"}")))
        << qPrintable(text.left(3000));
    EXPECT_TRUE(text.contains(QStringLiteral("\"variant\": \"dbu200\"")));
    EXPECT_TRUE(text.contains(QStringLiteral("\"model\": \"DBU200-D\"")));
    EXPECT_TRUE(text.contains(QStringLiteral("\"firmware\": \"1.5\"")));
    EXPECT_TRUE(text.contains(QStringLiteral("\"text\": \"CW/STOP\"")));
    // PID coefficients: floats as the shortest decimal that gives the same float.
    EXPECT_TRUE(text.contains(QStringLiteral("\"name\": \"pid.p\", \"address\": \"0x0090\", "
                                             "\"registers\": [15820, 52429], \"value\": 0.1,")))
        << qPrintable(text.right(3000));
    // Parameters in profile order: the control mode (0x2015) before the input X0 (0x2101)
    // because the profile lists it first.
    EXPECT_LT(text.indexOf(QStringLiteral("core.control_mode")),
              text.indexOf(QStringLiteral("\"io.x0\"")));
    EXPECT_TRUE(text.endsWith(QStringLiteral("\"\n}\n")));
}

TEST_F(BackupFileTest, ChecksumCoversTheCanonicalCompactJson)
{
    QJsonObject document = root();
    const QString checksum = document.take(QStringLiteral("checksum")).toString();
    const QByteArray compact = QJsonDocument(document).toJson(QJsonDocument::Compact);
    EXPECT_EQ(checksum,
              QStringLiteral("sha256:") +
                  QString::fromLatin1(
                      QCryptographicHash::hash(compact, QCryptographicHash::Sha256).toHex()));
    // Layout is not content: the same document indented differently still loads.
    QString error;
    EXPECT_TRUE(BackupFile::fromJson(QJsonDocument(root()).toJson(QJsonDocument::Compact),
                                     registry(), &error))
        << qPrintable(error);
}

TEST_F(BackupFileTest, RefusesWhatIsNotABackup)
{
    EXPECT_TRUE(refusal("this is not json").startsWith(QStringLiteral("not a JSON file")));
    EXPECT_TRUE(refusal("[1, 2]").contains(QStringLiteral("not an object")));
    EXPECT_TRUE(refusal("{\"format\": \"something-else\"}")
                    .contains(QStringLiteral("\"format\" is \"something-else\"")));
    QJsonObject document = root();
    document.insert(QStringLiteral("formatVersion"), 2);
    EXPECT_TRUE(refusal(resigned(document))
                    .contains(QStringLiteral("written by a newer OpenTOP (format version 2)")));
    // FuzzBackupFile: a version beyond 64-bit integers was converted to one (undefined).
    document.insert(QStringLiteral("formatVersion"), 1.2e38);
    EXPECT_TRUE(
        refusal(resigned(document))
            .contains(QStringLiteral("written by a newer OpenTOP (format version 1.2e+38)")));
    document = root();
    document.remove(QStringLiteral("checksum"));
    EXPECT_TRUE(refusal(QJsonDocument(document).toJson()).contains(QStringLiteral("no checksum")));
}

TEST_F(BackupFileTest, RefusesAFileChangedAfterItWasWritten)
{
    // A value edited by hand, registers and value alike, the checksum left as it was.
    QByteArray text = file.toJson(registry());
    const QByteArray before = "\"registers\": [1000], \"value\": 1000, \"text\": \"1000 r/min\"";
    ASSERT_TRUE(text.contains(before));
    text.replace(text.indexOf(before), before.size(),
                 "\"registers\": [1500], \"value\": 1500, \"text\": \"1500 r/min\"");
    EXPECT_EQ(refusal(text),
              QStringLiteral("the file was changed after it was written (checksum mismatch)"));
    // The same edit with a checksum recomputed the wrong way (over the pretty text instead of
    // the canonical compact JSON) is just as much a mismatch.
    QJsonObject document = edited(root(), 0, QStringLiteral("spno2.speed"), {1500}, 1500);
    document.insert(
        QStringLiteral("checksum"),
        QStringLiteral("sha256:") +
            QString::fromLatin1(QCryptographicHash::hash(QJsonDocument(document).toJson(),
                                                         QCryptographicHash::Sha256)
                                    .toHex()));
    EXPECT_TRUE(
        refusal(QJsonDocument(document).toJson()).contains(QStringLiteral("checksum mismatch")));
}

TEST_F(BackupFileTest, RefusesAValueTheProfileDoesNotAllowEvenWithAValidChecksum)
{
    const QString error =
        refusal(resigned(edited(root(), 0, QStringLiteral("spno2.speed"), {5000}, 5000)));
    EXPECT_TRUE(error.contains(QStringLiteral("machine number 1")));
    EXPECT_TRUE(error.contains(QStringLiteral("spno2.speed: 5000 r/min is not allowed; allowed: 0 "
                                              "or 250–3000 r/min")))
        << qPrintable(error);
    // The value beside the registers must agree with them.
    const QString disagree =
        refusal(resigned(edited(root(), 0, QStringLiteral("spno2.speed"), {1000}, 1500)));
    EXPECT_TRUE(disagree.contains(QStringLiteral("spno2.speed: \"value\" 1500 does not match its "
                                                 "registers (1000 r/min)")))
        << qPrintable(disagree);
}

TEST_F(BackupFileTest, InputFunctionsAreCheckedAgainstTheFilesOwnControlMode)
{
    // RUN/STOP (1) is a Mode1 code; the file's drive is in Mode2.
    const QString error = refusal(resigned(edited(root(), 0, QStringLiteral("io.x0"), {1}, 1)));
    EXPECT_TRUE(error.contains(QStringLiteral("io.x0: 1 is not allowed"))) << qPrintable(error);
    // With the file's control mode Mode1 the same code is fine.
    QJsonObject document = edited(root(), 0, QStringLiteral("core.control_mode"), {0}, 0);
    const int mode1[] = {1, 2, 5, 6}; // RUN/STOP, CW/CCW, M0, M1
    for (int x = 0; x < 4; ++x)
        document = edited(document, 0, QStringLiteral("io.x%1").arg(x), {mode1[x]}, mode1[x]);
    QString accepted;
    EXPECT_TRUE(BackupFile::fromJson(resigned(document), registry(), &accepted))
        << qPrintable(accepted);
}

TEST_F(BackupFileTest, RefusesUnknownFamiliesVariantsAndParameters)
{
    auto withDevice = [this](const std::function<void(QJsonObject&)>& change) {
        QJsonObject document = root();
        QJsonArray devices = document.value(QStringLiteral("devices")).toArray();
        QJsonObject device = devices.at(0).toObject();
        change(device);
        devices[0] = device;
        document.insert(QStringLiteral("devices"), devices);
        return refusal(resigned(document));
    };
    EXPECT_TRUE(withDevice([](QJsonObject& d) {
                    d.insert(QStringLiteral("family"), QStringLiteral("vfd"));
                }).contains(QStringLiteral("unknown family \"vfd\"; known: ")));
    // A DBU's settings labelled as another family: its variant and its settings are unknown.
    EXPECT_TRUE(withDevice([](QJsonObject& d) {
                    d.insert(QStringLiteral("family"), QStringLiteral("dcpid"));
                }).contains(QStringLiteral("unknown variant \"dbu200\" of family dcpid")));
    const QString wrongFamily = withDevice([](QJsonObject& d) {
        d.insert(QStringLiteral("family"), QStringLiteral("dcpid"));
        d.insert(QStringLiteral("variant"), QJsonValue());
    });
    EXPECT_TRUE(wrongFamily.contains(QStringLiteral("unknown parameter \"spno1.direction\": the "
                                                    "dcpid profile has no such setting")))
        << qPrintable(wrongFamily);
    EXPECT_TRUE(withDevice([](QJsonObject& d) {
                    d.insert(QStringLiteral("variant"), QStringLiteral("dbu900"));
                }).contains(QStringLiteral("unknown variant \"dbu900\" of family dbu")));
    auto withParameter = [&](const QJsonObject& extra) {
        return withDevice([&](QJsonObject& d) {
            QJsonArray parameters = d.value(QStringLiteral("parameters")).toArray();
            parameters << extra;
            d.insert(QStringLiteral("parameters"), parameters);
        });
    };
    EXPECT_TRUE(withParameter({{QStringLiteral("name"), QStringLiteral("spno9.speed")},
                               {QStringLiteral("registers"), QJsonArray{1}}})
                    .contains(QStringLiteral("unknown parameter \"spno9.speed\"")));
    EXPECT_TRUE(
        withParameter({{QStringLiteral("name"), QStringLiteral("status.load")},
                       {QStringLiteral("address"), QStringLiteral("0x200D")},
                       {QStringLiteral("registers"), QJsonArray{1}},
                       {QStringLiteral("value"), 1}})
            .contains(QStringLiteral("\"status.load\" is not a setting that backups hold")));
    const QString count = refusal(
        resigned(edited(root(), 0, QStringLiteral("spno2.speed"), {0, 1000}, QJsonValue())));
    EXPECT_TRUE(count.contains(QStringLiteral("spno2.speed: 2 registers, but the parameter has 1")))
        << qPrintable(count);
}

TEST_F(BackupFileTest, SavesAtomicallyAndLoads)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("drives.json"));
    QString error;
    ASSERT_TRUE(file.save(path, registry(), &error)) << qPrintable(error);
    const std::optional<BackupFile> loaded = BackupFile::load(path, registry(), &error);
    ASSERT_TRUE(loaded) << qPrintable(error);
    EXPECT_EQ(loaded->slaves(), (QVector<int>{1, 7}));
    EXPECT_FALSE(
        BackupFile::load(dir.filePath(QStringLiteral("missing.json")), registry(), &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("cannot read"))) << qPrintable(error);
    EXPECT_FALSE(file.save(dir.filePath(QStringLiteral("no/such/dir.json")), registry(), &error));
}

TEST_F(BackupFileTest, DbuBackupNeedsFewRequests)
{
    const BackupReader::Result r = backup(1);
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(r.parameters, BackupReader::settingNames(profile("dbu")).size());
    // Block reads within the profile's read blocks, at most 17 registers each.
    EXPECT_LE(r.requests, 14);
    std::cout << "[          ] DBU backup: " << r.parameters << " settings, " << r.requests
              << " requests, " << r.elapsedMs << " ms in process" << std::endl;
}

// Issue 24: the name given to a machine travels in its backup; a broken one is refused.
TEST_F(BackupFileTest, AMachinesNameIsKeptAndCheckedAndTheCounterpartOfADriveIsFound)
{
    file.devices[0].machineName = QStringLiteral("Infeed conveyor 3");
    QString error;
    std::optional<BackupFile> back =
        BackupFile::fromJson(file.toJson(registry()), registry(), &error);
    ASSERT_TRUE(back) << qPrintable(error);
    EXPECT_EQ(back->devices[0].machineName, QStringLiteral("Infeed conveyor 3"));
    EXPECT_TRUE(back->devices[1].machineName.isEmpty());
    EXPECT_EQ(back->devices[0].title(), QStringLiteral("drive 1 (Infeed conveyor 3, DBU200-D)"));
    // Only a named machine has the key: files of unnamed ones stay as they were.
    EXPECT_FALSE(root()
                     .value(QStringLiteral("devices"))
                     .toArray()
                     .at(1)
                     .toObject()
                     .contains(QStringLiteral("machineName")));
    QJsonObject document = root();
    QJsonArray devices = document.value(QStringLiteral("devices")).toArray();
    QJsonObject first = devices.at(0).toObject();
    first.insert(QStringLiteral("machineName"), QStringLiteral("two\nlines"));
    devices[0] = first;
    document.insert(QStringLiteral("devices"), devices);
    EXPECT_TRUE(refusal(resigned(document)).contains(QStringLiteral("machineName")));

    // Beside drive 7 of the bus, the file's drive 7; beside a DC controller at another number,
    // the file's DC controller; beside a family the file lacks, its first drive.
    EXPECT_EQ(file.counterpartOf(7, QStringLiteral("dcpid")), 7);
    EXPECT_EQ(file.counterpartOf(9, QStringLiteral("dcpid")), 7);
    EXPECT_EQ(file.counterpartOf(1, QStringLiteral("dbu")), 1);
    EXPECT_EQ(file.counterpartOf(3, QStringLiteral("other")), 1);
    EXPECT_EQ(BackupFile().counterpartOf(1, QStringLiteral("dbu")), 0);
}
