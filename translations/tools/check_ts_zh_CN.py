#!/usr/bin/env python3
"""Checker for /work/i18n/opentop_zh_CN.ts (OpenTOP, Simplified Chinese).

For every message it verifies:
  * the translation is not empty and carries no type="unfinished";
  * numerus messages hold exactly one <numerusform> (CJK: one plural form);
  * the same placeholders as the source (%1..%99, %L1.., %n, %%), as a multiset;
  * the same HTML / rich-text tags (<b>, </b>, <br>, <a href=...>, ...), as a multiset;
  * the same leading and trailing whitespace and the same number of "\\n";
  * every "&X" accelerator of the source has "&X" (same letter) in the translation;
  * "..."/"…" at the end of the source is kept;
  * glossary terms (glossary_zh_CN.md) are used where the source names them.
It also checks that the file parses as XML, that everything outside the
<translation> elements is byte-identical to the untranslated original (when
work_zh_CN/opentop_zh_CN.orig.ts exists) and, when lrelease is installed,
that lrelease reports "0 unfinished".

Usage: python3 check_zh_CN.py [file.ts]      exit status 0 when 0 problems.
"""
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections import Counter

HERE = os.path.dirname(os.path.abspath(__file__))
TS = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, 'opentop_zh_CN.ts')
ORIG = os.path.join(HERE, 'work_zh_CN', 'opentop_zh_CN.orig.ts')
LRELEASE = '/usr/lib/qt6/bin/lrelease'

PLACEHOLDER = re.compile(r'%(?:L?\d{1,2}|n|%)')
TAG = re.compile(r'</?[A-Za-z][A-Za-z0-9]*(?:\s[^<>]*)?/?>')
ACCEL = re.compile(r'&([A-Za-z0-9])')
LEAD = re.compile(r'^\s*')
TRAIL = re.compile(r'\s*$')

# (regex on the source, required Chinese term, optional exception regex on the source)
TERMS = [
    (r'\bmachine numbers?\b', '站号', None),
    (r'\bcommunication priority\b', '通信优先级', None),
    (r'\bI/O priority\b', 'I/O 优先级', None),
    (r'\bcontrol priority\b', '控制优先级', None),
    (r'\bcommunication groups?\b', '通信组', None),
    (r'\brunning data\b', '运行数据', None),
    (r'\bdeceleration time\b', '减速时间', None),
    (r'\bacceleration time\b', '加速时间', None),
    (r'\bload rate\b', '负载率', None),
    (r'\btarget speed\b', '目标速度', None),
    (r'\bcurrent speed\b', '当前速度', None),
    (r'\balarm reset\b', '报警复位', None),
    (r'\bcommunication error\b', '通信错误', None),
    (r'\btest[- ]run\b', '试运行', None),
    (r'\bSTOP ALL\b', '全部停止', None),
    (r'\bfactory defaults?\b', '出厂', None),
    (r'\bpending\b', '待写入', None),
    (r'\btraffic log\b', '报文日志', None),
    (r'\bsimulated bus\b', '模拟总线', None),
    (r'\bfirst-pass yield\b', '直通率', None),
    (r'\bper-unit values?\b', '单台数值', None),
    (r'\bproduction mode\b', '生产模式', None),
    (r'\bresults database\b', '结果数据库', None),
    (r'\bserial number\b', '序列号', None),
    (r'\brecipes?\b', '配方', r'\brecipe (check|create|show|sign)\b|eol recipe|RECIPE'),
    (r'\bgolden unit\b', '标准样机', None),
    (r'\bcertificates?\b', '证书', r'^certificate: |; certificate\)'),
    (r'\bfirmware\b', '固件', r'firmware='),
    (r'\bbroadcast\b', '广播', None),
    (r'\bverif(y|ied|ication)\b', '校验', None),
    (r'\bread back\b', '回读', None),
    (r'\bbackups?\b', '备份', r'--from-backup|"backup"|backup ID'),
    (r'\bspeed display\b', '速度显示', None),
    (r'\bparent\b', '父站', None),
    (r'\bchild(ren)?\b', '子站', None),
    (r'\bwarnings?\b', '警告', r'^warning: |Warning-Out|warning ID CODE'),
    (r'\balarms?\b', '报警', r'alarm=|Alarm-Reset|Alarm-Out|alarm ID CODE|^Alarm-Reset$'),
    (r'\bpoll(ing|ed|s)?\b', '轮询', r'--poll-ms'),
]


def text_of(el):
    return el.text or ''


def main():
    problems = []
    data = open(TS, 'rb').read()
    try:
        root = ET.fromstring(data)
    except ET.ParseError as e:
        print(f'XML does not parse: {e}')
        return 1
    if b'type="unfinished"' in data:
        problems.append(('file', 'type="unfinished" is still present'))
    n = 0
    for ctx in root.iter('context'):
        cname = ctx.findtext('name')
        for msg in ctx.iter('message'):
            n += 1
            src = text_of(msg.find('source'))
            tel = msg.find('translation')
            where = f'{cname}: {src[:70]!r}'
            if tel is None:
                problems.append((where, 'no <translation>'))
                continue
            if tel.get('type'):
                problems.append((where, f'translation type="{tel.get("type")}"'))
            if msg.get('numerus') == 'yes':
                forms = tel.findall('numerusform')
                if len(forms) != 1:
                    problems.append((where, f'{len(forms)} numerusforms, expected 1'))
                    continue
                tr = text_of(forms[0])
                if '%n' not in tr:
                    problems.append((where, 'numerus translation without %n'))
            else:
                tr = text_of(tel)
            if not tr.strip():
                problems.append((where, 'empty translation'))
                continue
            ps, pt = Counter(PLACEHOLDER.findall(src)), Counter(PLACEHOLDER.findall(tr))
            if ps != pt:
                problems.append((where, f'placeholders {sorted(ps.elements())} vs {sorted(pt.elements())}'))
            ts_, tt = Counter(TAG.findall(src)), Counter(TAG.findall(tr))
            if ts_ != tt:
                problems.append((where, f'tags differ: {sorted((ts_ - tt).elements())} / {sorted((tt - ts_).elements())}'))
            if LEAD.match(src).group(0) != LEAD.match(tr).group(0):
                problems.append((where, 'leading whitespace differs'))
            if TRAIL.search(src).group(0) != TRAIL.search(tr).group(0):
                problems.append((where, 'trailing whitespace differs'))
            if src.count('\n') != tr.count('\n'):
                problems.append((where, f'{src.count(chr(10))} newlines in source, {tr.count(chr(10))} in translation'))
            src_acc = [a.lower() for a in ACCEL.findall(src.replace('&&', ''))]
            tr_acc = [a.lower() for a in ACCEL.findall(tr.replace('&&', ''))]
            for a in src_acc:
                if a not in tr_acc:
                    problems.append((where, f'accelerator &{a} missing'))
            if len(tr_acc) > len(src_acc):
                problems.append((where, 'translation has more accelerators than the source'))
            if src_acc and re.search(r'&[A-Za-z0-9]', tr) and not re.search(r'\(&[A-Za-z0-9]\)', tr) \
                    and re.search(r'[\u4e00-\u9fff]', tr):
                problems.append((where, 'accelerator not written as a "(&X)" suffix'))
            for end in ('…', '...'):
                if src.rstrip().endswith(end) and not tr.rstrip().endswith(end) \
                        and not re.search(re.escape(end) + r'[）)：:]?$', tr.rstrip()):
                    problems.append((where, f'source ends with {end!r}, translation does not'))
            for pat, term, exc in TERMS:
                if re.search(pat, src, re.I) and term not in tr:
                    if exc and re.search(exc, src):
                        continue
                    problems.append((where, f'glossary: source has /{pat}/, translation lacks {term}'))
    # everything outside <translation> must be byte-identical to the original
    if os.path.exists(ORIG):
        strip = lambda b: re.sub(rb'<translation[^>]*>.*?</translation>', b'<translation/>', b, flags=re.S)
        if strip(open(ORIG, 'rb').read()) != strip(data):
            problems.append(('file', 'text outside <translation> differs from the original'))
    for where, what in problems:
        print(f'{where}\n    -> {what}')
    print(f'{n} messages checked, {len(problems)} problems')
    if os.path.exists(LRELEASE):
        out = subprocess.run([LRELEASE, TS, '-qm', '/tmp/check_zh_CN.qm'],
                             capture_output=True, text=True)
        msg = (out.stdout + out.stderr).strip()
        print('lrelease:', msg)
        if '0 unfinished' not in msg or out.returncode != 0:
            problems.append(('lrelease', msg))
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
