#!/usr/bin/env python3
"""The size of the house (issue 33): per source module, its largest file (lines) and its longest
function (lines from the signature to the closing brace, by Universal Ctags' end: field), and every
function over a limit. For the closing note and for a newcomer looking for what to split first.

    scripts/code_sizes.py [--limit 60] [ROOT]

The limit of the style guide exempts data tables: the functions in DATA_TABLES, each with its
reason, are marked as such and listed apart from the functions over the limit.
"""
import argparse
import os
import subprocess
import sys

MODULES = ["common", "theory", "hydro", "md", "run", "kinetic", "compare", "cli", "python"]
SUFFIXES = (".cpp", ".hpp")
# (file, function) -> why it is a data table rather than code to split.
DATA_TABLES = {
    ("theory/observables.cpp", "observable_catalogue"):
        "the observable catalogue: one aggregate initializer, an entry of positional fields per observable",
}


def sources(root, module):
    folder = os.path.join(root, module)
    return sorted(os.path.join(module, name) for name in os.listdir(folder) if name.endswith(SUFFIXES))


def functions(root, files):
    """[(lines, file, name, first line)] of every function Universal Ctags finds in `files`."""
    out = subprocess.run(["ctags", "--languages=C++", "--c++-kinds=f", "--fields=+ne", "-o", "-", *files],
                         cwd=root, capture_output=True, text=True, check=True).stdout
    found = []
    for line in out.splitlines():
        fields = line.split("\t")
        extra = dict(f.split(":", 1) for f in fields[3:] if ":" in f)
        if "line" in extra and "end" in extra:
            first, last = int(extra["line"]), int(extra["end"])
            name = fields[0] if not fields[0].startswith("__anon") else "(lambda)"
            found.append((last - first + 1, fields[1], name, first))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", nargs="?", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    parser.add_argument("--limit", type=int, default=60, help="list functions longer than this (lines)")
    args = parser.parse_args()
    over = []
    print("| module | largest file (lines) | longest function (lines) |\n|---|---|---|")
    for module in MODULES:
        files = sources(args.root, module)
        sizes = [(sum(1 for _ in open(os.path.join(args.root, f), encoding="utf-8")), f) for f in files]
        lines, largest = max(sizes)
        found = functions(args.root, files)
        length, where, name, first = max(found)
        table = ", data table" if (where, name) in DATA_TABLES else ""
        print(f"| {module} | {largest} ({lines}) | {name} in {where}:{first} ({length}{table}) |")
        over += [f for f in found if f[0] > args.limit]
    tables = [f for f in over if (f[1], f[2]) in DATA_TABLES]
    code = [f for f in over if (f[1], f[2]) not in DATA_TABLES]
    print(f"\nfunctions over {args.limit} lines outside data tables: {len(code)}")
    for length, where, name, first in sorted(code, reverse=True):
        print(f"  {length:4d}  {name}  {where}:{first}")
    print(f"data tables over {args.limit} lines: {len(tables)}")
    for length, where, name, first in sorted(tables, reverse=True):
        print(f"  {length:4d}  {name}  {where}:{first}  ({DATA_TABLES[(where, name)]})")


if __name__ == "__main__":
    sys.exit(main())
