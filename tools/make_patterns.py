#!/usr/bin/env python3
"""Writes the f-pattern files of tools/data/patterns/ (gmr.gmap, version 1) from face lists.

Each pattern is a disc of faces over vertex positions. Darts: one pair per face edge (alpha_0),
alpha_1 at the face corners, alpha_2 between faces sharing an edge; boundary darts are 2-free.
A dart is flagged iff its vertex is a corner of the original polygon and its edge lies on a side
of that polygon (Damiand & Nivoliers 2022 §4.3.2, read for G-maps: see docs/query-replace.md).
Usage: tools/make_patterns.py [OUTPUT_ROOT]   (default: tools/data/patterns)
"""
import json
import os
import sys


def on_segment(p, a, b):
    cross = [(b[1] - a[1]) * (p[2] - a[2]) - (b[2] - a[2]) * (p[1] - a[1]),
             (b[2] - a[2]) * (p[0] - a[0]) - (b[0] - a[0]) * (p[2] - a[2]),
             (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])]
    if any(abs(c) > 1e-9 for c in cross):
        return False
    dot = sum((p[i] - a[i]) * (b[i] - a[i]) for i in range(3))
    return -1e-9 <= dot <= sum((b[i] - a[i]) ** 2 for i in range(3)) + 1e-9


def pattern(positions, corners, faces):
    sides = [(corners[i], corners[(i + 1) % len(corners)]) for i in range(len(corners))]

    def on_side(v, w):
        return any(on_segment(positions[v], positions[a], positions[b]) and
                   on_segment(positions[w], positions[a], positions[b]) for a, b in sides)

    vertex, a0, a1 = [], [], []
    by_edge = {}
    for face in faces:
        k = len(face)
        base = len(vertex)
        for i in range(k):  # darts 2i (at face[i]) and 2i+1 (at face[i+1]) on edge i
            vertex += [face[i], face[(i + 1) % k]]
        for i in range(k):
            a0 += [base + 2 * i + 1, base + 2 * i]
        a1 += [0] * (2 * k)
        for i in range(k):
            d_end = base + 2 * i + 1             # end of edge i, at face[i+1]
            d_next = base + 2 * ((i + 1) % k)    # start of edge i+1, at face[i+1]
            a1[d_end] = d_next
            a1[d_next] = d_end
        for i in range(k):
            v, w = face[i], face[(i + 1) % k]
            by_edge.setdefault(frozenset((v, w)), []).append((base + 2 * i, base + 2 * i + 1))
    n = len(vertex)
    a2 = list(range(n))
    for key, uses in by_edge.items():
        if len(uses) > 2:
            raise SystemExit("non-manifold edge %s" % sorted(key))
        if len(uses) == 2:
            (p0, p1), (q0, q1) = uses
            if vertex[p0] == vertex[q0]:
                pairs = [(p0, q0), (p1, q1)]
            else:
                pairs = [(p0, q1), (p1, q0)]
            for x, y in pairs:
                a2[x], a2[y] = y, x
    flags = [d for d in range(n) if vertex[d] in corners and on_side(vertex[d], vertex[a0[d]])]
    first = {}
    for d in range(n):
        first.setdefault(vertex[d], d)
    return {
        "format": "gmr.gmap", "version": 1, "kind": "gmap", "dimension": 2, "darts": n,
        "alpha": {"0": a0, "1": a1, "2": a2},
        "embeddings": [
            {"name": "flag", "orbit": "<>", "values": [{"dart": d, "value": d in flags} for d in range(n)]},
            {"name": "position", "orbit": "<1,2>",
             "values": [{"dart": d, "value": positions[v]} for v, d in sorted(first.items())]},
        ],
    }


# The unit square A(0) B(1) C(2) D(3); midpoints M(4) of AB, N(5) of BC, P(6) of CD, Q(7) of DA;
# centre O(8).
SQUARE = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
          [0.5, 0, 0], [1, 0.5, 0], [0.5, 1, 0], [0, 0.5, 0], [0.5, 0.5, 0]]
TRIANGLE = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.5, 0, 0], [0.5, 0.5, 0], [0, 0.5, 0], [1 / 3, 1 / 3, 0]]

SETS = {
    # Conformal refinement of quads (Damiand & Nivoliers §7.3, Fig. 14): one f-pattern per class of
    # split-edge sets of a square (1, 2 adjacent, 2 opposite, 3, 4 split edges).
    "conformal-faces": {
        "split1": (SQUARE, [0, 1, 2, 3], [[0, 4, 3], [4, 1, 2], [4, 2, 3]]),
        "split2-adjacent": (SQUARE, [0, 1, 2, 3], [[4, 1, 5], [5, 2, 3], [0, 4, 5, 3]]),
        "split2-opposite": (SQUARE, [0, 1, 2, 3], [[0, 4, 6, 3], [4, 1, 2, 6]]),
        "split3": (SQUARE, [0, 1, 2, 3], [[0, 4, 6, 3], [4, 1, 5], [4, 5, 6], [5, 2, 6]]),
        # Fig. 9a: a square with its 4 edges split, cut into 4 quads (hexahedral subdivision).
        "split4": (SQUARE, [0, 1, 2, 3], [[0, 4, 8, 7], [4, 1, 5, 8], [8, 5, 2, 6], [7, 8, 6, 3]]),
    },
    # Tetrahedra to hexahedra (§7.4, Fig. 16 left): a triangle with split edges cut into 3 quads.
    "tet-to-hex": {
        "triangle3": (TRIANGLE, [0, 1, 2], [[0, 3, 6, 5], [3, 1, 4, 6], [6, 4, 2, 5]]),
    },
}


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "data", "patterns")
    for folder, patterns in SETS.items():
        os.makedirs(os.path.join(root, folder), exist_ok=True)
        for name, (positions, corners, faces) in patterns.items():
            with open(os.path.join(root, folder, name + ".json"), "w") as out:
                json.dump(pattern(positions, corners, faces), out)
                out.write("\n")


if __name__ == "__main__":
    main()
