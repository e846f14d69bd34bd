// A family described only by its profile is simulated from the data: defaults, validation,
// read blocks, temporary settings until their store command.
#include "tests/sim/SimTestSupport.h"

#include "model/profile/ProfileLoader.h"
#include "sim/GenericSimDevice.h"

using namespace opentop;
using namespace opentop::test;

namespace {

const char* const kProfile = R"({
  "schema": 1, "family": "pump", "name": "Test pump", "vendor": "ACME", "manual": "none",
  "serial": { "baud": 9600, "parity": "N", "stopBits": 1, "bauds": [9600, 19200] },
  "limits": { "maxReadRegisters": 5, "maxWriteRegisters": 4, "minSlave": 1, "maxSlave": 247,
              "broadcast": true, "groups": false },
  "variants": [],
  "identify": { "function": 4, "address": "0x0000", "count": 1, "name": "", "version": "info.version",
                "nameMatch": "" },
  "readBlocks": [ { "function": 3, "first": "0x0100", "last": "0x0104" } ],
  "groups": [ { "id": "main", "label": "Main", "help": "" } ],
  "codeTables": {},
  "parameters": [
    { "name": "info.version", "label": "Version", "help": "", "group": "main",
      "address": "0x0000", "read": 4, "type": "u16", "kind": "info" },
    { "name": "flow.setpoint", "label": "Flow", "help": "", "group": "main", "address": "0x0100",
      "read": 3, "write": 6, "type": "u16", "kind": "setting", "scale": 0.1, "unit": "l/min",
      "allowed": [ { "min": 0, "max": 50 } ], "default": 12.5, "storeWith": "store.all" },
    { "name": "flow.mode", "label": "Mode", "help": "", "group": "main", "address": "0x0104",
      "read": 3, "write": 6, "type": "u16", "kind": "setting",
      "enum": [ { "value": 0, "label": "Off" }, { "value": 1, "label": "On" } ], "default": 1 },
    { "name": "store.all", "label": "Store", "help": "", "group": "main", "address": "0x0200",
      "write": 6, "type": "u16", "kind": "command", "safety": "store",
      "enum": [ { "value": 1, "label": "Store" } ] }
  ]
})";

} // namespace

TEST(GenericSimDevice, ServesAProfileFromDataAlone)
{
    QString error;
    const std::optional<Profile> profile =
        ProfileLoader::loadJson(QByteArray(kProfile), QStringLiteral("pump.json"), &error);
    ASSERT_TRUE(profile) << error.toStdString();
    SimFixture sim("dbu200@1");
    ASSERT_TRUE(sim.bus->addDevice(std::make_unique<GenericSimDevice>(*profile, QString(), 5)));

    EXPECT_EQ(sim.read(5, 3, 0x0100, 5).values, (QVector<quint16>{125, 0, 0, 0, 1}));
    EXPECT_EQ(sim.read(5, 3, 0x0100, 6).exception, 0x03); // over maxReadRegisters
    EXPECT_EQ(sim.read(5, 3, 0x0105).exception, 0x02);
    EXPECT_EQ(sim.write(5, 0x0100, 501).exception, 0x03); // 50.1 l/min > 50
    EXPECT_EQ(sim.write(5, 0x0104, 2).exception, 0x03);
    EXPECT_EQ(sim.write(5, quint16(0x0000), 1).exception, 0x02);
    EXPECT_EQ(sim.write(5, 0x0200, 0).exception, 0x03);
    EXPECT_EQ(sim.read(5, 1, 0x0000).exception, 0x01);

    ASSERT_TRUE(sim.write(5, 0x0100, 300).ok());
    ASSERT_TRUE(sim.write(5, 0x0104, 0).ok());
    sim.device(5)->powerCycle(sim.clock->nowMs());
    EXPECT_EQ(sim.read(5, 3, 0x0100).values.value(0), 125); // temporary until stored
    EXPECT_EQ(sim.read(5, 3, 0x0104).values.value(0), 0);   // settings persist
    ASSERT_TRUE(sim.write(5, 0x0100, 300).ok());
    ASSERT_TRUE(sim.write(5, 0x0200, 1).ok());
    sim.device(5)->powerCycle(sim.clock->nowMs());
    EXPECT_EQ(sim.read(5, 3, 0x0100).values.value(0), 300);
}
