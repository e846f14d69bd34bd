#!/usr/bin/env python3
"""Fills unfinished messages of translations/opentop_<lang>.ts from a JSON file
{"<context>|<source>": {"zh_TW": "...", "zh_CN": "...", "ko": "...", "ja": "..."}} (issue 13).
Only messages lupdate marked unfinished are touched; the rest of each file stays byte-identical.
Usage: fill_ts.py TRANSLATIONS.json [translations/]"""
import html
import json
import os
import re
import sys

def unescape(text):
    return html.unescape(text)

def escape(text):
    return (text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')
            .replace("'", '&apos;').replace('"', '&quot;'))

def main():
    table = json.load(open(sys.argv[1], encoding='utf-8'))
    folder = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), '..')
    for lang in ('zh_TW', 'zh_CN', 'ko', 'ja'):
        path = os.path.join(folder, f'opentop_{lang}.ts')
        text = open(path, encoding='utf-8').read()
        out, filled, left = [], 0, 0
        context = None
        pos = 0
        pattern = re.compile(r'<name>(.*?)</name>|<message(?: [^>]*)?>(.*?)</message>', re.S)
        for m in pattern.finditer(text):
            if m.group(1) is not None:
                context = unescape(m.group(1))
                continue
            body = m.group(2)
            if 'type="unfinished"' not in body:
                continue
            source = unescape(re.search(r'<source>(.*?)</source>', body, re.S).group(1))
            entry = table.get(f'{context}|{source}')
            if not entry or lang not in entry:
                left += 1
                continue
            # A %n message (numerus) takes one form: these languages have no plural forms.
            def translated(found):
                if '<numerusform' in found.group(0):
                    return ('<translation>\n            <numerusform>' + escape(entry[lang]) +
                            '</numerusform>\n        </translation>')
                return '<translation>' + escape(entry[lang]) + '</translation>'
            new_body = re.sub(r'<translation type="unfinished">.*?</translation>|'
                              r'<translation type="unfinished"/>',
                              translated, body, count=1, flags=re.S)
            out.append(text[pos:m.start(2)] + new_body)
            pos = m.end(2)
            filled += 1
        out.append(text[pos:])
        open(path, 'w', encoding='utf-8').write(''.join(out))
        print(f'{lang}: {filled} filled, {left} left unfinished')

main()
