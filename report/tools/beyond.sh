#!/usr/bin/env bash
# The figures of the report's Part II (what goes beyond the assignment), made from the
# repository root after the release examples and the binary are built (report/build.sh
# --figures calls it last; it can also run alone: bash report/tools/beyond.sh).
#
#   figures/renders/materials.png, figures/cli/materials-render.txt
#       cargo run --release --example materials -- --width 800 (every material and texture kind)
#   figures/renders/environment.png, figures/cli/environment-render.txt
#       raytrace render scenes/environment.toml --width 800 (an environment map, depth of field)
#   figures/renders/instances.png, figures/cli/instances-render.txt
#       raytrace render validate/scenes/instances.toml --width 400 (instances of two meshes)
#   figures/bsdf_chi2.csv
#       the BSDF samplers' chi-squared runs and the planted mistakes, as tests/it/bsdf_chi2.rs
#       prints them (cargo test --test it bsdf_chi2 -- --nocapture)
set -euo pipefail
cd "$(dirname "$0")/../.."
FIG=report/figures
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$FIG/renders" "$FIG/cli"

if [ -f assets/meshes/bunny.obj ]; then
    echo "== the materials example"
    target/release/examples/materials --width 800 --out "$tmp" | sed "s|$tmp/|output/|g" | tee "$FIG/cli/materials-render.txt"
    cp "$tmp/materials.png" "$FIG/renders/materials.png"
else
    echo "   (no bunny: bash tools/fetch_meshes.sh; the committed materials figure stays)"
fi

echo "== the environment scene (raytrace render)"
target/release/raytrace render scenes/environment.toml --width 800 --quiet --out "$tmp/environment.png" |
    sed "s|$tmp/|report/figures/renders/|" | tee "$FIG/cli/environment-render.txt"
cp "$tmp/environment.png" "$FIG/renders/environment.png"

echo "== instances (validate/scenes/instances.toml: one ball mesh and a cube placed several times)"
target/release/raytrace render validate/scenes/instances.toml --width 400 --quiet --out "$tmp/instances.png" |
    sed "s|$tmp/|report/figures/renders/|" | tee "$FIG/cli/instances-render.txt"
cp "$tmp/instances.png" "$FIG/renders/instances.png"

echo "== the BSDF samplers' chi-squared tests (tests/it/bsdf_chi2.rs)"
cargo test --quiet --test it bsdf_chi2 -- --nocapture --test-threads 1 >"$tmp/chi2.txt" 2>&1 ||
    { cat "$tmp/chi2.txt"; exit 1; }
python3 - "$tmp/chi2.txt" "$FIG/bsdf_chi2.csv" <<'PY'
import csv, re, sys
line = re.compile(
    r"^(?P<run>.+?)(?: Case \{ spec: (?P<spec>.*?), theta: (?P<theta>[\d.]+), .*?scalar: (?P<scalar>F32|F64) \})?"
    r": Outcome \{ chi2: (?P<chi2>\S+), dof: (?P<dof>\d+), p: (?P<p>[^,]+),")
rows = []
for text in open(sys.argv[1], encoding="utf-8"):
    # (the quiet test runner prints a progress dot before some lines)
    m = line.match(text.strip().lstrip("."))
    if not m:
        continue
    d = m.groupdict()
    planted = not re.match(r"\w+\[\d+\]$", d["run"])
    rows.append({"run": d["run"], "kind": "planted" if planted else "correct", "spec": d["spec"] or "",
                 "theta": d["theta"] or "", "scalar": (d["scalar"] or "").lower(),
                 "chi2": d["chi2"], "dof": d["dof"], "p": d["p"]})
correct = sum(r["kind"] == "correct" for r in rows)
if correct != 28:
    sys.exit(f"bsdf_chi2.csv: expected the 28 runs of tests/it/bsdf_chi2.rs, parsed {correct} (of {len(rows)} lines):\n"
             + "\n".join(r["run"][:60] for r in rows))
with open(sys.argv[2], "w", newline="", encoding="utf-8") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
print(f"wrote {sys.argv[2]} ({len(rows)} runs)")
PY
