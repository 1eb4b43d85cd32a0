#!/usr/bin/env python3
"""The graph of lib/'s modules (its first-level folders) from their #include lines, and its cycles.

    python3 test/module_graph.py [LIB_DIR]          # exit 1 and name the cycles if there are any
    python3 test/module_graph.py --graph [LIB_DIR]  # each module and the modules it includes, lowest first

A module A depends on B when a file of A (tests beside the code left out: they may use anything) includes
"B/...". Modules must form a directed graph without cycles (a type two modules need lives in
the lower one); a cycle is printed with one include that makes each of its edges.
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def module_edges(lib):
    """{module: {dependency: 'file -> included'}} for every module of lib."""
    edges = {}
    for module in sorted(os.listdir(lib)):
        folder = os.path.join(lib, module)
        if not os.path.isdir(folder):
            continue
        deps = edges.setdefault(module, {})
        for root, _, files in os.walk(folder):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp")) or name.endswith("_test.cpp") or name == "testing.h":
                    continue
                path = os.path.join(root, name)
                with open(path, encoding="utf-8") as f:
                    for included in INCLUDE.findall(f.read()):
                        target = included.split("/")[0]
                        if "/" in included and target != module and os.path.isdir(os.path.join(lib, target)):
                            deps.setdefault(target, os.path.relpath(path, lib) + " -> " + included)
    return edges


def strongly_connected(edges):
    """Tarjan's strongly connected components, each a sorted list."""
    index, low, stack, on_stack, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            out.append(sorted(component))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


def layers(edges):
    """Modules by depth: 0 includes no other module, n includes some of depth n-1 and none deeper."""
    depth = {}

    def of(v, seen=()):
        if v not in depth:
            depth[v] = 1 + max((of(w, seen + (v,)) for w in edges[v] if w not in seen), default=-1)
        return depth[v]

    for v in edges:
        of(v)
    return depth


def main(argv):
    show = "--graph" in argv
    args = [a for a in argv if a != "--graph"]
    lib = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib")
    edges = module_edges(lib)
    cycles = [c for c in strongly_connected(edges) if len(c) > 1]
    if show:
        depth = layers(edges)
        for v in sorted(edges, key=lambda m: (depth[m], m)):
            print(f"{v:11} {depth[v]}  {' '.join(sorted(edges[v], key=lambda m: (depth[m], m)))}")
    for cycle in cycles:
        print("include cycle between modules: " + ", ".join(cycle), file=sys.stderr)
        for a in cycle:
            for b, why in sorted(edges[a].items()):
                if b in cycle:
                    print(f"  {a} -> {b}: {why}", file=sys.stderr)
    return 1 if cycles else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
