#!/usr/bin/env python3
"""Static include walk over the product's sources (lib/, solvers/, tools/; not tests or bench).

Fails (exit 1, one line per finding) when
  - the folders include each other in a cycle (a folder is the directory of a file: an include
    of "lib/scenario/x.hpp" from lib/engines/settings/y.cpp is an edge between those two), or
  - a pure integrator folder (INTEGRATORS) or the solvers include a layer above them (FORBIDDEN):
    the integrators are numerics, below the scenario files, the metrics, the CLI and the
    reference engines.
Usage: check_includes.py [REPOSITORY]   (default: the checkout this script is in)
"""
import pathlib
import re
import sys

ROOTS = ("lib", "solvers", "tools")
SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".cc"}
# Folders that hold pure numerics, and the folders they must not include.
INTEGRATORS = ("lib/engines/moreau_jean", "lib/engines/event_driven", "solvers")
FORBIDDEN = ("lib/scenario", "lib/metrics", "tools/cli", "tools/adapters", "tools/engines",
             "lib/engines/reference", "lib/engines/settings")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def folder_edges(repository):
    """{folder: {included folder: example 'file -> include'}} over the product's sources."""
    edges = {}
    for root in ROOTS:
        for path in sorted((repository / root).rglob("*")):
            if path.suffix not in SOURCE_SUFFIXES or not path.is_file():
                continue
            source = path.relative_to(repository)
            folder = source.parent.as_posix()
            for included in INCLUDE.findall(path.read_text(encoding="utf-8", errors="replace")):
                target = pathlib.PurePosixPath(included)
                if target.parts[0] not in ROOTS or not (repository / target).exists():
                    continue  # a system or third-party header, or a path relative to the file
                target_folder = target.parent.as_posix()
                if target_folder != folder:
                    edges.setdefault(folder, {}).setdefault(
                        target_folder, f"{source.as_posix()} -> {included}")
    return edges


def strongly_connected(edges):
    """Tarjan's algorithm: the folder groups that reach each other (cycles), largest first."""
    index, low, stack, on_stack, groups = {}, {}, [], set(), []
    counter = [0]

    def visit(node):
        index[node] = low[node] = counter[0]
        counter[0] += 1
        stack.append(node)
        on_stack.add(node)
        for nxt in edges.get(node, {}):
            if nxt not in index:
                visit(nxt)
                low[node] = min(low[node], low[nxt])
            elif nxt in on_stack:
                low[node] = min(low[node], index[nxt])
        if low[node] == index[node]:
            group = []
            while True:
                top = stack.pop()
                on_stack.discard(top)
                group.append(top)
                if top == node:
                    break
            if len(group) > 1:
                groups.append(sorted(group))

    sys.setrecursionlimit(10000)
    for node in sorted(edges):
        if node not in index:
            visit(node)
    return sorted(groups, key=len, reverse=True)


def inside(folder, prefix):
    return folder == prefix or folder.startswith(prefix + "/")


def main():
    repository = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else
                              pathlib.Path(__file__).resolve().parents[2])
    edges = folder_edges(repository)
    findings = []
    for group in strongly_connected(edges):
        members = set(group)
        witnesses = [example for folder in group for target, example in edges[folder].items()
                     if target in members]
        findings.append("include cycle between folders " + ", ".join(group) + ": " +
                        "; ".join(witnesses))
    for folder, targets in sorted(edges.items()):
        if not any(inside(folder, pure) for pure in INTEGRATORS):
            continue
        for target, example in sorted(targets.items()):
            if any(inside(target, layer) for layer in FORBIDDEN):
                findings.append(f"integrator folder {folder} includes {target}: {example}")
    for finding in findings:
        print("check_includes: " + finding)
    folders = len(set(edges) | {t for ts in edges.values() for t in ts})
    print(f"check_includes: {folders} folders, "
          f"{sum(len(t) for t in edges.values())} folder-level includes, {len(findings)} findings")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
