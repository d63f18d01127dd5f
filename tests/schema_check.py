#!/usr/bin/env python3
"""Validate JSON documents against docs/schema/acbb.schema.json with the
jsonschema package's Draft 2020-12 validator (Debian python3-jsonschema;
issue 28 item 6: it replaced a hand-written checker of a subset).
Usage: schema_check.py SCHEMA [--def KIND] [--lines] [--each] DOC.json...
--def: check against $defs/KIND instead of the root; --lines: each line of
a DOC is one document (JSONL); --each: the DOC is an array, check each
element. Exit 0 when every document conforms, 1 with each violation's
path and reason on stderr otherwise, 77 when jsonschema is missing."""
import json
import sys

try:
    import jsonschema
except ImportError:
    print("schema_check.py: the jsonschema module is missing (apt-get install python3-jsonschema)",
          file=sys.stderr)
    sys.exit(77)


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


def validator(schema, kind):
    cls = jsonschema.Draft202012Validator
    cls.check_schema(schema)
    if kind:
        if kind not in schema["$defs"]:
            raise KeyError(f"no $defs/{kind} in the schema")
        # A reference into the whole schema, so $refs between $defs resolve.
        schema = {**schema, "$ref": f"#/$defs/{kind}"}
        schema.pop("oneOf", None)
    return cls(schema)


def main():
    schema = json.load(open(sys.argv[1]))
    args = sys.argv[2:]
    lines = "--lines" in args
    each = "--each" in args
    args = [a for a in args if a not in ("--lines", "--each")]
    kind = None
    if args[:1] == ["--def"]:
        kind, args = args[1], args[2:]
    v = validator(schema, kind)
    bad = 0
    for name in args:
        errs = []
        for i, doc in enumerate(documents(name, lines, each)):
            where = f"${i}" if lines or each else "$"
            # best_match: under oneOf, the branch that came closest
            e = jsonschema.exceptions.best_match(v.iter_errors(doc))
            if e is not None:
                path = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in e.absolute_path)
                errs.append(f"{where}{path}: {e.message}")
        for e in errs:
            print(f"{name}: {e}", file=sys.stderr)
        bad += bool(errs)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
