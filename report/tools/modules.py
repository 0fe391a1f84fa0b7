#!/usr/bin/env python3
"""The library's module graph and line counts, for the report (stdlib only).

    python3 report/tools/modules.py [DIR]    writes DIR/modules.csv and DIR/loc.csv
                                             (DIR: report/data by default)

modules.csv: one row per top-level module of src/ (the `mod` lines of src/lib.rs):
  module, files, lines (all lines of its files, tests and docs included),
  layer (0 for a module that uses no other; else one more than the highest it uses),
  position (its place in its layer, 0 to 1, for the diagram),
  uses (the modules it names in `use crate::...` lines or `crate::module::` paths outside its
  comments and unit tests, space-separated),
  uses_direct (those uses no chain of other uses implies: the transitive reduction).
loc.csv: lines per part of the repository (src without the binary, the binary, tests,
  examples, benches): all lines as `wc -l` counts them, and code_lines, those that are neither
  blank nor a comment nor inside a file's `#[cfg(test)] mod tests`.
"""
import csv
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
SRC = ROOT / "src"
OUT = ROOT / "report" / "data"


def modules():
    lib = (SRC / "lib.rs").read_text(encoding="utf-8")
    return re.findall(r"^\s*(?:pub\s+)?mod\s+(\w+);", lib, re.M)


def files_of(module):
    files = []
    if (SRC / f"{module}.rs").exists():
        files.append(SRC / f"{module}.rs")
    if (SRC / module).is_dir():
        files += sorted((SRC / module).rglob("*.rs"))
    return files


def without_tests(text):
    # Unit tests may use anything: cut each file at its test module.
    cut = re.search(r"^#\[cfg\(test\)\]\s*\n\s*mod tests", text, re.M)
    return text[: cut.start()] if cut else text


def used(text, known):
    """The modules named by the `use crate::...;` statements of `text`."""
    found = set()
    for stmt in re.findall(r"\buse\s+crate::(.*?);", text, re.S):
        stmt = re.sub(r"//[^\n]*", "", stmt).strip()
        if stmt.startswith("{"):
            # use crate::{a::X, b, c::{..}}: the first name of each top-level item
            body, depth, item, items = stmt[1:], 0, "", []
            for ch in body:
                if ch == "{":
                    depth += 1
                elif ch == "}":
                    if depth == 0:
                        break
                    depth -= 1
                if ch == "," and depth == 0:
                    items.append(item)
                    item = ""
                else:
                    item += ch
            items.append(item)
            names = [re.match(r"\s*(\w+)", i).group(1) for i in items if re.match(r"\s*(\w+)", i)]
        else:
            names = [re.match(r"(\w+)", stmt).group(1)]
        found.update(n for n in names if n in known)
    # Paths written out in code (`impl Float for crate::double_double::DoubleDouble`), not in
    # comments or documentation.
    code = "\n".join(l for l in text.splitlines() if not l.strip().startswith("//"))
    found.update(n for n in re.findall(r"\bcrate::(\w+)::", code) if n in known)
    return found


def lines(path):
    return path.read_text(encoding="utf-8").count("\n")


def code_lines(path):
    """Lines of code: not blank, not a comment, not in the file's unit-test module."""
    text = without_tests(path.read_text(encoding="utf-8"))
    return sum(1 for l in text.splitlines() if l.strip() and not l.strip().startswith("//"))


def main():
    global OUT
    if len(sys.argv) > 1:
        OUT = pathlib.Path(sys.argv[1])
    mods = modules()
    known = set(mods)
    uses, counts = {}, {}
    for m in mods:
        fs = files_of(m)
        counts[m] = (len(fs), sum(lines(f) for f in fs))
        u = set()
        for f in fs:
            u |= used(without_tests(f.read_text(encoding="utf-8")), known)
        u.discard(m)
        uses[m] = u
    layer = {}

    def depth(m, seen=()):
        if m in layer:
            return layer[m]
        if m in seen:
            raise SystemExit(f"modules.py: a cycle through {' -> '.join(seen + (m,))}")
        d = 1 + max((depth(u, seen + (m,)) for u in uses[m]), default=-1)
        layer[m] = d
        return d

    for m in mods:
        depth(m)
    # Transitive reduction: the uses not implied by a chain of other uses (what a diagram draws).
    def reach(m):
        seen, todo = set(), list(uses[m])
        while todo:
            u = todo.pop()
            if u not in seen:
                seen.add(u)
                todo.extend(uses[u])
        return seen

    reduced = {m: {u for u in uses[m] if not any(u in reach(v) for v in uses[m] if v != u)} for m in mods}
    # An order within each layer for the diagram: bottom-up, each module at the mean position
    # of the modules it uses (the barycentre heuristic), so that fewer arrows cross.
    # Modules that use none are spread evenly; the others go to that mean, then are pushed
    # apart to at least GAP and kept inside [0.06, 0.94].
    GAP = 0.15
    pos = {}
    for d in range(max(layer.values()) + 1):
        row = [m for m in mods if layer[m] == d]
        bary = {m: sum(pos[u] for u in reduced[m]) / len(reduced[m]) for m in row if reduced[m]}
        row.sort(key=lambda m: (bary.get(m, -1), m))
        if not bary:
            for i, m in enumerate(row):
                pos[m] = (i + 0.5) / len(row)
            continue
        xs = [bary.get(m, 0.5) for m in row]
        for _ in range(50):
            for i in range(1, len(xs)):
                if xs[i] - xs[i - 1] < GAP:
                    mid = (xs[i] + xs[i - 1]) / 2
                    xs[i - 1], xs[i] = mid - GAP / 2, mid + GAP / 2
            shift = max(0.0, 0.06 - xs[0]) - max(0.0, xs[-1] - 0.94)
            xs = [x + shift for x in xs]
        for m, x in zip(row, xs):
            pos[m] = x
    OUT.mkdir(parents=True, exist_ok=True)
    with open(OUT / "modules.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["module", "files", "lines", "layer", "position", "uses", "uses_direct"])
        for m in sorted(mods, key=lambda m: (layer[m], pos[m])):
            w.writerow([m, counts[m][0], counts[m][1], layer[m], f"{pos[m]:.4f}", " ".join(sorted(uses[m])),
                        " ".join(sorted(reduced[m]))])
    parts = [
        ("library (src/, without src/bin)", [p for p in SRC.rglob("*.rs") if "bin" not in p.relative_to(SRC).parts]),
        ("command-line renderer (src/bin)", list((SRC / "bin").rglob("*.rs"))),
        ("tests (tests/)", list((ROOT / "tests").rglob("*.rs"))),
        ("examples (examples/)", list((ROOT / "examples").rglob("*.rs"))),
        ("benches (benches/)", list((ROOT / "benches").rglob("*.rs"))),
    ]
    with open(OUT / "loc.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["part", "files", "lines", "code_lines"])
        for name, fs in parts:
            w.writerow([name, len(fs), sum(lines(p) for p in fs), sum(code_lines(p) for p in fs)])
    print(f"wrote {OUT / 'modules.csv'} ({len(mods)} modules) and {OUT / 'loc.csv'}")


if __name__ == "__main__":
    main()
