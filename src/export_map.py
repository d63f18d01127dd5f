#!/usr/bin/env python3
"""The shared library's linker version script (meson.build): every function
the public headers (include/acbb/*.h, the core, given as arguments; not
the tools in include/acbb/tools/) declare is global,
everything else, the engine's internals, is local. Comments are dropped
first, so prose naming a function exports nothing."""
import re
import sys

names = set()
for path in sys.argv[1:]:
    with open(path, encoding="utf-8") as f:
        text = re.sub(r"/\*.*?\*/", " ", f.read(), flags=re.S)
    names.update(re.findall(r"\b(acbb_[a-z0-9_]+)\s*\(", text))
print("{\n  global:")
for n in sorted(names):
    print(f"    {n};")
print("  local: *;\n};")
