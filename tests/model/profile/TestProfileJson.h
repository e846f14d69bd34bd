#pragma once

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

// A small, valid profile used by loader and codec tests; tests mutate copies of it.
inline QJsonObject testProfileJson()
{
    const char* text = R"JSON({
  "schema": 1, "family": "tdev", "name": "Test drive",
  "serial": {"baud": 19200, "parity": "N", "stopBits": 1, "bauds": [9600, 19200]},
  "limits": {"maxReadRegisters": 17, "maxWriteRegisters": 17, "minSlave": 1, "maxSlave": 247,
             "broadcast": true, "groups": false},
  "variants": [{"id": "t200", "model": "T200", "label": "T200"},
               {"id": "t400", "model": "T400", "label": "T400"}],
  "identify": {"function": 4, "address": "0x0007", "count": 5, "name": "info.name",
               "version": "info.version", "nameMatch": "^TD"},
  "groups": [{"id": "main", "label": "Main"}, {"id": "info", "label": "Info"}],
  "codeTables": {"alarm": {"label": "Alarms", "entries": [
      {"code": 1, "panel": "AL001", "name": "Overvoltage", "reset": "power"},
      {"code": 3, "panel": "AL003", "name": "Overcurrent", "reset": "alarm-reset"}]}},
  "parameters": [
    {"name": "speed", "label": "Speed", "group": "main", "address": "0xCA03", "read": 3,
     "write": 6, "type": "u16", "kind": "setting", "unit": "r/min",
     "allowed": [{"min": 0, "max": 0}, {"min": 250, "max": 3000}], "default": 1000,
     "when": [{"variant": "t400", "allowed": [{"min": 0, "max": 0}, {"min": 300, "max": 3000}]}]},
    {"name": "accel", "label": "Acceleration", "group": "main", "address": "0x1303", "read": 3,
     "write": 6, "type": "u16", "kind": "setting", "scale": 0.1, "unit": "s",
     "allowed": [{"min": 0.5, "max": 30.0}], "default": 0.5},
    {"name": "decel", "label": "Deceleration", "group": "main", "address": "0x4503", "read": 3,
     "write": 6, "type": "u16", "kind": "setting", "scale": 0.1, "unit": "s",
     "allowed": [{"min": 0.5, "max": 0.5}, {"min": 2.0, "max": 30.0}], "default": 0.5},
    {"name": "direction", "label": "Direction", "group": "main", "address": "0x0313", "read": 3,
     "write": 6, "type": "u16", "kind": "setting",
     "enum": [{"value": 0, "label": "CW"}, {"value": 1, "label": "CCW"}], "default": 0},
    {"name": "mode", "label": "Control mode", "group": "main", "address": "0x2015", "read": 3,
     "write": 6, "type": "u16", "kind": "setting",
     "enum": [{"value": 0, "label": "Mode1"}, {"value": 1, "label": "Mode2"}], "default": 1},
    {"name": "io.x0", "label": "X0 function", "group": "main", "address": "0x2101", "read": 3,
     "write": 6, "type": "u16", "kind": "setting", "default": 17,
     "enum": [{"value": 16, "label": "Not used"}, {"value": 17, "label": "CW/STOP"}],
     "when": [{"param": "mode", "equals": 0,
               "enum": [{"value": 0, "label": "Not used"}, {"value": 1, "label": "RUN/STOP"}],
               "default": 1}]},
    {"name": "group", "label": "Group", "group": "main", "address": "0x00F5", "read": 3,
     "write": 6, "type": "u16", "kind": "setting", "allowed": [{"min": 1, "max": 247}],
     "enum": [{"value": 65535, "label": "Disabled"}], "default": "0xFFFF"},
    {"name": "ro0", "label": "Correction", "group": "main", "address": "0x0421", "read": 3,
     "write": 6, "type": "s16", "kind": "setting", "unit": "r/min",
     "allowed": [{"min": -100, "max": 100}], "default": 0},
    {"name": "reduction", "label": "Reduction", "group": "main", "address": "0x0403", "read": 3,
     "write": 16, "type": "u32", "kind": "setting", "scale": 0.01,
     "allowed": [{"min": 1.0, "max": 9999.99}], "default": 1.0},
    {"name": "pid.p", "label": "P", "group": "main", "address": "0x0090", "read": 3,
     "write": 16, "type": "f32", "kind": "setting", "allowed": [{"min": 0, "max": 1}]},
    {"name": "info.name", "label": "Name", "group": "info", "address": "0x0007", "read": 4,
     "type": "string", "count": 4, "kind": "info"},
    {"name": "info.version", "label": "Version", "group": "info", "address": "0x000B",
     "read": 4, "type": "u16", "kind": "info"},
    {"name": "status", "label": "Status", "group": "info", "address": "0x0065", "read": 4,
     "type": "bits", "count": 2, "kind": "status",
     "bits": [{"bit": 1, "name": "running", "label": "Running"},
              {"bit": 8, "width": 3, "name": "spno", "label": "SPno"}]},
    {"name": "alarm.record1", "label": "Alarm 1", "group": "info", "address": "0x1C01",
     "read": 4, "type": "u16", "kind": "record", "codeTable": "alarm"},
    {"name": "start", "label": "Start/stop", "group": "main", "address": "0x2003", "write": 6,
     "type": "u16", "kind": "command", "safety": "motion",
     "enum": [{"value": 0, "label": "STOP"}, {"value": 1, "label": "START"}]}
  ]
})JSON";
    return QJsonDocument::fromJson(QByteArray(text)).object();
}

inline QByteArray toJson(const QJsonObject& o)
{
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}
