#!/bin/sh
# Rebuilds the `ok-*` files of tests/fuzz/corpus/resume from a live sweep
# (the one tests/fuzz/fuzz_cli.c reads every resume input as; CSV with
# --csv-header: a one-file input has no sidecar). A sweep
# file's header holds every resolved scene key, so a new preset key or a
# new output column changes it: run this after adding one.
#   tests/fuzz/make_resume_corpus.sh build/acbb      (from the repository root)
set -eu
ACBB=${1:?usage: make_resume_corpus.sh path/to/acbb}
D=tests/fuzz/corpus/resume
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
"$ACBB" sweep presets/7008C.ini --set fidelity.model=quasi-static \
    --grid operating.axial_load_N=100,200 --grid effects.thermal_expansion=on,off \
    --jobs 1 --jsonl "$T/w.jsonl" --csv-header --csv "$T/w.csv" >/dev/null 2>&1
cp "$T/w.jsonl" "$D/ok-whole.jsonl"
cp "$T/w.csv" "$D/ok-whole.csv"
python3 - "$T" "$D" <<'PY'
import sys
t, d = sys.argv[1], sys.argv[2]
j = open(t + "/w.jsonl", "rb").read()
c = open(t + "/w.csv", "rb").read()
jl, cl = j.split(b"\n"), c.split(b"\n")
def put(name, data): open(d + "/" + name, "wb").write(data)
put("ok-header-cut.jsonl", jl[0][:100])                    # header cut mid-line
put("ok-header-cut.csv", cl[0] + b"\n" + cl[1][:40])       # column line cut
put("ok-header-cut-4k.csv", c[:4096])                      # cut at a 4 KiB boundary
put("ok-partial-record.jsonl", b"\n".join(jl[:4]) + b"\n" + jl[4][:len(jl[4]) // 2])
put("ok-partial-record.csv", b"\n".join(cl[:5]) + b"\n" + cl[5][:len(cl[5]) // 2])
wl = [jl[0]] + [r.replace(b'"status":"converged"', b'"status":"wall_limit"') for r in jl[1:]]
put("ok-wall-limit.jsonl", b"\n".join(wl))
PY
