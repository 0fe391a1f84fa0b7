#!/usr/bin/env bash
# Builds the report: report/report.pdf from report/report.typ (with report/lib/ and report/parts/),
# with Typst from PyPI (pinned).
#
#   bash report/build.sh             compile report/report.pdf from the committed figures and data
#   bash report/build.sh --data      first copy the data made outside report/ into report/data/
#   bash report/build.sh --figures   first regenerate every figure and table (implies --data;
#                                    ~10 min on 2 cores, timings included: run it on an idle machine)
#   bash report/build.sh --check     compile to a temporary PDF only, to check the source (CI)
#
# Needs python3 with venv and pip; --figures also needs cargo. Runs from any directory.
# Every build warns when a copy in report/data/ differs from its source, and when the figures
# or the copied results were made at a commit older than the last one that changed the code
# that makes them (the code they depict; changes to comments alone do not count).
#
# report/data/ holds, from outside report/ (copied by --data and --figures):
#   scale.csv, scale.md          python3 bench/scale.py (this crate against Embree 3)
#   comparison.csv, comparison.md, furnace.csv, fresnel_probe.csv, foreign.csv, foreign.md,
#   foreign-veach_mis.png        bash validate/run.sh (the Mitsuba 3 cross-check)
#   mitsuba_bench.csv            validate/.venv/bin/python validate/bench.py (time beside Mitsuba 3)
#   book.csv, book.md            python3 bench/book.py (random_spheres beside the book's C++)
#   equal_time.csv, equal_time.md
#                                cargo run --release --features studies --example equal_time
#   provenance.csv               each copy's source and the commit that last committed it
# and, made by --figures:
#   modules.csv, loc.csv         python3 report/tools/modules.py (module graph, line counts)
#   speed.csv, speed_memory.csv  python3 report/tools/speed.py (interleaved timings)
#   dispatch.csv                 cargo bench -p raytrace-benches --bench render -- dispatch (criterion, enum vs dyn)
#   tests.csv                    cargo test -- --list (tests per test target)
#   tiles.csv                    the dragon in four tiles, merged, compared with the whole
#
# --figures regenerates, into report/figures/:
#   renders/<example>.png, renders.txt, renders.csv
#       every example in release at the size the report shows, with its printed summary;
#   failures/*.png, failures/failures.csv
#       the textbook methods' failures beside the library's renders (report/failures);
#   precision.csv, precision_time_vs_error.svg, convergence.csv, convergence.svg, precision.txt
#       the accuracy study (cargo run --release --features studies --example precision);
#   nee_efficiency.csv, nee_efficiency.svg
#       emitters sampled or not (cargo run --release --features studies --example nee_efficiency);
#   renders/cornell_box.png, renders/dragon.png, cli/*.txt, ../data/tiles.csv
#       scene files rendered and checked by the raytrace binary (the dragon and its tiles only if
#       tools/fetch_meshes.sh has fetched it; otherwise the committed figure stays);
#   renders/materials.png, renders/environment.png, bsdf_chi2.csv
#       Part II's figures (report/tools/beyond.sh);
#   build-info.csv
#       the machine, compiler, build flags and commit the figures were made with.
set -euo pipefail
cd "$(dirname "$0")/.."

TYPST_VERSION=0.15.2
VENV=report/.venv
FIG=report/figures
DATA=report/data

# The examples and the widths the report shows them at (heights follow each scene's aspect;
# every other option is the example's default).
EXAMPLES=(
    "four_mirrors 800"
    "matte_spheres 800"
    "glass 800"
    "plane_and_triangles 800"
    "point_lights 800"
    "random_spheres 400"
)

usage() { sed -n '2,14s/^# \{0,1\}//p' "$0"; }

figures=false
data=false
check=false
for arg in "$@"; do
    case "$arg" in
        --figures) figures=true; data=true ;;
        --data) data=true ;;
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
    cargo build --release --features studies --examples --quiet
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

    echo "== emitters sampled or not (examples/nee_efficiency)"
    "target/release/examples/nee_efficiency" --out "$FIG" | tee "$FIG/nee_efficiency.txt"

    echo "== scene files through the raytrace binary"
    cargo build --release --bin raytrace --quiet
    mkdir -p "$FIG/cli"
    local rt=target/release/raytrace
    "$rt" check scenes/cornell_box.toml >"$FIG/cli/cornell_box-check.txt"
    "$rt" check scenes/random_spheres.toml >"$FIG/cli/random_spheres-check.txt"
    "$rt" render scenes/cornell_box.toml --quiet --out "$tmp/cornell_box.png" | sed "s|$tmp/|report/figures/renders/|" \
        | tee "$FIG/cli/cornell_box-render.txt"
    cp "$tmp/cornell_box.png" "$FIG/renders/cornell_box.png"
    if [ -f assets/meshes/dragon_vrip_res2.ply ]; then
        local dragon=(scenes/dragon.toml --width 600 --spp 32 --quiet)
        "$rt" check scenes/dragon.toml >"$FIG/cli/dragon-check.txt"
        "$rt" render "${dragon[@]}" --out "$tmp/dragon.png" | sed "s|$tmp/|report/figures/renders/|" \
            | tee "$FIG/cli/dragon-render.txt"
        # The same render as four tiles in four processes, merged: the same bytes?
        echo "tile,command,output" >"$DATA/tiles.csv"
        for k in 1 2 3 4; do
            out=$("$rt" render "${dragon[@]}" --tile "$k/4" --out "$tmp/dragon-$k.rtile")
            echo "$k,\"raytrace render ${dragon[*]} --tile $k/4 --out dragon-$k.rtile\",\"${out//$tmp\//}\"" >>"$DATA/tiles.csv"
        done
        "$rt" merge "$tmp"/dragon-[1-4].rtile --out "$tmp/merged.png" >/dev/null
        if cmp -s "$tmp/merged.png" "$tmp/dragon.png"; then same=identical; else same=different; fi
        echo "merged,\"raytrace merge dragon-1.rtile … dragon-4.rtile --out merged.png; cmp merged.png dragon.png\",$same" >>"$DATA/tiles.csv"
        cp "$tmp/dragon.png" "$FIG/renders/dragon.png"
    else
        echo "   (no assets/meshes/dragon_vrip_res2.ply: bash tools/fetch_meshes.sh; the committed dragon stays)"
    fi

    echo "== timings (report/tools/speed.py: interleaved runs of the examples)"
    "$VENV/bin/python" report/tools/speed.py --out "$DATA/speed.csv"

    echo "== enum against trait objects (criterion: cargo bench -p raytrace-benches --bench render -- dispatch)"
    cargo bench --quiet -p raytrace-benches --bench render -- dispatch --warm-up-time 1 --measurement-time 3 >/dev/null
    "$VENV/bin/python" - "$DATA/dispatch.csv" <<'PY'
import csv, glob, json, os, sys
rows = []
for b in sorted(glob.glob("target/criterion/dispatch/*/*/new/benchmark.json")):
    meta = json.load(open(b))
    est = json.load(open(os.path.join(os.path.dirname(b), "estimates.json")))
    scalar, path = meta["function_id"].split("/")
    rows.append({"scalar": scalar, "path": path, "scene": meta["value_str"],
                 "mean_ms": f"{est['mean']['point_estimate'] / 1e6:.3f}",
                 "ci_low_ms": f"{est['mean']['confidence_interval']['lower_bound'] / 1e6:.3f}",
                 "ci_high_ms": f"{est['mean']['confidence_interval']['upper_bound'] / 1e6:.3f}"})
if len(rows) != 8:
    sys.exit(f"dispatch.csv: expected 8 criterion results, found {len(rows)}")
with open(sys.argv[1], "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
print(f"wrote {sys.argv[1]}")
PY

    echo "== the tests, counted (cargo test -- --list)"
    # (The list goes through a file: `python -` reads its script from stdin.)
    cargo test -- --list >"$tmp/tests.txt" 2>&1
    "$VENV/bin/python" - "$tmp/tests.txt" "$DATA/tests.csv" <<'PY'
import csv, re, sys
target, counts = None, {}
for line in open(sys.argv[1], encoding="utf-8"):
    m = re.match(r"\s*Running (?:unittests )?(\S+)", line)
    if m:
        target = m.group(1)
        continue
    m = re.match(r"\s*Doc-tests (\S+)", line)
    if m:
        target = "doc-tests"
        continue
    if target and line.rstrip().endswith(": test"):
        # The integration tests are two crates: count them by topic (top-level module).
        key = target
        m = re.match(r"tests/(it|files)/", target)
        if m:
            key = m.group(0) + line.strip().split("::")[0]
        counts[key] = counts.get(key, 0) + 1
if not counts:
    sys.exit("tests.csv: no test listed (see " + sys.argv[1] + ")")
with open(sys.argv[2], "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["target", "tests"])
    for t, n in sorted(counts.items()):
        w.writerow([t, n])
print(f"wrote {sys.argv[2]}: {sum(counts.values())} tests in {len(counts)} targets")
PY

    echo "== Part II's figures (report/tools/beyond.sh)"
    bash report/tools/beyond.sh

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

# The data made outside report/ that the report reads, as "source copy" pairs.
COPIES=(
    "bench/results/scale.csv $DATA/scale.csv"
    "bench/results/scale.md $DATA/scale.md"
    "validate/results/comparison.csv $DATA/comparison.csv"
    "validate/results/comparison.md $DATA/comparison.md"
    "validate/results/furnace.csv $DATA/furnace.csv"
    "validate/results/fresnel_probe.csv $DATA/fresnel_probe.csv"
    "validate/results/foreign/comparison.csv $DATA/foreign.csv"
    "validate/results/foreign/comparison.md $DATA/foreign.md"
    "validate/results/foreign/png/foreign-veach_mis-f64.png $DATA/foreign-veach_mis.png"
    "validate/results/bench/bench.csv $DATA/mitsuba_bench.csv"
    "bench/results/book.csv $DATA/book.csv"
    "bench/results/book.md $DATA/book.md"
    "bench/results/equal_time.csv $DATA/equal_time.csv"
    "bench/results/equal_time.md $DATA/equal_time.md"
)

copy_data() {
    mkdir -p "$DATA"
    # provenance.csv: each copy's source and the commit that last committed it (results whose
    # own text names no commit are quoted with this one).
    echo "copy,source,committed_at" >"$DATA/provenance.csv"
    for pair in "${COPIES[@]}"; do
        read -r src dst <<<"$pair"
        if [ -f "$src" ]; then cp "$src" "$dst"; else echo "warning: $src is missing; $dst kept" >&2; fi
        echo "${dst#"$DATA"/},$src,$(git log -1 --format=%h -- "$src" 2>/dev/null)" >>"$DATA/provenance.csv"
    done
    python3 report/tools/modules.py "$DATA"
}

# Warnings only: the PDF is still built from what is committed.
check_data() {
    for pair in "${COPIES[@]}"; do
        read -r src dst <<<"$pair"
        if [ -f "$src" ] && ! cmp -s "$src" "$dst"; then
            echo "warning: $dst differs from $src: bash report/build.sh --data takes the new one" >&2
        fi
    done
    local tmp
    tmp=$(mktemp -d)
    python3 report/tools/modules.py "$tmp" >/dev/null
    for f in modules.csv loc.csv; do
        cmp -s "$tmp/$f" "$DATA/$f" ||
            echo "warning: $DATA/$f no longer matches src/: bash report/build.sh --data remakes it" >&2
    done
    rm -rf "$tmp"
    # Is the commit a result was made at older than the last change to the code it depicts?
    git rev-parse --git-dir >/dev/null 2>&1 || return 0
    # The last commit that changed the code under the given paths beyond comments (// or # )
    # and blank lines: a commit that only rewords comments leaves every result as it was. Test
    # files (`tests.rs`, `tests/`) are not the code a result depicts.
    last_code() {
        local c
        set -- "$@" ':(exclude,glob)**/tests.rs' ':(exclude,glob)**/tests/**'
        for c in $(git log --format=%h -- "$@" 2>/dev/null); do
            if git show --format= --unified=0 "$c" -- "$@" | grep -E '^[+-]' | grep -vE '^(\+\+\+|---) ' |
                grep -qvE '^[+-][[:space:]]*(//.*|#( .*)?)?$'; then
                echo "$c"
                return
            fi
        done
    }
    stale() { # $1 what, $2 its commit, $3 the command that remakes it, then the paths it depicts
        local what=$1 made=$2 remake=$3 code
        shift 3
        code=$(last_code "$@")
        if [ -z "$code" ]; then
            return
        elif [ -z "$made" ]; then
            echo "warning: $what names no commit" >&2
        elif ! git cat-file -e "$made^{commit}" 2>/dev/null; then
            echo "warning: $what was made at $made, a commit this clone does not have" >&2
        elif ! git merge-base --is-ancestor "$code" "$made" 2>/dev/null; then
            echo "warning: $what was made at $made, before $code, the last commit that changed the code in $*: $remake" >&2
        fi
    }
    stale "report/figures (build-info.csv)" \
        "$(sed -n 's/^commit,\([0-9a-f]*\).*/\1/p' "$FIG/build-info.csv")" "bash report/build.sh --figures" \
        src examples report/failures
    grep -q "with uncommitted changes" "$FIG/build-info.csv" &&
        echo "warning: report/figures were made from uncommitted code" >&2
    stale "$DATA/scale.csv (scale.md)" \
        "$(grep -o 'commit `[0-9a-f]*`' "$DATA/scale.md" | head -1 | tr -d '`' | cut -d' ' -f2)" \
        "python3 bench/scale.py, then bash report/build.sh --data" src examples/scale bench/scale.py bench/embree
    stale "$DATA/comparison.csv (comparison.md)" \
        "$(grep -o 'Commit `[0-9a-f]*`' "$DATA/comparison.md" | head -1 | tr -d '`' | cut -d' ' -f2)" \
        "bash validate/run.sh, then bash report/build.sh --data" src 'validate/*.py' validate/run.sh validate/scenes
    stale "$DATA/foreign.csv (foreign.md)" \
        "$(grep -o 'Commit `[0-9a-f]*`' "$DATA/foreign.md" | head -1 | tr -d '`' | cut -d' ' -f2)" \
        "bash validate/run.sh, then bash report/build.sh --data" src 'validate/*.py' validate/foreign
    stale "$DATA/book.csv (book.md)" \
        "$(grep -o 'Ours: commit [0-9a-f]*' "$DATA/book.md" | head -1 | cut -d' ' -f3)" \
        "python3 bench/book.py, then bash report/build.sh --data" src examples/random_spheres.rs bench/book.py bench/book
    grep -q "with uncommitted changes" "$DATA/book.md" &&
        echo "warning: $DATA/book.md was made from uncommitted code" >&2
    # The equal-time study's results name no commit: the one that committed them stands for it.
    stale "$DATA/equal_time.csv" "$(sed -n 's/^equal_time.csv,[^,]*,//p' "$DATA/provenance.csv")" \
        "cargo run --release --features studies --example equal_time, then bash report/build.sh --data" src examples/equal_time
    return 0
}

if $data; then
    echo "== copying the data made outside report/ into $DATA"
    copy_data
fi

if $figures; then
    start=$SECONDS
    regenerate_figures
    echo "== figures regenerated in $((SECONDS - start)) s"
fi

check_data

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
