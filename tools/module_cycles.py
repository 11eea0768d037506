#!/usr/bin/env python3
"""Lists import circles between the modules of each crate of the workspace: module A uses
module B (`use crate::b`, `crate::b::f()`, `super::b`) and B, directly or through others, uses
A. A module and the modules nested in it count as one (a child naming its parent's items is no
circle). Exit code 1 when a circle exists (test.sh runs it)."""

import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PATH = re.compile(r"\b(crate|super|self)((?:::[A-Za-z_][A-Za-z0-9_]*)+)")
GROUP = re.compile(r"\b(crate|super|self)::\{([^}]*)\}")


def module_of(src: Path, file: Path) -> tuple:
    parts = list(file.relative_to(src).with_suffix("").parts)
    if parts[-1] in ("mod", "lib", "main"):
        parts = parts[:-1]
    return tuple(parts)


def resolve(modules: set, base: tuple, names: list) -> tuple | None:
    """The deepest module named by `base` + `names`, other than `base` itself."""
    best = None
    for i in range(1, len(names) + 1):
        candidate = base + tuple(names[:i])
        if candidate in modules:
            best = candidate
    return best


def nested(a: tuple, b: tuple) -> bool:
    """Whether one module contains the other (a parent and its children are one unit here)."""
    return a[: len(b)] == b or b[: len(a)] == a


def edges_of(modules: set, file: Path, module: tuple) -> set:
    text = re.sub(r"//[^\n]*", "", file.read_text(encoding="utf-8"))
    cut = text.find("#[cfg(test)]")
    if cut >= 0:
        text = text[:cut]
    paths = [(m.group(1), m.group(2)) for m in PATH.finditer(text)]
    for m in GROUP.finditer(text):
        for item in m.group(2).split(","):
            item = item.strip().split(" as ")[0].split("::{")[0]
            if item:
                paths.append((m.group(1), "::" + item.replace(" ", "")))
    found = set()
    for anchor, rest in paths:
        base = {"crate": (), "super": module[:-1], "self": module}[anchor]
        target = resolve(modules, base, [n for n in rest.split("::") if n])
        if target is not None and not nested(target, module):
            found.add(target)
    return found


def cycles(crate: Path) -> list:
    src = crate / "src"
    files = sorted(src.rglob("*.rs"))
    modules = {module_of(src, f): f for f in files}
    graph = {m: edges_of(set(modules), f, m) for m, f in modules.items()}
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                out.append(sorted("::".join(c) or "(root)" for c in component))

    sys.setrecursionlimit(10000)
    for v in graph:
        if v not in index:
            visit(v)
    return out


def main() -> int:
    found = 0
    for crate in sorted((ROOT / "crates").iterdir()):
        if not (crate / "src").is_dir():
            continue
        for circle in cycles(crate):
            found += 1
            print(f"{crate.name}: " + " ↔ ".join(circle))
    if found:
        print(f"{found} import circle(s)", file=sys.stderr)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
