#!/usr/bin/env python3
"""A file's own tr() helper (`QString tr(const char* text) { return
QCoreApplication::translate("CONTEXT", text); }`) must ask for the context lupdate files that
file's messages under; otherwise every translated message of the file shows in English.
Usage: check-tr-contexts.py REPO_ROOT. Exit 1 with each mismatch named."""
import glob, os, re, sys
import xml.etree.ElementTree as ET

root = sys.argv[1] if len(sys.argv) > 1 else '.'
ts = sorted(glob.glob(os.path.join(root, 'translations', 'opentop_*.ts')))
if not ts:
    sys.exit('check-tr-contexts: no translations/opentop_*.ts under ' + root)
contexts = {}
for ctx in ET.parse(ts[0]).getroot():
    name = ctx.find('name').text
    for m in ctx.findall('message'):
        if m.find('translation') is not None and m.find('translation').get('type') in (
                'obsolete', 'vanished'):
            continue
        for loc in m.findall('location'):
            f = os.path.normpath(loc.get('filename').replace('../', '', 1))
            contexts.setdefault(f, set()).add(name)
helper = re.compile(r'QString tr\(const char\* \w+[^)]*\)\s*\{\s*return '
                    r'QCoreApplication::translate\("([^"]+)"')
problems = []
for folder in ('app', 'cli', 'connection', 'model', 'report', 'sim', 'transport', 'ui'):
    for f in glob.glob(os.path.join(root, folder, '**', '*.cpp'), recursive=True):
        m = helper.search(open(f, encoding='utf-8').read())
        rel = os.path.relpath(f, root)
        if m and rel in contexts and m.group(1) not in contexts[rel]:
            problems.append(f'{rel}: its tr() asks for "{m.group(1)}" but lupdate files its '
                            f'messages under {sorted(contexts[rel])}')
for p in problems:
    print(p)
print(f'check-tr-contexts: {len(problems)} problem(s)')
sys.exit(1 if problems else 0)
