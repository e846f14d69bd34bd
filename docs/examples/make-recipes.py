#!/usr/bin/env python3
# Writes the example recipes of this folder in the layout OpenTOP writes, with their checksums
# (docs/recipe-format.md). RecipeFileTest checks that OpenTOP reads and writes them byte for byte.
# Run it from this folder after changing an example here.
import json, hashlib

def norm(x):
    if isinstance(x, float) and x == int(x):
        return int(x)
    if isinstance(x, dict):
        return {k: norm(v) for k, v in x.items()}
    if isinstance(x, list):
        return [norm(v) for v in x]
    return x

def sign(doc):
    doc = norm(doc)
    doc.pop("checksum", None)
    canonical = json.dumps(doc, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    doc["checksum"] = "sha256:" + hashlib.sha256(canonical.encode()).hexdigest()
    return doc

def dbu_steps(spno=2, target=1500, tol=50, timeout=5, direction="cw"):
    return [
        {"type": "priority"},
        {"type": "select", "spno": spno},
        {"type": "start", "direction": direction},
        {"type": "waitSpeed", "target": target, "tolerance": tol, "unit": "r/min", "timeout": timeout},
        {"type": "hold", "duration": 5, "limits": [
            {"parameter": "status.current_speed", "statistic": "min", "lower": target - tol, "unit": "r/min"},
            {"parameter": "status.current_speed", "statistic": "mean", "lower": target - tol / 2, "upper": target + tol / 2, "unit": "r/min"},
            {"parameter": "status.current_speed", "statistic": "max", "upper": target + tol, "unit": "r/min"},
            {"parameter": "status.load", "statistic": "max", "upper": 80, "unit": "%"}]},
        {"type": "stop", "margin": 1},
        {"type": "noAlarm"},
        {"type": "read", "parameter": "core.control_priority", "equals": "Communication priority"},
    ]

def dbu_settings(speed=1500):
    return [
        {"name": "spno2.speed", "value": speed, "unit": "r/min"},
        {"name": "spno2.accel", "value": 2, "unit": "s"},
        {"name": "spno2.decel", "value": 2.5, "unit": "s"},
        {"name": "spno2.direction", "value": "CW"},
        {"name": "alarm.load_warning", "value": 90, "unit": "%"},
    ]

one = {
    "format": "opentop-recipe", "formatVersion": 1,
    "product": "Conveyor C-200", "revision": "A",
    "description": "One DBU200 belt drive at machine number 1: runs SPno2 at 1500 r/min clockwise.",
    "positions": [{
        "machineNumber": 1, "name": "belt", "family": "dbu",
        "variants": ["dbu200"], "firmware": ["1.5"],
        "settings": dbu_settings(),
        "unitValues": [{"name": "spno3.speed", "min": 1400, "max": 1600, "unit": "r/min", "source": "csv"}],
        "steps": dbu_steps(),
    }],
}

eight = {
    "format": "opentop-recipe", "formatVersion": 1,
    "product": "Sorter S-8", "revision": "C",
    "description": "Eight DBU belt drives on machine numbers 1-8, tested together; the speed of the last one is trimmed by the operator.",
    "positions": [],
}
for n in range(1, 9):
    pos = {
        "machineNumber": n, "name": "lane %d" % n, "family": "dbu",
        "variants": ["dbu200", "dbu400"], "firmware": ["1.5"],
        "settings": dbu_settings(1200),
        "steps": dbu_steps(target=1200, tol=40, timeout=4),
    }
    if n == 8:
        pos["unitValues"] = [{"name": "spno4.speed", "min": 1000, "max": 1400, "unit": "r/min", "source": "operator"}]
    eight["positions"].append(pos)

dc = {
    "format": "opentop-recipe", "formatVersion": 1,
    "product": "Lift L-1", "revision": "B",
    "description": "A DC motor PID controller at machine number 7 in the speed loop: 300 commutations per second forward.",
    "positions": [{
        "machineNumber": 7, "name": "lift motor", "family": "dcpid",
        "firmware": ["1.0"],
        "settings": [
            {"name": "config.speed_mode", "value": "Speed loop (commutation)"},
            {"name": "config.stall_time", "value": 2, "unit": "s"},
            {"name": "config.rated_current", "value": 2.5, "unit": "A"},
            {"name": "config.max_current", "value": 5, "unit": "A"},
        ],
        "unitValues": [{"name": "config.brake_current", "min": 0.5, "max": 1.5, "unit": "A", "source": "operator"}],
        "steps": [
            {"type": "speed", "speed": 300, "unit": "1/s"},
            {"type": "waitSpeed", "target": 300, "tolerance": 30, "unit": "1/s", "timeout": 10},
            {"type": "hold", "duration": 5, "limits": [
                {"parameter": "status.commutation", "statistic": "min", "lower": 270, "unit": "1/s"},
                {"parameter": "status.commutation", "statistic": "mean", "lower": 285, "upper": 315, "unit": "1/s"},
                {"parameter": "status.commutation", "statistic": "max", "upper": 330, "unit": "1/s"},
                {"parameter": "status.current", "statistic": "max", "upper": 3, "unit": "A"},
                {"parameter": "status.pwm", "statistic": "max", "upper": 90, "unit": "%"}]},
            {"type": "stop", "deceleration": 0, "margin": 1.5},
            {"type": "read", "parameter": "status.current", "upper": 0.1, "unit": "A"},
        ],
    }],
}


ORDER = ["format", "formatVersion", "product", "revision", "description", "machineNumber",
         "name", "family", "variants", "firmware", "type", "parameter", "statistic", "spno",
         "speed", "direction", "target", "tolerance", "value", "min", "max", "lower", "upper",
         "equals", "unit", "timeout", "duration", "deceleration", "margin", "source",
         "settings", "unitValues", "steps", "limits", "positions", "checksum"]

def scalar(v):
    return json.dumps(v, ensure_ascii=False)

def keys(o):
    ks = [k for k in ORDER if k in o]
    return ks + sorted(k for k in o if k not in ks)

def flat(v):
    if isinstance(v, list):
        return all(not isinstance(x, (list, dict)) for x in v)
    if isinstance(v, dict):
        return all(flat(x) for x in v.values())
    return True

def pretty(v, indent):
    inner = " " * (indent + 2)
    f = flat(v)
    if isinstance(v, list):
        items = [("" if f else inner) + pretty(x, indent + 2) for x in v]
        if f or not items:
            return "[" + ", ".join(items) + "]"
        return "[\n" + ",\n".join(items) + "\n" + " " * indent + "]"
    if isinstance(v, dict):
        fields = [("" if f else inner) + scalar(k) + ": " + pretty(v[k], indent + 2) for k in keys(v)]
        if f:
            return "{" + ", ".join(fields) + "}"
        return "{\n" + ",\n".join(fields) + "\n" + " " * indent + "}"
    return scalar(v)


for name, doc in (("recipe-dbu200.json", one), ("recipe-eight-dbu.json", eight), ("recipe-dcpid.json", dc)):
    with open(name, "w") as f:
        f.write(pretty(sign(doc), 0) + "\n")
