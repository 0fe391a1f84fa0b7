#!/usr/bin/env bash
# Builds the report: report/report.pdf from report/report.typ, with Typst from PyPI (pinned).
#
#   bash report/build.sh             compile report/report.pdf from the committed figures
#   bash report/build.sh --figures   first regenerate every figure, then compile (~30 s on 2 cores)
#   bash report/build.sh --check     compile to a temporary PDF only, to check the source (CI)
#
# Needs python3 with venv and pip; --figures also needs cargo. Runs from any directory.
#
# --figures regenerates, into report/figures/:
#   renders/<example>.png, renders.txt, renders.csv
#       every example in release at the size the report shows, with its printed summary;
#   failures/*.png, failures/failures.csv
#       the textbook methods' failures beside the library's renders (report/failures);
#   precision.csv, precision_time_vs_error.svg, convergence.csv, convergence.svg, precision.txt
#       the accuracy study (cargo run --release --example precision);
#   build-info.csv
#       the machine, compiler, build flags and commit the figures were made with.
# (figures/dispatch.csv holds criterion results recorded by hand: see the report, §4.2.)
set -euo pipefail
cd "$(dirname "$0")/.."

TYPST_VERSION=0.15.2
VENV=report/.venv
FIG=report/figures

# The examples and the widths the report shows them at (heights follow each scene's aspect;
# every other option is the example's default).
EXAMPLES=(
    "four_mirrors 800"
    "matte_spheres 600"
    "glass 600"
    "plane_and_triangles 600"
    "point_lights 600"
    "random_spheres 400"
)

usage() { sed -n '2,8s/^# \{0,1\}//p' "$0"; }

figures=false
check=false
for arg in "$@"; do
    case "$arg" in
        --figures) figures=true ;;
        --check) check=true ;;
        -h | --help) usage; exit 0 ;;
        *) echo "build.sh: unknown option $arg" >&2; usage >&2; exit 2 ;;
    esac
done

# Typst in a local virtual environment (git ignores report/.venv).
if ! "$VENV/bin/python" -c "import typst, sys; sys.exit(typst.__version__ != '$TYPST_VERSION')" 2>/dev/null; then
    echo "== installing typst $TYPST_VERSION into $VENV"
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install --quiet --disable-pip-version-check "typst==$TYPST_VERSION"
fi

regenerate_figures() {
    export CARGO_TERM_COLOR=never
    echo "== building the examples (release)"
    cargo build --release --examples --quiet
    mkdir -p "$FIG/renders"
    local tmp
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' RETURN

    echo "== rendering the examples"
    : >"$tmp/renders.txt"
    for entry in "${EXAMPLES[@]}"; do
        read -r name width <<<"$entry"
        {
            echo "\$ cargo run --release --example $name -- --width $width"
            "target/release/examples/$name" --width "$width" --out "$tmp"
            echo
        } | tee -a "$tmp/renders.txt"
        cp "$tmp/$name.png" "$FIG/renders/$name.png"
    done
    # The files went to a temporary folder; the commands shown write to output/.
    sed "s|$tmp/|output/|g" "$tmp/renders.txt" >"$FIG/renders.txt"
    # The summaries as a table the report reads.
    "$VENV/bin/python" - "$FIG/renders.txt" "$FIG/renders.csv" "${#EXAMPLES[@]}" <<'PY'
import csv, re, sys
text = open(sys.argv[1], encoding="utf-8").read()
head = re.compile(r"\$ (?P<command>cargo run .*)\n(?P<example>\w+): (?P<width>\d+)×(?P<height>\d+) pixels, "
                  r"(?P<spp>\d+) spp, max depth (?P<max_depth>\d+), (?P<precision>\w+), seed (?P<seed>\d+)")
stats = re.compile(r"render: (?P<seconds>[\d.]+) s, (?P<rays>\d+) rays, (?P<mrays>[\d.]+) Mrays/s "
                   r"on (?P<threads>\d+) threads?\n\s+total \(render \+ files\): (?P<total>[\d.]+) s")
rows = []
for block in text.split("\n\n"):
    h, s = head.search(block), stats.search(block)
    if h and s:
        rows.append({**h.groupdict(), **s.groupdict()})
fields = ["example", "command", "width", "height", "spp", "max_depth", "precision", "seed",
          "seconds", "rays", "mrays", "threads", "total"]
with open(sys.argv[2], "w", newline="", encoding="utf-8") as f:
    w = csv.DictWriter(f, fieldnames=fields)
    w.writeheader()
    w.writerows(rows)
if len(rows) != int(sys.argv[3] if len(sys.argv) > 3 else len(rows)):
    sys.exit("renders.csv: a summary did not parse")
print(f"wrote {sys.argv[2]} ({len(rows)} renders)")
PY

    echo "== the failure figures (report/failures)"
    CARGO_TARGET_DIR=target cargo run --release --quiet --manifest-path report/failures/Cargo.toml -- "$FIG/failures"

    echo "== the accuracy study (examples/precision)"
    "target/release/examples/precision" --out "$FIG" | tee "$FIG/precision.txt"

    {
        echo "key,value"
        echo "cpu,\"$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //' || echo unknown)\""
        echo "cores,$(nproc 2>/dev/null || echo unknown)"
        echo "rustc,\"$(rustc --version)\""
        # The flags of the builds: RUSTFLAGS if set, else .cargo/config.toml's.
        echo "rustflags,\"${RUSTFLAGS:-$(sed -n 's/^rustflags = \[\(.*\)\]/\1/p' .cargo/config.toml | tr -d '",')}\""
        echo "commit,$(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- src examples 2>/dev/null || echo ' (with uncommitted changes)')"
        echo "date,$(date -u +%Y-%m-%d)"
    } >"$FIG/build-info.csv"
}

if $figures; then
    start=$SECONDS
    regenerate_figures
    echo "== figures regenerated in $((SECONDS - start)) s"
fi

if $check; then
    out=$(mktemp -d)/report.pdf
else
    out=report/report.pdf
fi
echo "== compiling report/report.typ -> $out"
"$VENV/bin/python" - "$out" <<'PY'
import sys, typst
# Only the fonts embedded in Typst, so every machine builds the same PDF.
_, warnings = typst.compile_with_warnings(
    "report/report.typ", output=sys.argv[1], root="report", ignore_system_fonts=True)
for w in warnings:
    print(f"warning: {getattr(w, 'message', w)}", file=sys.stderr)
PY
if $check; then
    echo "== report compiles ($(wc -c <"$out") bytes)"
    rm -rf "$(dirname "$out")"
else
    echo "== wrote $out"
fi
