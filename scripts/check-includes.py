#!/usr/bin/env python3
"""The include rules of docs/architecture.md, checked on the source tree (a ctest test):
every quoted include names its module from the repository root and exists there; nothing
outside app/ includes app/; model/ and transport/ include no Qt Widgets; the folders inside
model/ form no cycle. Prints each breach and exits 1 when there is one."""
import os
import re
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..'))
modules = ('transport', 'model', 'report', 'sim', 'connection', 'ui', 'cli', 'bench', 'app', 'tests')
include = re.compile(r'^\s*#\s*include\s+([<"])([^>"]+)[>"]', re.M)
widgets = re.compile(r'^(QtWidgets/|Q(Widget|Dialog|MainWindow|PushButton|Label|LineEdit|MessageBox|Application)\b)')
problems = []
graph = {}

for module in modules:
    for folder, dirs, files in os.walk(os.path.join(root, module)):
        dirs[:] = [d for d in dirs if d not in ('corpus',)]
        for name in files:
            if not name.endswith(('.cpp', '.h')):
                continue
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, root)
            with open(path, encoding='utf-8') as f:
                text = f.read()
            for kind, target in include.findall(text):
                if kind == '<':
                    if module in ('model', 'transport') and widgets.match(target):
                        problems.append(f'{rel}: Qt Widgets in {module}/: <{target}>')
                    continue
                if target.endswith(('.moc', '_autogen.h')) or target.startswith(('moc_', 'ui_')):
                    continue
                if target.split('/')[0] not in modules or not os.path.isfile(os.path.join(root, target)):
                    problems.append(f'{rel}: "{target}" does not name a file from the repository root')
                    continue
                if target.startswith('app/') and module != 'app':
                    problems.append(f'{rel}: includes app/ ("{target}")')
                if module == 'model' and target.startswith('model/'):
                    src = rel.split('/')[1] if rel.count('/') > 1 else '(root)'
                    dst = target.split('/')[1] if target.count('/') > 1 else '(root)'
                    if src != dst:
                        graph.setdefault(src, set()).add(dst)

# Folder cycles inside model/ (Tarjan's strongly connected components).
index, low, stack, on, cycles, counter = {}, {}, [], set(), [], [0]


def visit(v):
    index[v] = low[v] = counter[0]
    counter[0] += 1
    stack.append(v)
    on.add(v)
    for w in graph.get(v, ()):
        if w not in index:
            visit(w)
            low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        component = []
        while True:
            w = stack.pop()
            on.discard(w)
            component.append(w)
            if w == v:
                break
        if len(component) > 1:
            cycles.append(sorted(component))


for v in list(graph):
    if v not in index:
        visit(v)
for c in cycles:
    edges = [f'{a} -> {b}' for a in c for b in sorted(graph.get(a, ())) if b in c]
    problems.append('model/ folders in a cycle: ' + ', '.join(edges))

for p in problems:
    print(p)
print(f'include rules: {len(problems)} problem(s)')
sys.exit(1 if problems else 0)
