#!/usr/bin/env python3
"""Writes the STL meshes of the GRPVSS six-axis demo robot and its U-shaped fixture.

The robot's collision meshes are boxes (binary STL, metres, one closed convex mesh per link);
the fixture is a U-shaped prism (closed, NOT convex: the cell decomposes it exactly).
Run from this folder: `python3 generate_meshes.py` (the STL files are committed; rerunning
rewrites them byte for byte).
"""
import struct
from pathlib import Path

HERE = Path(__file__).resolve().parent


def box_triangles(lo, hi):
    """The 12 outward-facing triangles of the axis-aligned box [lo, hi]."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    triangles = []
    for a, b, c, d in quads:
        triangles.append((v[a], v[b], v[c]))
        triangles.append((v[a], v[c], v[d]))
    return triangles


def prism_triangles(outline, cap_triangles, z0, z1):
    """A closed prism over a counter-clockwise simple polygon whose cap is triangulated by
    `cap_triangles` (counter-clockwise index triples)."""
    n = len(outline)
    bottom = [(x, y, z0) for x, y in outline]
    top = [(x, y, z1) for x, y in outline]
    triangles = []
    for a, b, c in cap_triangles:
        triangles.append((bottom[a], bottom[c], bottom[b]))  # facing -z
        triangles.append((top[a], top[b], top[c]))
    for i in range(n):
        j = (i + 1) % n
        triangles.append((bottom[i], bottom[j], top[j]))
        triangles.append((bottom[i], top[j], top[i]))
    return triangles


def normal(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    length = sum(x * x for x in n) ** 0.5
    return [x / length for x in n]


def write_stl(name, triangles):
    data = bytearray(b"GRPVSS six-axis demo: " + name.encode())
    data += bytes(80 - len(data))
    data += struct.pack("<I", len(triangles))
    for a, b, c in triangles:
        data += struct.pack("<3f", *normal(a, b, c))
        for vertex in (a, b, c):
            data += struct.pack("<3f", *vertex)
        data += struct.pack("<H", 0)
    (HERE / "meshes" / (name + ".stl")).write_bytes(bytes(data))


LINK_BOXES = {
    # link: (lo, hi) in the link's frame, metres
    "base_link": ((-0.15, -0.15, 0.0), (0.15, 0.15, 0.2)),
    "link_1": ((-0.1, -0.1, 0.0), (0.12, 0.1, 0.2)),
    "link_2": ((-0.06, -0.07, -0.06), (0.06, 0.07, 0.5)),
    "link_3": ((-0.06, -0.06, -0.06), (0.1, 0.06, 0.09)),
    "link_4": ((0.0, -0.045, -0.045), (0.38, 0.045, 0.045)),
    "link_5": ((-0.04, -0.04, -0.04), (0.06, 0.04, 0.04)),
    "link_6": ((0.0, -0.03, -0.03), (0.02, 0.03, 0.03)),
}

# A U seen from above (x right, y up): 0.24 x 0.16 overall, two 0.06 m arms around a
# 0.12 x 0.10 gap, 0.1 m high; counter-clockwise, its cap cut into six triangles.
U_OUTLINE = [(-0.12, -0.08), (0.12, -0.08), (0.12, 0.08), (0.06, 0.08), (0.06, -0.02),
             (-0.06, -0.02), (-0.06, 0.08), (-0.12, 0.08)]
U_CAP = [(0, 1, 4), (0, 4, 5), (1, 2, 3), (1, 3, 4), (0, 5, 6), (0, 6, 7)]


def u_fixture_triangles():
    return prism_triangles(U_OUTLINE, U_CAP, 0.0, 0.1)


if __name__ == "__main__":
    (HERE / "meshes").mkdir(exist_ok=True)
    for link, (lo, hi) in LINK_BOXES.items():
        write_stl(link, box_triangles(lo, hi))
    write_stl("u_fixture", u_fixture_triangles())
