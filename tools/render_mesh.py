#!/usr/bin/env python3
"""Renders OFF surface meshes (as written by `gmr apply ... -o x.off`) to one SVG, side by side:
orthographic view from a fixed direction, faces drawn back to front (painter's algorithm), each
filled with a grey of its Lambert shading. No dependency beyond Python 3.

Usage: tools/render_mesh.py OUT.svg "title:mesh.off" ["title:mesh.off" ...]
"""
import math
import sys


def read_off(path):
    tokens = []
    for line in open(path):
        line = line.split("#", 1)[0].split()
        if line:
            tokens.append(line)
    head = tokens[0]
    rest = tokens[1:] if head == ["OFF"] else [head[1:]] + tokens[1:]
    nv, nf = int(rest[0][0]), int(rest[0][1])
    verts = [tuple(float(x) for x in rest[1 + k][:3]) for k in range(nv)]
    faces = [[int(x) for x in rest[1 + nv + k][1:1 + int(rest[1 + nv + k][0])]] for k in range(nf)]
    return verts, faces


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    n = math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2) or 1.0
    return (a[0] / n, a[1] / n, a[2] / n)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


# View: rotate about z then x; light from the viewer's upper left.
AZ, EL = math.radians(35), math.radians(25)


def view(p):
    x, y, z = p
    x, y = x * math.cos(AZ) - y * math.sin(AZ), x * math.sin(AZ) + y * math.cos(AZ)
    y, z = y * math.cos(EL) - z * math.sin(EL), y * math.sin(EL) + z * math.cos(EL)
    return (x, z, y)  # screen x, screen y (up), depth (larger = farther)


LIGHT = norm((-0.4, 0.6, -1.0))


def panel(verts, faces, ox, size):
    pts = [view(v) for v in verts]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    scale = 0.9 * size / max(max(xs) - min(xs), max(ys) - min(ys), 1e-12)
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    out = []
    order = sorted(range(len(faces)), key=lambda f: -sum(pts[v][2] for v in faces[f]) / len(faces[f]))
    for f in order:
        poly = [pts[v] for v in faces[f]]
        n = norm(cross(sub(poly[1], poly[0]), sub(poly[2], poly[0])))
        shade = abs(dot(n, LIGHT))
        g = int(60 + 180 * shade)
        coords = " ".join(f"{ox + size / 2 + (p[0] - cx) * scale:.2f},{size / 2 - (p[1] - cy) * scale + 20:.2f}" for p in poly)
        out.append(f'<polygon points="{coords}" fill="rgb({g},{g},{min(255, g + 20)})" stroke="#333" stroke-width="0.3"/>')
    return out


def main():
    out_path, items = sys.argv[1], sys.argv[2:]
    size = 260
    body = []
    for k, item in enumerate(items):
        title, path = item.split(":", 1)
        verts, faces = read_off(path)
        body += panel(verts, faces, k * size, size)
        body.append(f'<text x="{k * size + size / 2}" y="14" text-anchor="middle" font-family="Helvetica" font-size="13">{title}</text>')
    with open(out_path, "w") as f:
        f.write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{size * len(items)}" height="{size + 25}">\n')
        f.write("\n".join(body))
        f.write("\n</svg>\n")


if __name__ == "__main__":
    main()
