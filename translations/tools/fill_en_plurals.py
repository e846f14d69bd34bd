#!/usr/bin/env python3
"""Fills the English plural forms of translations/plurals/opentop_en.ts: for each unfinished
%n message, the singular and the plural. The noun counted by %n is the first "word(s)" after
%n: "word" for one, "words" for more; other "(s)" (counted by %1) stay. Sentences whose verb
or pronoun follows the count are written out in OVERRIDES. Prints any message it cannot fill.
Usage: fill_en_plurals.py [translations/plurals/opentop_en.ts]"""
import html
import os
import re
import sys

OVERRIDES = {
    '%n edit(s) have not been written to the drives. Quit and discard them?':
        ('%n edit has not been written to the drives. Quit and discard it?',
         '%n edits have not been written to the drives. Quit and discard them?'),
    'Your %n unwritten edit(s) of this drive are discarded.':
        ('Your %n unwritten edit of this drive is discarded.',
         'Your %n unwritten edits of this drive are discarded.'),
    '%n problem(s): the recipe cannot be saved until they are fixed.':
        ('%n problem: the recipe cannot be saved until it is fixed.',
         '%n problems: the recipe cannot be saved until they are fixed.'),
    'Save the %n drive(s) that were read?':
        ('Save the %n drive that was read?', 'Save the %n drives that were read?'),
    'communication error (%n in a row)':
        ('communication error (%n in a row)', 'communication errors (%n in a row)'),
}

COUNTED = re.compile(r'(%n(?:[^%()]*?\b))(\w+)\(s\)')


def forms(source):
    if source in OVERRIDES:
        return OVERRIDES[source]
    m = COUNTED.search(source)
    if not m:
        return None
    one = source[:m.start(2)] + m.group(2) + source[m.end():]
    many = source[:m.start(2)] + m.group(2) + 's' + source[m.end():]
    return one, many


def escape(text):
    return (text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')
            .replace("'", '&apos;').replace('"', '&quot;'))


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(__file__), '..', 'plurals', 'opentop_en.ts')
    text = open(path, encoding='utf-8').read()
    unfilled = []

    def fill(m):
        body = m.group(0)
        if 'type="unfinished"' not in body:
            return body
        source = html.unescape(re.search(r'<source>(.*?)</source>', body, re.S).group(1))
        found = forms(source)
        if not found:
            unfilled.append(source)
            return body
        translation = ('<translation>\n            <numerusform>' + escape(found[0]) +
                       '</numerusform>\n            <numerusform>' + escape(found[1]) +
                       '</numerusform>\n        </translation>')
        return re.sub(r'<translation type="unfinished">.*?</translation>', lambda _: translation,
                      body, count=1, flags=re.S)

    text = re.sub(r'<message numerus="yes">.*?</message>', fill, text, flags=re.S)
    open(path, 'w', encoding='utf-8').write(text)
    for source in unfilled:
        print('not filled (add it to OVERRIDES):', source)
    return 1 if unfilled else 0


sys.exit(main())
