#!/usr/bin/env python3
"""The layers of lrchain and their sizes: lines of public headers, private headers, sources (and the
generated part of them) and tests per layer, and the #include edges between layers.

    scripts/layer_sizes.py                 # the working tree
    scripts/layer_sizes.py --commit 2e2ebde  # a commit, read through git ls-tree / git cat-file

A public header is one under <layer>/include/ (or a folder include/ below the layer, as in
derivation/model_compiler/include/); every other header of the layer is private. A test file belongs
to the highest layer it includes (tests/python/ and python/tests belong to python). An edge A -> B
counts the #include "lrchain/..." or "derivation/..." lines of A's files that name a header of B.
"""
import argparse
import re
import subprocess
import sys
from pathlib import Path

LAYERS = ["lib", "derivation", "sim", "jobs", "cli", "python"]  # lowest first
HEADER = re.compile(r"\.(h|hpp|hh)(\.in)?$")
SOURCE = re.compile(r"\.(c|cc|cpp)$")
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]', re.M)


class Tree:
    """The files of the working tree or of one commit."""

    def __init__(self, root, commit=None):
        self.root = Path(root)
        self.commit = commit

    def git(self, *args, data=None):
        return subprocess.run(["git", "-C", str(self.root), *args], input=data, capture_output=True,
                              check=True).stdout

    def files(self):
        if self.commit:
            out = self.git("ls-tree", "-r", "--name-only", self.commit)
        else:
            out = self.git("ls-files", "--cached", "--others", "--exclude-standard")
        return [p for p in out.decode().splitlines() if p]

    def texts(self, paths):
        """{path: text} of `paths` (one git cat-file --batch for a commit)."""
        if not self.commit:
            result = {}
            for p in paths:
                f = self.root / p
                if f.is_file():
                    result[p] = f.read_text(errors="replace")
            return result
        request = "".join(f"{self.commit}:{p}\n" for p in paths).encode()
        out = self.git("cat-file", "--batch", data=request)
        result, pos = {}, 0
        for p in paths:
            end = out.index(b"\n", pos)
            header = out[pos:end].split()
            pos = end + 1
            if len(header) < 3 or header[1] == b"missing":
                continue
            size = int(header[2])
            result[p] = out[pos:pos + size].decode(errors="replace")
            pos += size + 1
        return result


def layer_of(path):
    top = path.split("/", 1)[0]
    return top if top in LAYERS else None


def is_public(path):
    return "/include/" in "/" + path.split("/", 1)[1] if "/" in path else False


def include_key(path):
    """The name other files include a header by: the part after .../include/ (else None)."""
    parts = path.split("/")
    if "include" in parts:
        i = len(parts) - 1 - parts[::-1].index("include")
        name = "/".join(parts[i + 1:])
        return name[:-3] if name.endswith(".in") else name
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--commit", help="read this commit (any git revision) instead of the working tree")
    ap.add_argument("--root", default=str(Path(__file__).resolve().parent.parent),
                    help="the repository (default: the one holding this script)")
    args = ap.parse_args()
    tree = Tree(args.root, args.commit)
    paths = tree.files()

    code = [p for p in paths if HEADER.search(p) or SOURCE.search(p)]
    py = [p for p in paths if p.endswith(".py") and (p.startswith("python/") or p.startswith("tests/"))]
    texts = tree.texts(code + py)

    # Headers by the name they are included by, each with its layer (also private ones of src/,
    # included by their path below the layer's src/ folder).
    owner = {}
    for p in code:
        layer = layer_of(p)
        if layer and HEADER.search(p):
            key = include_key(p)
            if key:
                owner[key] = layer

    rows = {l: dict(public=0, private=0, sources=0, generated=0, tests=0, files=0) for l in LAYERS}
    edges = {}

    def lines(p):
        return texts.get(p, "").count("\n")

    def included_layers(p):
        found = []
        for name in INCLUDE.findall(texts.get(p, "")):
            if name in owner:
                found.append(owner[name])
        return found

    for p in code:
        layer = layer_of(p)
        if p.startswith("tests/"):
            inc = included_layers(p)
            if inc:
                top = max(inc, key=LAYERS.index)
                rows[top]["tests"] += lines(p)
            continue
        if not layer:
            continue
        r = rows[layer]
        r["files"] += 1
        n = lines(p)
        if HEADER.search(p):
            r["public" if include_key(p) else "private"] += n
        else:
            r["sources"] += n
            if "/generated/" in p:
                r["generated"] += n
        for target in included_layers(p):
            if target != layer:
                edges[(layer, target)] = edges.get((layer, target), 0) + 1
    for p in py:
        n = lines(p)
        if p.startswith("tests/python/") or p.startswith("python/tests/"):
            rows["python"]["tests"] += n
        elif p.startswith("python/"):
            rows["python"]["sources"] += n
            rows["python"]["files"] += 1

    what = args.commit or "working tree"
    if args.commit:
        what += " (" + tree.git("rev-parse", "--short", args.commit).decode().strip() + ")"
    print(f"lrchain layers, {what}")
    print("source lines: headers public (include/) and private, sources (of them generated), tests")
    head = f"{'layer':<11}{'files':>7}{'public h':>10}{'private h':>11}{'sources':>9}{'(gen.)':>9}{'total':>9}{'share':>7}{'tests':>8}"
    print(head)
    print("-" * len(head))
    totals = {l: r["public"] + r["private"] + r["sources"] for l, r in rows.items()}
    grand = sum(totals.values()) or 1
    for l in LAYERS:
        r = rows[l]
        if not r["files"] and not r["tests"]:
            print(f"{l:<11}{'(none)':>7}")
            continue
        print(f"{l:<11}{r['files']:>7}{r['public']:>10}{r['private']:>11}{r['sources']:>9}{r['generated']:>9}"
              f"{totals[l]:>9}{100 * totals[l] / grand:>6.0f}%{r['tests']:>8}")
    print("-" * len(head))
    print(f"{'all':<11}{sum(r['files'] for r in rows.values()):>7}{sum(r['public'] for r in rows.values()):>10}"
          f"{sum(r['private'] for r in rows.values()):>11}{sum(r['sources'] for r in rows.values()):>9}"
          f"{sum(r['generated'] for r in rows.values()):>9}{grand:>9}{'':>7}{sum(r['tests'] for r in rows.values()):>8}")
    print()
    print("include edges between layers (#include lines; a lower layer including a higher one is marked !)")
    for (a, b), n in sorted(edges.items(), key=lambda e: (LAYERS.index(e[0][0]), LAYERS.index(e[0][1]))):
        mark = "  !" if LAYERS.index(b) > LAYERS.index(a) else ""
        print(f"  {a:>10} -> {b:<10}{n:>6}{mark}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
