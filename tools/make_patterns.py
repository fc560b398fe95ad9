#!/usr/bin/env python3
"""Writes the pattern files of tools/data/patterns/ (gmr.gmap, version 1).

f-patterns are discs of faces over vertex positions. Darts: one pair per face edge (alpha_0),
alpha_1 at the face corners, alpha_2 between faces sharing an edge; boundary darts are 2-free.
v-patterns are balls of hexahedra (3-G-maps): a dart is a (hexahedron, face, edge, vertex) flag,
alpha_3 links the darts of a face shared by two hexahedra; boundary darts are 3-free.
A boundary dart is flagged iff its vertex is a corner of the original cell and its edge lies on an
original edge (Damiand & Nivoliers 2022 §4.3.2, read for G-maps: see docs/query-replace.md).
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


# Faces of a hexahedron whose corners are numbered by coordinate bits x + 2y + 4z.
HEX_FACES = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def pattern_json(darts, alpha, positions, corners, edges):
    """The gmr.gmap document of a 3-G-map pattern whose darts are (cell, face, vertex, other vertex
    of the edge) flags: a boundary (3-free) dart is flagged when its vertex is a corner and its edge
    lies on one of the given edges; positions on the vertices (orbit <1,2,3>)."""
    n = len(darts)

    def on_edge(v, w):
        return any(on_segment(positions[v], positions[a], positions[b]) and
                   on_segment(positions[w], positions[a], positions[b]) for a, b in edges)

    flags = [alpha[3][d] == d and darts[d][2] in corners and on_edge(darts[d][2], darts[d][3]) for d in range(n)]
    first = {}
    for d in range(n):
        first.setdefault(darts[d][2], d)
    return {
        "format": "gmr.gmap", "version": 1, "kind": "gmap", "dimension": 3, "darts": n,
        "alpha": {str(i): alpha[i] for i in range(4)},
        "embeddings": [
            {"name": "flag", "orbit": "<>", "values": [{"dart": d, "value": flags[d]} for d in range(n)]},
            {"name": "position", "orbit": "<1,2,3>",
             "values": [{"dart": d, "value": positions[v]} for v, d in sorted(first.items())]},
        ],
    }


def volume_pattern(positions, corners, edges, hexes):
    """A 3-G-map from hexahedra (8 vertex ids each, in coordinate-bit order)."""
    darts = []  # (hex, face index, vertex, other vertex of the edge)
    index = {}
    for h, hx in enumerate(hexes):
        for f, face in enumerate(HEX_FACES):
            cyc = [hx[i] for i in face]
            for i in range(4):
                v, w, u = cyc[i], cyc[(i + 1) % 4], cyc[i - 1]
                for (a, b) in ((v, w), (v, u)):
                    index[(h, f, a, b)] = len(darts)
                    darts.append((h, f, a, b))
    n = len(darts)
    face_verts = {(h, f): frozenset(hexes[h][i] for i in HEX_FACES[f]) for h in range(len(hexes)) for f in range(6)}
    by_face = {}
    for (h, f), vs in face_verts.items():
        by_face.setdefault(vs, []).append((h, f))
    alpha = [[0] * n for _ in range(4)]
    for d, (h, f, v, w) in enumerate(darts):
        alpha[0][d] = index[(h, f, w, v)]
        cyc = [hexes[h][i] for i in HEX_FACES[f]]
        i = cyc.index(v)
        nb = {cyc[(i + 1) % 4], cyc[i - 1]}
        (x,) = nb - {w}
        alpha[1][d] = index[(h, f, v, x)]
        (g,) = [g for g in range(6) if g != f and v in face_verts[(h, g)] and w in face_verts[(h, g)]]
        alpha[2][d] = index[(h, g, v, w)]
        other = [hf for hf in by_face[face_verts[(h, f)]] if hf != (h, f)]
        if len(by_face[face_verts[(h, f)]]) > 2:
            raise SystemExit("a face shared by more than two hexahedra")
        alpha[3][d] = index[(other[0][0], other[0][1], v, w)] if other else d
    return pattern_json(darts, alpha, positions, corners, edges)


def polyhedral_pattern(positions, corners, edges, volumes):
    """A 3-G-map from volumes given as closed polygon surfaces (lists of vertex cycles). A dart is a
    (volume, face, vertex, other vertex of the edge) flag; alpha_2 joins the two faces of a volume
    sharing an edge, alpha_3 the same face (vertex set) in two volumes; boundary darts are 3-free."""
    darts, index = [], {}
    for c, faces in enumerate(volumes):
        for f, cyc in enumerate(faces):
            for i, v in enumerate(cyc):
                for w in (cyc[(i + 1) % len(cyc)], cyc[i - 1]):
                    index[(c, f, v, w)] = len(darts)
                    darts.append((c, f, v, w))
    n = len(darts)
    face_key = {(c, f): frozenset(cyc) for c, faces in enumerate(volumes) for f, cyc in enumerate(faces)}
    by_face = {}
    for cf, key in face_key.items():
        by_face.setdefault(key, []).append(cf)

    def has_edge(cyc, v, w):
        return any({cyc[i], cyc[(i + 1) % len(cyc)]} == {v, w} for i in range(len(cyc)))

    alpha = [[0] * n for _ in range(4)]
    for d, (c, f, v, w) in enumerate(darts):
        cyc = volumes[c][f]
        alpha[0][d] = index[(c, f, w, v)]
        i = cyc.index(v)
        (x,) = {cyc[(i + 1) % len(cyc)], cyc[i - 1]} - {w}
        alpha[1][d] = index[(c, f, v, x)]
        others = [g for g, gc in enumerate(volumes[c]) if g != f and has_edge(gc, v, w)]
        if len(others) != 1:
            raise SystemExit("volume %d: edge %s in %d faces" % (c, sorted((v, w)), len(others) + 1))
        alpha[2][d] = index[(c, others[0], v, w)]
        shared = [cf for cf in by_face[face_key[(c, f)]] if cf != (c, f)]
        if len(shared) > 1:
            raise SystemExit("a face shared by more than two volumes")
        alpha[3][d] = index[(shared[0][0], shared[0][1], v, w)] if shared else d
    return pattern_json(darts, alpha, positions, corners, edges)


CUBE_EDGES = [(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1]


def cube_rotations():
    """The 24 rotations of the cube as permutations of its corners (coordinate bits x + 2y + 4z)."""
    def corner_map(f):
        return tuple(sum(b << i for i, b in enumerate(f([(v >> i) & 1 for i in range(3)]))) for v in range(8))
    turn_x = corner_map(lambda p: [p[0], 1 - p[2], p[1]])
    turn_y = corner_map(lambda p: [p[2], p[1], 1 - p[0]])
    group = {tuple(range(8))}
    frontier = list(group)
    while frontier:
        g = frontier.pop()
        for t in (turn_x, turn_y):
            h = tuple(t[g[v]] for v in range(8))
            if h not in group:
                group.add(h)
                frontier.append(h)
    assert len(group) == 24
    return sorted(group)


def mc_face_step(inside, isolate_inside):
    """The faces of the cube after the face step of marching cubes (§7.2) for the inside corners
    `inside` (a bit mask): each cut edge gets its midpoint; a face with 2 cuts is cut by one segment;
    a face with 4 cuts by two segments cutting off its inside corners (face in isolate_inside) or its
    outside corners. Returns the pieces (vertex cycles) and the segments."""
    cut = lambda a, b: ((inside >> a) ^ (inside >> b)) & 1
    mid = lambda a, b: 8 + CUBE_EDGES.index((min(a, b), max(a, b)))
    pieces, segments = [], []
    for f, face in enumerate(HEX_FACES):
        cyc = []
        for i in range(4):
            a, b = face[i], face[(i + 1) % 4]
            cyc.append(a)
            if cut(a, b):
                cyc.append(mid(a, b))
        cuts = [k for k, v in enumerate(cyc) if v >= 8]
        if not cuts:
            pieces.append(cyc)
        elif len(cuts) == 2:
            i, j = cuts
            pieces.append(cyc[i:j + 1])
            pieces.append(cyc[j:] + cyc[:i + 1])
            segments.append((cyc[i], cyc[j]))
        else:
            # corners between consecutive cuts; cut off those on the chosen side
            keep = list(cyc)
            for k in range(4):
                p, q = cuts[k], cuts[(k + 1) % 4]
                corner = cyc[(p + 1) % len(cyc)]
                if bool(inside >> corner & 1) == (f in isolate_inside):
                    pieces.append([cyc[p], corner, cyc[q]])
                    segments.append((cyc[p], cyc[q]))
                    keep.remove(corner)
            pieces.append(keep)
    return pieces, segments


def mc_volumes(inside, isolate_inside):
    """The volumes of the marching-cubes v-pattern: the cube's surface after the face step is cut
    along the loops of segments into components; each component closed by the loops' polygons is
    one volume (inside or outside part of the cell)."""
    pieces, segments = mc_face_step(inside, isolate_inside)
    seg = {frozenset(s) for s in segments}
    # loops: every cut point has two segments
    nbr = {}
    for a, b in segments:
        nbr.setdefault(a, []).append(b)
        nbr.setdefault(b, []).append(a)
    loops, seen = [], set()
    for start in sorted(nbr):
        if start in seen:
            continue
        loop, prev, v = [start], None, start
        seen.add(start)
        while True:
            (w,) = [x for x in nbr[v] if x != prev] if prev is not None else [nbr[v][0]]
            if w == start:
                break
            loop.append(w)
            seen.add(w)
            prev, v = v, w
        loops.append(loop)
    # components: pieces sharing an edge that is not a segment
    parent = list(range(len(pieces)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    by_edge = {}
    for k, cyc in enumerate(pieces):
        for i in range(len(cyc)):
            e = frozenset((cyc[i], cyc[(i + 1) % len(cyc)]))
            by_edge.setdefault(e, []).append(k)
    for e, ks in by_edge.items():
        assert len(ks) == 2, (inside, e, ks)
        if e not in seg:
            parent[find(ks[0])] = find(ks[1])
    comps = sorted({find(k) for k in range(len(pieces))})
    volumes = {c: [pieces[k] for k in range(len(pieces)) if find(k) == c] for c in comps}
    for loop in loops:
        sides = {find(k) for i in range(len(loop)) for k in by_edge[frozenset((loop[i], loop[(i + 1) % len(loop)]))]}
        assert len(sides) == 2, (inside, loop)
        for c in sides:
            volumes[c].append(loop)
    assert len(volumes) == len(loops) + 1
    return [volumes[c] for c in comps]


def mc_classes():
    """One representative (inside mask, faces whose inside corners are cut off) per class of the
    654 marching-cubes configurations under the cube's 24 rotations and the exchange of inside and
    outside (the cell's boundary after the face step does not tell them apart): the face
    resolution "inside corners cut off" is carried by the face, so a rotation permutes masks and
    resolutions, and the exchange complements both."""
    rotations = cube_rotations()
    faces = [frozenset(f) for f in HEX_FACES]
    seen, reps = set(), []
    for inside in range(1, 255):
        cut = lambda a, b: ((inside >> a) ^ (inside >> b)) & 1
        ambiguous = [f for f, face in enumerate(HEX_FACES) if all(cut(face[i], face[(i + 1) % 4]) for i in range(4))]
        for res in range(1 << len(ambiguous)):
            iso = frozenset(f for k, f in enumerate(ambiguous) if res >> k & 1)
            images = set()
            for r in rotations:
                m = sum(1 << r[v] for v in range(8) if inside >> v & 1)
                fs = frozenset(faces.index(frozenset(r[v] for v in faces[f])) for f in iso)
                amb = frozenset(faces.index(frozenset(r[v] for v in faces[f])) for f in ambiguous)
                images.add((m, fs))
                images.add((255 ^ m, amb - fs))  # the same cut, inside and outside swapped
            key = min(images, key=lambda x: (x[0], sorted(x[1])))
            if key not in seen:
                seen.add(key)
                reps.append((inside, iso))
    return reps


def marching_cubes_set():
    """The 29 v-patterns of marching cubes (§7.2, Fig. 12), generated: one per rotation class of
    the face-step configurations, each the cube cut into its inside and outside parts."""
    positions = [[v & 1, v >> 1 & 1, v >> 2 & 1] for v in range(8)]
    positions += [[(positions[a][i] + positions[b][i]) / 2 for i in range(3)] for a, b in CUBE_EDGES]
    out = {}
    for inside, iso in mc_classes():
        name = "mc-%03d" % inside + "".join("-f%d" % f for f in sorted(iso))
        out[name] = polyhedral_pattern(positions, list(range(8)), CUBE_EDGES, mc_volumes(inside, iso))
    return out


def hex_2x2x2():
    """Fig. 9b: a hexahedron cut into 2 x 2 x 2 hexahedra."""
    positions = [[x / 2, y / 2, z / 2] for z in range(3) for y in range(3) for x in range(3)]
    vid = lambda x, y, z: x + 3 * y + 9 * z
    hexes = [[vid(x + (b & 1), y + (b >> 1 & 1), z + (b >> 2 & 1)) for b in range(8)]
             for z in range(2) for y in range(2) for x in range(2)]
    corners = [vid(2 * (b & 1), 2 * (b >> 1 & 1), 2 * (b >> 2 & 1)) for b in range(8)]
    edges = [(corners[a], corners[b]) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1]
    return volume_pattern(positions, corners, edges, hexes)


def tet_4hex():
    """Fig. 16 right: a tetrahedron cut into 4 hexahedra, one per corner."""
    t = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    positions = list(t)
    ids = {}

    def point(vs):
        key = frozenset(vs)
        if len(key) == 1:
            return next(iter(key))
        if key not in ids:
            ids[key] = len(positions)
            positions.append([sum(t[v][i] for v in key) / len(key) for i in range(3)])
        return ids[key]

    hexes = []
    for v in range(4):
        a, b, c = [u for u in range(4) if u != v]
        # coordinate bits: x toward a, y toward b, z toward c
        hexes.append([point({v} | {p for bit, p in ((1, a), (2, b), (4, c)) if m & bit}) for m in range(8)])
    edges = [(a, b) for a in range(4) for b in range(a + 1, 4)]
    return volume_pattern(positions, [0, 1, 2, 3], edges, hexes)


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
    # Hexahedral subdivision (§7.1): the f-pattern of Fig. 9a (with the v-pattern hex8).
    "hex-subdivision": {
        "split4": (SQUARE, [0, 1, 2, 3], [[0, 4, 8, 7], [4, 1, 5, 8], [8, 5, 2, 6], [7, 8, 6, 3]]),
    },
    # Marching cubes (§7.2, Fig. 11): the 3 f-patterns of a face with 2 adjacent, 2 opposite or 4
    # cut edges (a corner cut off; the face cut in two; two opposite corners cut off).
    "marching-cubes": {
        "face-corner": (SQUARE, [0, 1, 2, 3], [[0, 4, 7], [4, 1, 2, 3, 7]]),
        "face-halves": (SQUARE, [0, 1, 2, 3], [[0, 4, 6, 3], [4, 1, 2, 6]]),
        "face-two-corners": (SQUARE, [0, 1, 2, 3], [[0, 4, 7], [5, 2, 6], [4, 1, 5, 6, 3, 7]]),
    },
    # Tetrahedra to hexahedra (§7.4, Fig. 16 left): a triangle with split edges cut into 3 quads.
    "tet-to-hex": {
        "triangle3": (TRIANGLE, [0, 1, 2], [[0, 3, 6, 5], [3, 1, 4, 6], [6, 4, 2, 5]]),
    },
}


VOLUME_SETS = {
    # Hexahedral subdivision (§7.1, Alg. 5): one f-pattern and one v-pattern.
    "hex-subdivision": {"hex8": hex_2x2x2},
    # Tetrahedra to hexahedra (§7.4, Fig. 16): with the f-pattern triangle3.
    "tet-to-hex": {"tet4": tet_4hex},
}


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "data", "patterns")
    mc = os.path.join(root, "marching-cubes")
    os.makedirs(mc, exist_ok=True)
    for name, content in marching_cubes_set().items():
        with open(os.path.join(mc, name + ".json"), "w") as out:
            json.dump(content, out)
            out.write("\n")
    for folder, patterns in VOLUME_SETS.items():
        os.makedirs(os.path.join(root, folder), exist_ok=True)
        for name, build in patterns.items():
            with open(os.path.join(root, folder, name + ".json"), "w") as out:
                json.dump(build(), out)
                out.write("\n")
    for folder, patterns in SETS.items():
        os.makedirs(os.path.join(root, folder), exist_ok=True)
        for name, (positions, corners, faces) in patterns.items():
            with open(os.path.join(root, folder, name + ".json"), "w") as out:
                json.dump(pattern(positions, corners, faces), out)
                out.write("\n")


if __name__ == "__main__":
    main()
