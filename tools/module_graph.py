#!/usr/bin/env python3
"""The library's module graph: which top-level module of src/ uses which.

    python3 tools/module_graph.py            print the graph (Mermaid) and check it
    python3 tools/module_graph.py --check    only check

A module uses another when any of its files names `crate::other` (a `use`, a path or a doc
link outside tests). Exits 1, naming the cycle, if the graph has one: every module then
stands on the ones below it and can be read after them.
"""
import pathlib
import re
import sys

SRC = pathlib.Path(__file__).resolve().parent.parent / "src"


def module_of(path: pathlib.Path) -> str:
    rel = path.relative_to(SRC).with_suffix("")
    return rel.parts[0]


def code_only(text: str) -> str:
    # Unit tests may use anything: cut each file at its test module.
    cut = re.search(r"^#\[cfg\(test\)\]\s*\nmod tests", text, re.M)
    text = text[: cut.start()] if cut else text
    return "\n".join(line for line in text.splitlines() if not line.lstrip().startswith("//"))


def graph() -> dict:
    edges = {}
    for path in sorted(SRC.rglob("*.rs")):
        me = module_of(path)
        if me == "lib":
            continue
        uses = set(re.findall(r"\bcrate::(\w+)", code_only(path.read_text())))
        # `super::x` inside a submodule stays inside its module.
        edges.setdefault(me, set()).update(u for u in uses if u != me)
    return edges


def cycle(edges: dict):
    state, stack = {}, []

    def visit(n):
        state[n] = "open"
        stack.append(n)
        for m in sorted(edges.get(n, ())):
            if state.get(m) == "open":
                return stack[stack.index(m):] + [m]
            if m not in state:
                found = visit(m)
                if found:
                    return found
        stack.pop()
        state[n] = "done"
        return None

    for n in sorted(edges):
        if n not in state:
            found = visit(n)
            if found:
                return found
    return None


def main() -> int:
    edges = graph()
    if "--check" not in sys.argv:
        print("graph BT")
        for n in sorted(edges):
            for m in sorted(edges[n]):
                print(f"    {n} --> {m}")
    found = cycle(edges)
    if found:
        print("module cycle: " + " -> ".join(found), file=sys.stderr)
        return 1
    print(f"module graph: {len(edges)} modules, no cycle", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
