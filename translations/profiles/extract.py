#!/usr/bin/env python3
"""Flat key -> English text of every translatable text of a device profile (issue 13).
Keys are stable names, never list positions, except a parameter's `when` entries (wN)."""
import json, sys

def texts(profile):
    out = {}
    def put(key, value):
        if isinstance(value, str) and value.strip():
            out[key] = value
    put('name', profile.get('name'))
    put('serial.formatHelp', profile.get('serial', {}).get('formatHelp'))
    for v in profile.get('variants', []):
        put(f"variants.{v['id']}.label", v.get('label'))
    for g in profile.get('groups', []):
        put(f"groups.{g['id']}.label", g.get('label'))
        put(f"groups.{g['id']}.help", g.get('help'))
    for tid, t in profile.get('codeTables', {}).items():
        put(f"codeTables.{tid}.label", t.get('label'))
        for e in t.get('entries', []):
            for f in ('name', 'resetText', 'cause', 'remedy'):
                put(f"codeTables.{tid}.{e['code']}.{f}", e.get(f))
    for e in profile.get('statusLed', []):
        for f in ('label', 'meaning', 'blink'):
            put(f"statusLed.{e['light']}.{f}", e.get(f))
    for p in profile.get('parameters', []):
        n = p['name']
        for f in ('label', 'help', 'unit', 'note'):
            put(f"parameters.{n}.{f}", p.get(f))
        for o in p.get('enum', []):
            put(f"parameters.{n}.enum.{o['value']}", o.get('label'))
            put(f"parameters.{n}.enum.{o['value']}.help", o.get('help'))
        for b in p.get('bits', []):
            put(f"parameters.{n}.bits.{b['name']}.label", b.get('label'))
            for i, val in enumerate(b.get('values', [])):
                put(f"parameters.{n}.bits.{b['name']}.values.{i}", val)
        for i, w in enumerate(p.get('when', [])):
            for f in ('unit', 'note'):
                put(f"parameters.{n}.w{i}.{f}", w.get(f))
            for o in w.get('enum', []):
                put(f"parameters.{n}.w{i}.enum.{o['value']}", o.get('label'))
                put(f"parameters.{n}.w{i}.enum.{o['value']}.help", o.get('help'))
    return out

if __name__ == '__main__':
    src = json.load(open(sys.argv[1], encoding='utf-8'))
    json.dump({'format': 'opentop-profile-texts', 'family': src['family'], 'texts': texts(src)},
              sys.stdout, ensure_ascii=False, indent=1)
