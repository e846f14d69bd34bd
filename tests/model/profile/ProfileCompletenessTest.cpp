// Completeness of the built-in profiles against the manuals, read independently of
// model/profiles/*.json. The register rows are in DbuRegisterTable.cpp (DBU manual
// 000_306a808c77939fd6.txt chapter 12) and DcRegisterTable.cpp (DC PID controller manual
// 003_e17f880ddc4c624e.txt section 1.3); this file holds the DBU code tables (chapters 11-5,
// 12-7, 12-8, 12-9, 13), the registers that must not be accessible, and the manual's worked
// value examples.
#include "model/profile/ProfileRegistry.h"
#include "model/profile/ValueCodec.h"
#include "tests/model/profile/RegisterTable.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>

namespace opentop::manualcheck {
namespace {

const Profile& dbu()
{
    const Profile* profile = ProfileRegistry::builtIn().family(QStringLiteral("dbu"));
    if (!profile)
        throw std::runtime_error("no built-in profile for family dbu");
    return *profile;
}

const Profile& dcpid()
{
    const Profile* profile = ProfileRegistry::builtIn().family(QStringLiteral("dcpid"));
    if (!profile)
        throw std::runtime_error("no built-in profile for family dcpid");
    return *profile;
}

struct CodeRow
{
    qint64 code;
    const char* panel;
    const char* reset; // "power" where the manual marks RESET x, "alarm-reset" for RESET o
    const char* led;   // MONITOR LED colour (chapter 13)
    const char* what;
};

// 12-7 and 13-1: ten alarms. Memory error 0Dh flashes blue, external interruption 0Fh purple.
const CodeRow kAlarms[] = {
    {0x01, "AL001", "power", "red", "over voltage"},
    {0x03, "AL003", "alarm-reset", "red", "over current"},
    {0x05, "AL005", "alarm-reset", "red", "over speed"},
    {0x07, "AL007", "alarm-reset", "red", "overload"},
    {0x09, "AL009", "power", "red", "abnormal start"},
    {0x0B, "AL00B", "power", "red", "Hall signal error"},
    {0x0D, "AL00D", "alarm-reset", "blue", "memory error"},
    {0x0F, "AL00F", "alarm-reset", "purple", "external interrupt"},
    {0x19, "AL019", "alarm-reset", "red", "overheat"},
    {0x21, "AL021", "alarm-reset", "red", "power supply protection"},
};

// 12-8 and 13-3: four warnings, "RESET NA": they clear themselves, no light is shown.
const CodeRow kWarnings[] = {
    {0x05, "WR005", nullptr, "", "over speed"},
    {0x07, "WR007", nullptr, "", "load rate %"},
    {0x17, "WR017", nullptr, "", "low voltage"},
    {0x19, "WR019", nullptr, "", "overheat"},
};

// 11-5 and 12-9: communication error codes in 0x007B and the exception code that goes with them.
struct CommErrorRow
{
    qint64 code;
    std::set<int> exceptions; // E0h is both 01h (function code) and 02h (data address)
};
const CommErrorRow kCommErrors[] = {
    {0xE0, {1, 2}}, {0xE1, {3}}, {0xE2, {4}}, {0xE3, {4}}, {0xE7, {4}}, {0xE8, {4}},
};

void checkCodeTable(const Profile& profile, const char* id, const CodeRow* rows, int count)
{
    const CodeTable* table = profile.codeTable(QString::fromLatin1(id));
    ASSERT_NE(table, nullptr) << "dbu profile: no code table \"" << id << "\"";
    EXPECT_EQ(int(table->entries.size()), count)
        << "dbu \"" << id << "\": chapter 13 lists " << count << " codes";
    for (int i = 0; i < count; ++i) {
        const CodeRow& row = rows[i];
        const CodeEntry* entry = table->find(row.code);
        if (!entry) {
            ADD_FAILURE() << "dbu \"" << id << "\": no entry for code " << row.code << " ("
                          << row.panel << " " << row.what << ")";
            continue;
        }
        EXPECT_EQ(entry->code, row.code);
        EXPECT_EQ(entry->panel.toStdString(), row.panel) << id << " code " << row.code;
        EXPECT_FALSE(entry->name.isEmpty()) << id << " " << row.panel << ": no name";
        if (row.reset) {
            EXPECT_EQ(entry->reset.toStdString(), row.reset)
                << id << " " << row.panel << " (" << row.what << "): reset method";
        } else {
            // "RESET NA": nothing to erase, the warning goes when its cause goes.
            EXPECT_TRUE(entry->reset == QStringLiteral("auto") ||
                        entry->reset == QStringLiteral("none"))
                << id << " " << row.panel << ": reset is \"" << entry->reset.toStdString()
                << "\", the manual says RESET NA";
        }
        EXPECT_EQ(entry->led.toStdString(), row.led) << id << " " << row.panel << ": LED colour";
    }
}

TEST(ProfileCompleteness, BothFamiliesAndDbuVariantsExist)
{
    const ProfileRegistry& registry = ProfileRegistry::builtIn();
    ASSERT_NE(registry.family(QStringLiteral("dbu")), nullptr);
    ASSERT_NE(registry.family(QStringLiteral("dcpid")), nullptr);
    // 2-2: DBU200-D (24 V, 250–3000 r/min) and DBU400-D4 (48 V, 300–3000 r/min).
    EXPECT_NE(dbu().variant(QStringLiteral("dbu200")), nullptr);
    EXPECT_NE(dbu().variant(QStringLiteral("dbu400")), nullptr);
}

TEST(ProfileCompleteness, DbuAlarmCodeTable)
{
    checkCodeTable(dbu(), "alarm", kAlarms, int(std::size(kAlarms)));
}

TEST(ProfileCompleteness, DbuWarningCodeTable)
{
    checkCodeTable(dbu(), "warning", kWarnings, int(std::size(kWarnings)));
}

TEST(ProfileCompleteness, DbuCommunicationErrorCodes)
{
    const ParameterMeta* meta = dbu().parameterAt(4, 0x007B);
    ASSERT_NE(meta, nullptr) << "dbu: no communication error register 0x007B (04)";
    ASSERT_FALSE(meta->codeTable.isEmpty()) << "dbu 0x007B: no code table";
    const CodeTable* table = dbu().codeTable(meta->codeTable);
    ASSERT_NE(table, nullptr) << "dbu 0x007B: code table " << meta->codeTable.toStdString()
                              << " does not exist";
    for (const CommErrorRow& row : kCommErrors) {
        const CodeEntry* entry = table->find(row.code);
        if (!entry) {
            ADD_FAILURE() << "dbu communication errors: no entry for E" << std::hex
                          << (row.code & 0xF) << "h (" << std::dec << row.code << ")";
            continue;
        }
        EXPECT_EQ(row.exceptions.count(entry->exceptionCode), 1u)
            << "communication error " << row.code << ": exception code " << entry->exceptionCode;
    }
}

// Registers the DC manual lists but that cannot be read or written on their own.
TEST(ProfileCompleteness, DcInaccessibleRegistersAreNotAccessible)
{
    // 1.3.3: 0x0043 "Retention, can not access": not even a reserved entry, since reserved
    // entries mark block reads over them as legal.
    for (quint8 function : {quint8(3), quint8(4), quint8(6), quint8(16)}) {
        const ParameterMeta* p = dcpid().parameterAt(function, 0x0043);
        EXPECT_EQ(p, nullptr) << "dcpid 0x0043 cannot be accessed, the profile has "
                              << p->name.toStdString() << " for function " << int(function);
    }
    // 1.3.4: 0x0054 "can not access alone" (only as the fifth register of a 0x10 from 0x0050).
    EXPECT_EQ(dcpid().parameterAt(3, 0x0054), nullptr) << "dcpid 0x0054 is not readable alone";
    EXPECT_EQ(dcpid().parameterAt(6, 0x0054), nullptr) << "dcpid 0x0054 is not writable alone";
}

// Every parameter of a profile is a register of the manual (reserved fillers excepted).
void checkNothingInvented(const Profile& profile, const std::vector<Register>& table,
                          const std::set<int>& alsoKnown)
{
    for (const ParameterMeta& p : profile.parameters) {
        bool known = alsoKnown.count(p.address) > 0;
        for (const Register& row : table)
            known = known || (p.address >= row.address && p.address < row.address + row.count);
        EXPECT_TRUE(known || p.kind == QStringLiteral("reserved"))
            << profile.family.toStdString() << ": parameter " << p.name.toStdString() << " at "
            << p.addressText().toStdString() << " is not in the manual's register map";
    }
}

TEST(ProfileCompleteness, DbuHasNoRegisterOutsideChapter12)
{
    checkNothingInvented(dbu(), dbuRegisters(), {});
}

TEST(ProfileCompleteness, DcHasNoRegisterOutsideSection13)
{
    checkNothingInvented(dcpid(), dcRegisters(), {0x0041, 0x0043, 0x0054});
}

// Chapter 10/11: 19200 bit/s 8N1 by default, seven rates, machine numbers 1–247, broadcast,
// groups, at most 17 registers a request (exception 03 "memory count is 0 or > 17").
TEST(ProfileCompleteness, DbuBusSettings)
{
    const Profile& p = dbu();
    EXPECT_EQ(p.serial.baud, 19200);
    EXPECT_EQ(p.serial.parity, 'N');
    EXPECT_EQ(p.serial.stopBits, 1);
    EXPECT_EQ(p.serial.bauds, (QVector<int>{9600, 14400, 19200, 28800, 38400, 57600, 115200}));
    EXPECT_EQ(p.minSlave, 1);
    EXPECT_EQ(p.maxSlave, 247);
    EXPECT_EQ(p.maxReadRegisters, 17);
    EXPECT_EQ(p.maxWriteRegisters, 17);
    EXPECT_TRUE(p.supportsBroadcast);
    EXPECT_TRUE(p.supportsGroups);
}

// DC manual 1.1: serial control defaults to 9600 bit/s, 8 data bits, even parity, 1 stop bit.
TEST(ProfileCompleteness, DcBusSettings)
{
    EXPECT_EQ(dcpid().serial.baud, 9600);
    EXPECT_EQ(dcpid().serial.parity, 'E');
    EXPECT_EQ(dcpid().serial.stopBits, 1);
}

// 12-10 (errata DBU-7): 0x0417 holds whole distance units, 0–99999 = 0000 0000h–0001 869Fh,
// high word first like the function 10h example; chapter 7's 0–5999.9 is not what it holds.
TEST(ProfileCompleteness, DbuDistanceForTheTimeDisplay)
{
    const ParameterMeta* distance = dbu().parameterAt(3, 0x0417);
    ASSERT_NE(distance, nullptr);
    EXPECT_EQ(distance->name, QStringLiteral("unit.distance"));
    EXPECT_DOUBLE_EQ(distance->spec.scale, 1.0);
    EXPECT_EQ(distance->writeFunction, 16);
    ValueCodec::Encoded e = ValueCodec::encodeNumber(*distance, 99999);
    ASSERT_TRUE(e.ok) << e.error.toStdString();
    EXPECT_EQ(e.registers, (QVector<quint16>{0x0001, 0x869F}));
    EXPECT_DOUBLE_EQ(ValueCodec::decode(*distance, {0x0001, 0x869F}).number, 99999);
    EXPECT_FALSE(ValueCodec::encodeNumber(*distance, 100000).ok);
    EXPECT_FALSE(ValueCodec::encodeNumber(*distance, 5999.9).ok); // no tenths
    EXPECT_TRUE(ValueCodec::encodeNumber(*distance, 6000).ok);    // above chapter 7's 5999.9
}

// 12-11: 0x0065 is read as two registers, high word first (bits 31–16 unused, in 0x0065). A drive
// that keeps the bits in 0x0065 instead reads the same (errata DBU-25).
TEST(ProfileCompleteness, DbuDriverStatusReadsEitherLayout)
{
    const ParameterMeta* status = dbu().parameterAt(4, 0x0065);
    ASSERT_NE(status, nullptr);
    EXPECT_EQ(status->wordOrder, WordOrder::HighFirst);
    const auto field = [status](const QVector<quint16>& regs, const char* name) {
        const double raw = ValueCodec::decode(*status, regs).raw;
        for (const BitField& b : status->bits) {
            if (b.name == QLatin1String(name))
                return (qint64(raw) >> b.bit) & ((1 << b.width) - 1);
        }
        ADD_FAILURE() << name;
        return qint64(-1);
    };
    // Running CCW with SPno3 and the alarm on: bits 1, 2, 9, 11 = 0x0A06.
    for (const QVector<quint16>& regs :
         {QVector<quint16>{0x0000, 0x0A06}, QVector<quint16>{0x0A06, 0x0000}}) {
        EXPECT_EQ(field(regs, "running"), 1);
        EXPECT_EQ(field(regs, "direction"), 1);
        EXPECT_EQ(field(regs, "spno_bits"), 2);
        EXPECT_EQ(field(regs, "alarm"), 1);
    }
    EXPECT_EQ(field({0x0000, 0x0000}, "running"), 0);
}

// The worked values of chapter 12 through the profile and the codec.
TEST(ProfileCompleteness, DbuManualValueExamples)
{
    const Profile& p = dbu();
    ValueContext dbu200;
    dbu200.variant = QStringLiteral("dbu200");

    // 12-1 function 03: reading SPno2's speed 0xCA03 gives 03 E8 = 1000 r/min.
    const ParameterMeta* speed = p.parameterAt(3, 0xCA03);
    ASSERT_NE(speed, nullptr);
    const ParamValue v = ValueCodec::decode(*speed, {0x03E8}, dbu200);
    EXPECT_TRUE(v.valid);
    EXPECT_TRUE(v.allowed);
    EXPECT_DOUBLE_EQ(v.number, 1000);

    // 12-1 function 10: speed reduction 1.00 -> 1.00 x 100 = 100 -> 00 00 00 64.
    const ParameterMeta* reduction = p.parameterAt(3, 0x0403);
    ASSERT_NE(reduction, nullptr);
    ValueCodec::Encoded e = ValueCodec::encodeNumber(*reduction, 1.00);
    EXPECT_TRUE(e.ok) << e.error.toStdString();
    EXPECT_EQ(e.registers, (QVector<quint16>{0x0000, 0x0064}));
    EXPECT_DOUBLE_EQ(ValueCodec::decode(*reduction, {0x000F, 0x423F}).number, 9999.99);

    // 12-3 remarks: 0.5 x 10 = 5 -> 0005h; 10.00 x 100 = 1000 -> 03E8h.
    const ParameterMeta* accel = p.parameterAt(3, 0x1303);
    ASSERT_NE(accel, nullptr);
    e = ValueCodec::encodeNumber(*accel, 0.5);
    EXPECT_TRUE(e.ok) << e.error.toStdString();
    EXPECT_EQ(e.registers, (QVector<quint16>{0x0005}));
    const ParameterMeta* ratio = p.parameterAt(3, 0x0405);
    ASSERT_NE(ratio, nullptr);
    e = ValueCodec::encodeNumber(*ratio, 10.00);
    EXPECT_TRUE(e.ok) << e.error.toStdString();
    EXPECT_EQ(e.registers, (QVector<quint16>{0x03E8}));

    // 12-10 remarks: minus in two's complement, -1 -> FFFFh, -2 -> FFFEh.
    const ParameterMeta* correction = p.parameterAt(3, 0x0421);
    ASSERT_NE(correction, nullptr);
    EXPECT_DOUBLE_EQ(ValueCodec::decode(*correction, {0xFFFF}).number, -1);
    e = ValueCodec::encodeNumber(*correction, -2);
    EXPECT_TRUE(e.ok) << e.error.toStdString();
    EXPECT_EQ(e.registers, (QVector<quint16>{0xFFFE}));

    // 12-11: device name "DBU" = 44 42 55 20 20 20 20 20.
    const ParameterMeta* name = p.parameterAt(4, 0x0007);
    ASSERT_NE(name, nullptr);
    const ParamValue n = ValueCodec::decode(*name, {0x4442, 0x5520, 0x2020, 0x2020});
    EXPECT_TRUE(n.valid);
    EXPECT_EQ(n.text.trimmed(), QStringLiteral("DBU"));

    // 12-1 function 04: alarm record 1 reads 00 0B, the Hall signal error AL00B.
    const ParameterMeta* record = p.parameterAt(4, 0x1C01);
    ASSERT_NE(record, nullptr);
    const CodeTable* alarms = p.codeTable(record->codeTable);
    ASSERT_NE(alarms, nullptr);
    ASSERT_NE(alarms->find(0x0B), nullptr);
    EXPECT_EQ(alarms->find(0x0B)->panel, QStringLiteral("AL00B"));
}

// The checks above must be able to fail: each mutation of a copy of the built-in profile below
// is one mistake a profile could make, and must be reported.
int failuresOf(const std::function<void()>& check)
{
    ::testing::TestPartResultArray results;
    {
        ::testing::ScopedFakeTestPartResultReporter reporter(
            ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &results);
        check();
    }
    return results.size();
}

const Register& row(const std::vector<Register>& table, quint16 address)
{
    for (const Register& r : table) {
        if (r.address == address)
            return r;
    }
    throw std::logic_error("test table has no row for this address");
}

ParameterMeta& meta(Profile& profile, quint16 address)
{
    for (ParameterMeta& p : profile.parameters) {
        if (p.address == address && p.kind != QStringLiteral("reserved"))
            return p;
    }
    throw std::logic_error("profile copy has no parameter at this address");
}

// Replaces the allowed set (raw) in the base spec and every conditional spec.
void setAllowed(ParameterMeta& p, QVector<ValueRange> ranges, QVector<qint64> codes)
{
    QVector<ValueSpec*> specs{&p.spec};
    for (ValueCondition& c : p.conditions)
        specs << &c.spec;
    for (ValueSpec* spec : specs) {
        spec->ranges = ranges;
        spec->options.clear();
        for (qint64 code : codes)
            spec->options.push_back(
                {code, QStringLiteral("code"), QString(), QStringLiteral("code")});
    }
}

int dbuFailures(const std::function<void(Profile&)>& mutate, quint16 address)
{
    Profile copy = dbu();
    mutate(copy);
    copy.index();
    return failuresOf([&] { checkRegister(copy, row(dbuRegisters(), address)); });
}

int dcFailures(const std::function<void(Profile&)>& mutate, quint16 address)
{
    Profile copy = dcpid();
    mutate(copy);
    copy.index();
    return failuresOf([&] { checkRegister(copy, row(dcRegisters(), address)); });
}

TEST(ProfileCompletenessSelfTest, UnchangedCopiesPass)
{
    EXPECT_EQ(dbuFailures([](Profile&) {}, 0x1013), 0);
    EXPECT_EQ(dbuFailures([](Profile&) {}, 0xCA03), 0);
    EXPECT_EQ(dcFailures([](Profile&) {}, 0x0040), 0);
}

TEST(ProfileCompletenessSelfTest, MistakesInTheRegisterMapAreReported)
{
    auto drop = [](Profile& p) {
        p.parameters.erase(
            std::remove_if(p.parameters.begin(), p.parameters.end(),
                           [](const ParameterMeta& m) { return m.address == 0x1013; }),
            p.parameters.end());
    };
    EXPECT_GT(dbuFailures(drop, 0x1013), 0) << "missing parameter";
    EXPECT_GT(dbuFailures([](Profile& p) { meta(p, 0x0421).type = DataType::U16; }, 0x0421), 0)
        << "wrong type";
    EXPECT_GT(dbuFailures([](Profile& p) { meta(p, 0x1011).spec.scale = 1; }, 0x1011), 0)
        << "wrong scale";
    EXPECT_GT(dbuFailures([](Profile& p) { meta(p, 0x0403).registerCount = 1; }, 0x0403), 0)
        << "wrong count";
    EXPECT_GT(dbuFailures([](Profile& p) { meta(p, 0x0403).writeFunction = 6; }, 0x0403), 0)
        << "wrong write function";
    EXPECT_GT(dbuFailures([](Profile& p) { meta(p, 0x1C01).readFunction = 3; }, 0x1C01), 0)
        << "wrong read function";
    EXPECT_GT(dbuFailures([](Profile& p) { meta(p, 0x1C01).codeTable = QStringLiteral("warning"); },
                          0x1C01),
              0)
        << "wrong code table";
    EXPECT_GT(dbuFailures([](Profile& p) { meta(p, 0x0065).bits.clear(); }, 0x0065), 0)
        << "no bit fields";
}

TEST(ProfileCompletenessSelfTest, WrongAllowedValuesAreReported)
{
    EXPECT_GT(dbuFailures(
                  [](Profile& p) {
                      setAllowed(meta(p, 0x1013), {{50, 121}}, {});
                  },
                  0x1013),
              0)
        << "one too many";
    EXPECT_GT(dbuFailures(
                  [](Profile& p) {
                      setAllowed(meta(p, 0x1013), {{50, 100}}, {});
                  },
                  0x1013),
              0)
        << "50–100 %, the misprint";
    EXPECT_GT(dbuFailures(
                  [](Profile& p) {
                      setAllowed(meta(p, 0x1011), {{0, 300}}, {});
                  },
                  0x1011),
              0)
        << "0.0 s allowed";
    EXPECT_GT(dbuFailures(
                  [](Profile& p) {
                      setAllowed(meta(p, 0x200F), {}, {0, 1, 2, 3, 4, 5, 6, 8});
                  },
                  0x200F),
              0)
        << "SPno8 = 8, the misprint";
    EXPECT_GT(dbuFailures(
                  [](Profile& p) {
                      setAllowed(meta(p, 0x4503), {{5, 300}}, {});
                  },
                  0x4503),
              0)
        << "deceleration 0.6–1.9 s allowed";
    EXPECT_GT(dbuFailures(
                  [](Profile& p) {
                      setAllowed(meta(p, 0xCA03), {{0, 0}, {250, 3000}}, {});
                  },
                  0xCA03),
              0)
        << "DBU400 given the DBU200 speeds";
    EXPECT_GT(dbuFailures(
                  [](Profile& p) {
                      setAllowed(meta(p, 0x00F5), {{1, 247}}, {});
                  },
                  0x00F5),
              0)
        << "group FFFFh (off) missing";
    EXPECT_GT(
        dbuFailures(
            [](Profile& p) {
                setAllowed(meta(p, 0x2101), {}, {0, 1, 2, 4, 5, 6, 7, 8, 9, 0x10, 0x11, 0x12});
            },
            0x2101),
        0)
        << "IN codes of both modes at once";
    EXPECT_GT(dcFailures(
                  [](Profile& p) {
                      for (ValueCondition& c : meta(p, 0x0040).conditions)
                          c.spec.scale = 0.1;
                  },
                  0x0040),
              0)
        << "set speed scale not following the speed mode";
}

TEST(ProfileCompletenessSelfTest, ReservedAndCodeTableMistakesAreReported)
{
    EXPECT_GT(dcFailures(
                  [](Profile& p) {
                      for (ParameterMeta& m : p.parameters) {
                          if (m.address == 0x000E)
                              m.kind = QStringLiteral("info");
                      }
                  },
                  0x000E),
              0)
        << "reserved register not marked reserved";

    Profile copy = dbu();
    CodeTable& alarms = copy.codeTables[QStringLiteral("alarm")];
    for (CodeEntry& e : alarms.entries) {
        if (e.code == 0x0B)
            e.reset = QStringLiteral("alarm-reset");
    }
    EXPECT_GT(failuresOf([&] { checkCodeTable(copy, "alarm", kAlarms, int(std::size(kAlarms))); }),
              0)
        << "Hall signal error reset by alarm-reset";
    alarms.entries.removeLast();
    EXPECT_GT(failuresOf([&] { checkCodeTable(copy, "alarm", kAlarms, int(std::size(kAlarms))); }),
              0)
        << "an alarm missing";
}

} // namespace
} // namespace opentop::manualcheck
