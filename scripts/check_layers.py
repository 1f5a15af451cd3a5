#!/usr/bin/env python3
"""Layer check of src/ (docs/architecture.md "Layers"): every #include "folder/file" in a file
under src/ must name its own folder or one of a lower layer; the folder-level include graph must
have no cycle. Exit 0 when clean, 1 with every offending include listed (file:line), 2 on a
folder that the layer order does not know.

Usage: scripts/check_layers.py [--graph] [ROOT]
  --graph  also print the folder-level include graph (edges with include counts)
"""
import os
import re
import sys

# Bottom to top; folders on one line are one layer and must not include each other. A subfolder
# listed here (contact/laws) is a node of its own, apart from its parent.
LAYERS = [
    ["core"],
    ["geometry"],
    ["analysis"],
    ["state"],
    ["physics"],
    ["model"],
    ["contact/laws"],
    ["parallel"],
    ["io"],
    ["generate"],
    ["neighbor"],
    ["scene"],
    ["contact", "field", "thermal"],
    ["interact"],
    ["integrate"],
    ["output"],
    ["sim"],
    ["check"],
    ["tools"],
    ["validate"],
    ["python"],
    ["cli"],
]
RANK = {folder: level for level, names in enumerate(LAYERS) for folder in names}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def node(path):
    """The layer node of a path relative to src/: its listed subfolder, else its top folder."""
    parts = path.split("/")
    for k in range(len(parts) - 1, 0, -1):
        if "/".join(parts[:k]) in RANK:
            return "/".join(parts[:k])
    return parts[0]


def scan(src):
    """Yields (node, file, line number, included node) for every quoted folder include."""
    for folder in sorted(os.listdir(src)):
        top = os.path.join(src, folder)
        if not os.path.isdir(top):
            continue
        for dirpath, _, files in os.walk(top):
            for name in sorted(files):
                if not name.endswith((".hpp", ".cpp", ".h")):
                    continue
                path = os.path.join(dirpath, name)
                own = node(os.path.relpath(path, src).replace(os.sep, "/"))
                with open(path, encoding="utf-8") as f:
                    for number, text in enumerate(f, 1):
                        m = INCLUDE.match(text)
                        if m and "/" in m.group(1) and os.path.isdir(os.path.join(src, m.group(1).split("/")[0])):
                            yield own, path, number, node(m.group(1))


def cycles(edges):
    """The strongly connected components with more than one folder (Tarjan)."""
    index, low, stack, on, found, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                found.append(sorted(comp))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return found


def main(argv):
    graph = "--graph" in argv
    args = [a for a in argv if a != "--graph"]
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    src = os.path.join(root, "src")
    edges, counts, upward, unknown = {}, {}, [], set()
    for folder, path, number, target in scan(src):
        if target == folder:
            continue
        for f in (folder, target):
            if f not in RANK:
                unknown.add(f)
        edges.setdefault(folder, set()).add(target)
        counts[(folder, target)] = counts.get((folder, target), 0) + 1
        if folder in RANK and target in RANK and RANK[target] >= RANK[folder]:
            upward.append((os.path.relpath(path, root), number, folder, target))
    if graph:
        for (a, b), n in sorted(counts.items()):
            print(f"  {a} -> {b} ({n})")
    if unknown:
        print("layers: folders missing from the layer order (scripts/check_layers.py LAYERS, "
              "docs/architecture.md): " + ", ".join(sorted(unknown)))
        return 2
    loops = cycles(edges)
    for path, number, folder, target in upward:
        same = RANK[target] == RANK[folder]
        print(f"{path}:{number}: {folder}/ includes {target}/, "
              f"{'a folder of its own layer' if same else 'a higher layer'}")
    for comp in loops:
        print("layers: folder-level include cycle among " + ", ".join(comp))
    edge_pairs = {(a, b) for (a, b) in counts}
    print(f"layers: {len(edge_pairs)} folder-level edges, "
          f"{len({(f, t) for _, _, f, t in upward})} against the layer order, {len(loops)} cycles")
    return 1 if upward or loops else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
