#!/usr/bin/env python3
"""Checks that glint's folders stand in layers: a folder of src/glint/ includes only folders below it.

The order is the one docs/architecture.md states, in its block between the markers
`<!-- layers: bottom to top -->` and `<!-- end of layers -->` (one folder name a line, each line
`N. name — what it holds`). Every folder of src/glint/ must be listed there, and every
`#include "glint/<folder>/..."` in src/glint/ must go from a folder to one listed before it. A loop
between folders can therefore not pass either. Prints each violation with the file and line, and the
folder → folder graph with -v; exits 1 on a violation.

    python3 scripts/check_layers.py [--root DIR] [-v]
"""
import argparse
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"glint/([A-Za-z0-9_]+)/')
LAYER_LINE = re.compile(r'^\s*\d+\.\s+`?([A-Za-z0-9_]+)/?`?')


def documented_order(doc_path):
    text = open(doc_path, encoding="utf-8").read()
    start = text.find("<!-- layers: bottom to top -->")
    end = text.find("<!-- end of layers -->")
    if start < 0 or end < start:
        sys.exit(f"{doc_path}: no layer list between '<!-- layers: bottom to top -->' and '<!-- end of layers -->'")
    order = []
    for line in text[start:end].splitlines()[1:]:
        match = LAYER_LINE.match(line)
        if match:
            order.append(match.group(1))
    return order


def include_edges(source_root):
    """(from folder, to folder, file, line number) for every include of another folder."""
    edges = []
    for folder in sorted(os.listdir(source_root)):
        folder_path = os.path.join(source_root, folder)
        if not os.path.isdir(folder_path):
            continue
        for directory, _, files in os.walk(folder_path):
            for name in sorted(files):
                path = os.path.join(directory, name)
                with open(path, encoding="utf-8", errors="replace") as source:
                    for number, line in enumerate(source, 1):
                        match = INCLUDE.match(line)
                        if match and match.group(1) != folder:
                            edges.append((folder, match.group(1), path, number))
    return edges


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    parser.add_argument("-v", "--verbose", action="store_true")
    args = parser.parse_args()
    source_root = os.path.join(args.root, "src", "glint")
    doc = os.path.join(args.root, "docs", "architecture.md")
    order = documented_order(doc)
    rank = {name: i for i, name in enumerate(order)}
    problems = []
    if len(rank) != len(order):
        problems.append(f"{doc}: a folder is listed twice in the layers")
    folders = sorted(f for f in os.listdir(source_root) if os.path.isdir(os.path.join(source_root, f)))
    for folder in folders:
        if folder not in rank:
            problems.append(f"src/glint/{folder}/ is not in the layer list of {doc}: add it at its place")
    for name in order:
        if name not in folders:
            problems.append(f"{doc}: the layer '{name}' has no folder src/glint/{name}/")
    graph = {}
    for source, target, path, number in include_edges(source_root):
        graph.setdefault(source, set()).add(target)
        if source in rank and target in rank and rank[target] >= rank[source]:
            problems.append(f"{os.path.relpath(path, args.root)}:{number}: {source}/ includes {target}/, "
                            f"which is not below it (layers: {' < '.join(order)})")
        elif target not in rank and target in folders:
            pass  # reported above as an unlisted folder
    if args.verbose:
        for source in sorted(graph, key=lambda f: rank.get(f, -1)):
            print(f"{source} -> {', '.join(sorted(graph[source], key=lambda f: rank.get(f, -1)))}")
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        return 1
    print(f"layers: {len(folders)} folders, {sum(len(t) for t in graph.values())} folder-to-folder include "
          f"pairs, all downwards ({' < '.join(order)})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
