#!/usr/bin/env python3
"""Static stack depth of a function of the library: the deepest chain of calls below it,
each frame its pushes, its `sub $n, %rsp` and the return address, read from `objdump -dr`
of the static library (x86-64). A guide for finding which frames to shrink when
c_tests/stack.sh (the painted, measured bound) fails: it over-counts paths a call never
takes and skips panic, unwind and the rare reduction paths, so the two differ by a
hundred bytes or so.

Usage: c_tests/stack_depth.py target/release/libcncrot.a 'DEMANGLED NAME' [--callees]
  e.g. c_tests/stack_depth.py target/rt/libcncrot.a cncrot_machine_tcp_inverse --callees
"""
import re
import subprocess
import sys

lib, root = sys.argv[1], sys.argv[2]
out = subprocess.run(['objdump', '-dr', '--no-show-raw-insn', lib],
                     capture_output=True, text=True, check=True).stdout
funcs = {}
cur = None
prev = ''
for line in out.splitlines():
    m = re.match(r'^[0-9a-f]+ <(.*)>:$', line)
    if m:
        cur = m.group(1)
        funcs.setdefault(cur, {'frame': 0, 'push': 0, 'calls': set(), 'done': False})
        prev = ''
        continue
    if cur is None:
        continue
    f = funcs[cur]
    if re.search(r'\tpush ', line) and not f['done']:
        f['push'] += 1
    m = re.search(r'sub +\$(0x[0-9a-f]+),%rsp', line)
    if m and not f['done']:
        f['frame'] = int(m.group(1), 16)
        f['done'] = True
    m = re.search(r'R_X86_64_\w+\s+(\S+?)(?:-0x[0-9a-f]+|\+0x[0-9a-f]+)?$', line)
    if m and ('call' in prev or 'jmp' in prev):
        c = m.group(1)
        f['calls'].add(c[6:] if c.startswith('.text.') else c)
    prev = line


def demangle(name):
    d = subprocess.run(['c++filt', name], capture_output=True, text=True).stdout.strip()
    return re.sub(r'::h[0-9a-f]{16}$', '', d)


memo = {}


def depth(name, path):
    if name in memo:
        return memo[name]
    f = funcs.get(name)
    if f is None:
        return (0, [])
    own = f['frame'] + 8 * f['push'] + 8
    best = (0, [])
    for c in f['calls']:
        if c in path or re.search(r'panic|backtrace|unwind|rem360_cold|fmod', c):
            continue
        d = depth(c, path | {name})
        if d[0] > best[0]:
            best = d
    memo[name] = (own + best[0], [(own, name)] + best[1])
    return memo[name]


for n in funcs:
    if demangle(n) != root:
        continue
    total, chain = depth(n, frozenset())
    print(total, demangle(n))
    for own, x in chain:
        print(f'   {own:5d} {demangle(x)[:120]}')
    if '--callees' in sys.argv:
        for c in sorted(funcs[n]['calls']):
            print(f'  callee {depth(c, frozenset([n]))[0]:5d} {demangle(c)[:100]}')
