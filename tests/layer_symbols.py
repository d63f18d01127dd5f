#!/usr/bin/env python3
"""Layering checked on symbols, not on #includes (tests/test_layers.sh (6)).

usage: layer_symbols.py RANKS LIB EXE     run nm on the built objects
       layer_symbols.py RANKS --nm FILE   read `nm -A -P` text (self-test)

RANKS is "base=-1,physics=0,...": each engine folder (src/<folder>/) and
its floor. Objects map to folders by their names: the library's members
are src_<folder>_<file>.c.o; the client objects (cli/, ui/) are in EXE.p/
as cli_<file>.c.o, ui_<file>.c.o (anything else there, a generated
source, counts as the client). A call through a public header leaves an
undefined symbol (nm type U) in the caller's object and a defined one in
the callee's, so every reference between folders is visible here.

Prints one line per problem, sorted, then nothing else:
  upward: DIR/FILE -> SYMBOL (DIR/FILE)   an engine folder references one above it
  client: DIR/FILE -> SYMBOL (DIR/FILE)   the engine references cli/ or ui/
  cycle: A <-> B ...                      folders that reach each other (one
                                          line per strongly connected set)
  unmapped: OBJECT                        an object that maps to no known folder
and on stderr the counts "engine N client M" (so a run that found
nothing cannot pass silently: the shell test checks them).
"""
import os
import re
import subprocess
import sys
from collections import defaultdict


def read_nm(text):
    """(object, type, symbol) for each global symbol in `nm -A -P` text."""
    for line in text.splitlines():
        # "lib.a[member.o]: sym T 0 10" or "dir/x.o: sym U"
        m = re.match(r'^(.*?):\s+(\S+)\s+([A-Za-z])(\s|$)', line)
        if not m:
            continue
        where, sym, typ = m.group(1), m.group(2), m.group(3)
        member = re.search(r'\[([^\]]+)\]$', where)
        obj = member.group(1) if member else os.path.basename(where)
        if typ == 'U' or typ.isupper() or typ in 'vw':
            yield obj, typ, sym


def home(obj, ranks):
    """(folder, file) for an object name, or None."""
    m = re.match(r'^src_([a-z]+)_(.+)\.o$', obj)
    if m:
        return (m.group(1), m.group(2)) if m.group(1) in ranks else None
    m = re.match(r'^(cli|ui)_(.+)\.o$', obj)
    if m:
        return m.group(1), m.group(2)
    return 'client', obj[:-2] if obj.endswith('.o') else obj


def floor(where, ranks):
    """The rank of a (folder, file); a client ranks above every folder."""
    return ranks.get(where[0], max(ranks.values()) + 1)


def reach(edges, nodes):
    """For each node, the set of nodes it reaches (6 folders: closure)."""
    out = {a: set(edges[a]) for a in nodes}
    for k in nodes:
        for a in nodes:
            if k in out[a]:
                out[a] |= out[k]
    return out


def check(text, ranks):
    """Problem lines and object counts for `nm -A -P` text."""
    defs, refs, problems = {}, defaultdict(set), []
    count = {'engine': 0, 'client': 0}
    seen = set()
    for obj, typ, sym in read_nm(text):
        where = home(obj, ranks)
        if obj not in seen:
            seen.add(obj)
            if where is None:
                problems.append(f'unmapped: {obj}')
            else:
                count['engine' if where[0] in ranks else 'client'] += 1
        if where is None:
            continue
        if typ == 'U':
            refs[where].add(sym)
        else:
            # a weak or common symbol may be defined in several objects:
            # keep the lowest (the engine's below any client's)
            old = defs.get(sym)
            if old is None or floor(where, ranks) < floor(old, ranks):
                defs[sym] = where
    edges = defaultdict(dict)   # folder -> {folder: an example reference}
    for (d, f), syms in refs.items():
        if d not in ranks:
            continue
        for sym in sorted(syms):
            if sym not in defs:
                continue
            hd, hf = defs[sym]
            line = f'{d}/{f} -> {sym} ({hd}/{hf})'
            if hd not in ranks:
                problems.append(f'client: {line}')
            elif hd != d:
                edges[d].setdefault(hd, line)
                if ranks[hd] > ranks[d]:
                    problems.append(f'upward: {line}')
    nodes = sorted(ranks)
    r = reach(edges, nodes)
    cycles = {tuple(sorted({a} | {b for b in r[a] if a in r[b]})) for a in nodes}
    for c in sorted(x for x in cycles if len(x) > 1):
        # two folders: both references; more: the upward lines say where
        via = [edges[x][y] for x, y in ((c[0], c[-1]), (c[-1], c[0])) if len(c) == 2]
        problems.append('cycle: ' + ' <-> '.join(c) + (f" ({'; '.join(via)})" if via else ''))
    return sorted(problems), count


def main(argv):
    ranks = {k: int(v) for k, v in (p.split('=') for p in argv[1].split(','))}
    if argv[2] == '--nm':
        text = open(argv[3]).read()
    else:
        lib, exe = argv[2], argv[3]
        objdir = exe + '.p'
        client = sorted(os.path.join(objdir, o) for o in os.listdir(objdir) if o.endswith('.o'))
        text = subprocess.run(['nm', '-A', '-P', lib] + client, check=True,
                              capture_output=True, text=True).stdout
    problems, count = check(text, ranks)
    print('\n'.join(problems), end='\n' if problems else '')
    print(f"engine {count['engine']} client {count['client']}", file=sys.stderr)


if __name__ == '__main__':
    main(sys.argv)
