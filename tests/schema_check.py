#!/usr/bin/env python3
"""A JSON Schema checker for the subset docs/schema/acbb.schema.json uses
(type, const, enum, required, properties, additionalProperties, items,
minimum; a type may be a list): no validator library is installed.
Usage: schema_check.py SCHEMA [--def KIND] [--lines] [--each] DOC.json...
--def: check against $defs/KIND instead of the root; --lines: each line of
a DOC is one document (JSONL); --each: the DOC is an array, check each
element. Exit 0 when every document conforms, 1 with each violation's
path on stderr otherwise."""
import json
import sys

TYPES = {"object": dict, "array": list, "string": str, "boolean": bool}


def type_ok(v, t):
    if isinstance(t, list):
        return any(type_ok(v, x) for x in t)
    if t == "number":
        return isinstance(v, (int, float)) and not isinstance(v, bool)
    if t == "integer":
        return isinstance(v, int) and not isinstance(v, bool)
    if t == "null":
        return v is None
    return isinstance(v, TYPES[t])


def check(v, s, path, errs):
    if s is True:
        return
    if s is False:
        errs.append(f"{path}: not allowed")
        return
    if "type" in s and not type_ok(v, s["type"]):
        errs.append(f"{path}: expected {s['type']}, got {type(v).__name__}")
        return
    if "const" in s and v != s["const"]:
        errs.append(f"{path}: expected {s['const']!r}, got {v!r}")
    if "enum" in s and v not in s["enum"]:
        errs.append(f"{path}: {v!r} not in {s['enum']}")
    if "minimum" in s and type_ok(v, "number") and v < s["minimum"]:
        errs.append(f"{path}: {v} < {s['minimum']}")
    if isinstance(v, dict):
        for k in s.get("required", []):
            if k not in v:
                errs.append(f"{path}: missing {k}")
        props = s.get("properties", {})
        for k, x in v.items():
            if k in props:
                check(x, props[k], f"{path}.{k}", errs)
            elif "additionalProperties" in s:
                check(x, s["additionalProperties"], f"{path}.{k}", errs)
    if isinstance(v, list) and "items" in s:
        for i, x in enumerate(v):
            check(x, s["items"], f"{path}[{i}]", errs)


def documents(name, lines, each):
    if lines:
        docs = [json.loads(x) for x in open(name) if x.strip()]
    else:
        docs = [json.load(open(name))]
    if each:
        if not all(isinstance(d, list) and d for d in docs):
            raise ValueError(f"{name}: not a non-empty array")
        docs = [x for d in docs for x in d]
    return docs


def main():
    schema = json.load(open(sys.argv[1]))
    args = sys.argv[2:]
    lines = "--lines" in args
    each = "--each" in args
    args = [a for a in args if a not in ("--lines", "--each")]
    if args[:1] == ["--def"]:
        schema = schema["$defs"][args[1]]
        args = args[2:]
    bad = 0
    for name in args:
        errs = []
        for i, doc in enumerate(documents(name, lines, each)):
            check(doc, schema, f"${i}" if lines or each else "$", errs)
        for e in errs:
            print(f"{name}: {e}", file=sys.stderr)
        bad += bool(errs)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
