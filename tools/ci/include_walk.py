#!/usr/bin/python3
"""Static include walk of the sources (lib, solvers, tools): fails on layering mistakes.

Two rules, on the project's own #include "..." lines (paths from the repository root):

1. No folder-level include cycle: with one node per folder and an edge A -> B whenever a file
   of A includes a file of B, the graph has no cycle. Each cycle is printed with the includes
   that make its edges.
2. The integrators stay pure numerics: no file of the Moreau-Jean or event-driven integrator
   folders or of solvers/ reaches, directly or through other headers, the scenario, metrics,
   command-line or engine (settings, adapters, registry) code. Each such include is printed
   with the chain that leads to it.

Usage: include_walk.py [REPOSITORY_ROOT]   (default: two folders above this script)
Exit status 0 when both rules hold, 1 when one fails, 2 on bad usage.
"""
import os
import re
import sys

SOURCE_ROOTS = ("lib", "solvers", "tools")
SUFFIXES = (".hpp", ".cpp", ".h", ".cc")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)

# Folders of the integrators and what they must not reach (path prefixes, with a slash).
INTEGRATORS = ("lib/engines/moreau_jean/", "lib/engines/event_driven/", "solvers/")
FORBIDDEN = {
    "lib/scenario/": "scenario",
    "lib/metrics/": "metrics",
    "tools/cli/": "command line",
    "tools/engines/": "engine",
    "tools/adapters/": "reference engine",
    "lib/engines/settings/": "engine settings",
    "lib/engines/reference/": "reference engine",
}


def read_includes(root):
    """{file: [(line number, included file)]} for every source file and its in-tree includes."""
    includes = {}
    for top in SOURCE_ROOTS:
        for folder, _, names in os.walk(os.path.join(root, top)):
            for name in names:
                if not name.endswith(SUFFIXES):
                    continue
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, root)
                with open(path, encoding="utf-8", errors="replace") as f:
                    text = f.read()
                found = []
                for m in INCLUDE.finditer(text):
                    target = m.group(1)
                    if os.path.isfile(os.path.join(root, target)):
                        found.append((text.count("\n", 0, m.start()) + 1, target))
                includes[rel] = found
    return includes


def folder_cycles(includes):
    """Strongly connected folder groups of more than one folder (Tarjan), with their edges."""
    edges = {}
    for source, targets in includes.items():
        a = os.path.dirname(source)
        for line, target in targets:
            b = os.path.dirname(target)
            if a != b:
                edges.setdefault(a, {}).setdefault(b, []).append(f"{source}:{line}: {target}")
    index, low, stack, on_stack, groups = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in edges.get(v, {}):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1:
                groups.append(sorted(group))

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    result = []
    for group in groups:
        members = set(group)
        lines = [site for a in group for b, sites in sorted(edges.get(a, {}).items())
                 if b in members for site in sites]
        result.append((group, lines))
    return result


def forbidden_reach(includes):
    """(integrator file, chain of includes, what it reaches) for every forbidden reach."""
    def forbidden(path):
        for prefix, what in FORBIDDEN.items():
            if path.startswith(prefix):
                return what
        return None

    problems = []
    for source in sorted(includes):
        if not source.startswith(INTEGRATORS):
            continue
        # Breadth-first through the includes, so the chain printed is a shortest one.
        parent = {source: None}
        queue = [source]
        while queue:
            current = queue.pop(0)
            for line, target in includes.get(current, []):
                if target in parent:
                    continue
                parent[target] = (current, line)
                what = forbidden(target)
                if what:
                    chain, node = [], target
                    while parent[node]:
                        previous, at = parent[node]
                        chain.append(f"{previous}:{at}: {node}")
                        node = previous
                    problems.append((source, what, list(reversed(chain))))
                else:
                    queue.append(target)
    return problems


def main(argv):
    if len(argv) > 2:
        print("usage: include_walk.py [REPOSITORY_ROOT]", file=sys.stderr)
        return 2
    root = argv[1] if len(argv) == 2 else os.path.join(os.path.dirname(__file__), "..", "..")
    if not os.path.isdir(os.path.join(root, "lib")):
        print(f"include walk: {root} is not the repository root (no lib/)", file=sys.stderr)
        return 2
    includes = read_includes(root)
    cycles = folder_cycles(includes)
    reaches = forbidden_reach(includes)
    for group, sites in cycles:
        print("include walk: folder-level include cycle among " + ", ".join(group) + ":")
        for site in sites:
            print("  " + site)
    for source, what, chain in reaches:
        print(f"include walk: integrator file {source} reaches {what} code:")
        for step in chain:
            print("  " + step)
    if cycles or reaches:
        return 1
    print(f"include walk: {len(includes)} files, no folder-level cycle, integrators pure")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
