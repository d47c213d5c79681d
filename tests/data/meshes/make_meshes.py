#!/usr/bin/env python3
"""Writes the real-mesh test inputs of `confvis flow` (tests/cli_real_mesh_test.cpp) the way
scanners and exporters write them. Deterministic; run from this folder to regenerate:
    python3 make_meshes.py

scan-disk.obj        a scanned height-field disk (irregular rings) with caps (an angle of
                     pi - 1e-3), needles (an angle of 1e-3), two zero-area faces (a vertex on its
                     neighbour's edge, a T-junction closed by a flat face), a seam of duplicated
                     vertices from the boundary inwards (as exporters split vertices) and two
                     unreferenced duplicate vertices.
scan-disk-crlf.obj   the same surface as a Windows exporter writes it: CRLF, a header comment,
                     mtllib/usemtl/g lines, v/vt/vn corners and quads where two triangles of a
                     ring band make one.
scan-disk.ply        the same surface as binary little-endian PLY (float32 positions, uchar
                     colours, uchar/int face lists), as scanners write it.
nonmanifold-edge.obj a small disk with a third face on one interior edge.
bowtie.obj           two small disks sharing one vertex.
flipped-face.obj     a small disk with one face's corners listed the other way round.
hole.obj             an annulus (a disk with a hole).
two-components.obj   two separate small disks.
"""
import math
import random
import struct


def height(x, y):
    return 0.12 * math.sin(3.1 * x + 0.4) * math.cos(2.3 * y) + 0.03 * math.sin(9 * x * y)


def ring_disk(rings, seed, jitter=0.25):
    """Points on concentric rings (jittered) and CCW triangles between them."""
    rnd = random.Random(seed)
    pts = [(0.0, 0.0)]
    ring_ids = [[0]]
    for k in range(1, rings + 1):
        n = 6 * k
        off = rnd.random()
        ids = []
        for i in range(n):
            t = 2 * math.pi * (i + off + (rnd.random() - 0.5) * jitter) / n
            r = k / rings * (1 if k == rings else 1 + (rnd.random() - 0.5) * jitter / rings)
            ids.append(len(pts))
            pts.append((r * math.cos(t), r * math.sin(t)))
        ring_ids.append(ids)
    tris = []
    for k in range(1, rings + 1):
        inner, outer = ring_ids[k - 1], ring_ids[k]
        if k == 1:
            for i in range(len(outer)):
                tris.append((0, outer[i], outer[(i + 1) % len(outer)]))
            continue
        ang = lambda v: math.atan2(pts[v][1], pts[v][0]) % (2 * math.pi)
        a = sorted(inner, key=ang)
        b = sorted(outer, key=ang)
        i = j = 0
        # Merge the two rings by angle, closing the band.
        while i < len(a) or j < len(b):
            ai, bj = a[i % len(a)], b[j % len(b)]
            an, bn = a[(i + 1) % len(a)], b[(j + 1) % len(b)]
            ta = ang(an) + (2 * math.pi if i + 1 >= len(a) else 0)
            tb = ang(bn) + (2 * math.pi if j + 1 >= len(b) else 0)
            if j >= len(b) or (i < len(a) and ta < tb):
                tris.append((ai, bj, an))
                i += 1
            else:
                tris.append((ai, bj, bn))
                j += 1
    return pts, tris


def orient(pts, t):
    (ax, ay), (bx, by), (cx, cy) = (pts[v][:2] for v in t)
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


def edge_faces(tris):
    m = {}
    for f, t in enumerate(tris):
        for c in range(3):
            m[(t[c], t[(c + 1) % 3])] = f
    return m


def scan_disk():
    pts, tris = ring_disk(9, 7)
    pts = [list(p) for p in pts]
    tris = [list(t) for t in tris]
    for t in tris:
        assert orient(pts, t) > 0
    rnd = random.Random(11)
    boundary = set()
    em = edge_faces(tris)
    for (a, b) in em:
        if (b, a) not in em:
            boundary |= {a, b}
    interior_edges = [(a, b) for (a, b) in em if (b, a) in em and a < b
                      and a not in boundary and b not in boundary]
    rnd.shuffle(interior_edges)
    used = set()

    def free(*vs):
        if any(v in used for v in vs):
            return False
        used.update(vs)
        return True

    caps = needles = flats = 0
    flat_faces = []
    for (a, c) in interior_edges:
        em = edge_faces(tris)
        if (a, c) not in em or (c, a) not in em:
            continue
        f = em[(a, c)]
        t = tris[f]
        d = [v for v in t if v not in (a, c)][0]
        if not free(a, c, d):
            continue
        ax, ay = pts[a][:2]
        cx, cy = pts[c][:2]
        dx, dy = pts[d][:2]
        mx, my = (ax + cx) / 2, (ay + cy) / 2
        if flats < 2:
            # A T-junction closed by a flat face: m exactly on a-c (in the plane).
            h = 0.0
            flats += 1
        elif caps < 6:
            # A cap: m off a-c towards d by 2.5e-4 |ac|, so its angle is pi - 1e-3.
            h = 2.5e-4 * math.hypot(cx - ax, cy - ay)
            caps += 1
        elif needles < 6:
            # A needle: m at 1e-3 |ad| from a inside face (a, c, d): (a, c, m), (a, m, d) are needles.
            m = len(pts)
            k = 1e-3
            pts.append([ax + k * (dx - ax) + k * (cx - ax) * 0.3, ay + k * (dy - ay) + k * (cy - ay) * 0.3])
            tris[f] = [a, c, m]
            tris.append([c, d, m])
            tris.append([d, a, m])
            needles += 1
            continue
        else:
            break
        nx, ny = -(cy - ay), cx - ax
        nl = math.hypot(nx, ny)
        m = len(pts)
        pts.append([mx + h * nx / nl, my + h * ny / nl])
        # Face (a, c, d) becomes (a, m, d), (m, c, d) and the flat/cap face (a, c, m).
        tris[f] = [a, m, d]
        tris.append([m, c, d])
        tris.append([a, c, m])
        if h == 0.0:
            flat_faces.append(len(tris) - 1)
    for f, t in enumerate(tris):
        assert f in flat_faces or orient(pts, t) > 0, t
    # 3-D positions on the height field; a flat face's middle vertex stays on its chord in 3-D
    # too (the midpoint of the chord), so the face has zero area in space as well.
    out = []
    for i, (x, y) in enumerate(pts):
        out.append([x, y, height(x, y)])
    for f in flat_faces:
        a, c, m = tris[f]
        out[m] = [(out[a][k] + out[c][k]) / 2 for k in range(3)]
    return out, [tuple(t) for t in tris], boundary


def with_seam(points, tris, boundary):
    """Splits the vertices of a path from the boundary inwards, as an exporter does at a
    texture seam: faces on one side use the copies. Adds two unreferenced duplicates."""
    points = [list(p) for p in points]
    # Path: boundary vertex at angle ~0 inwards along +x towards the centre, 4 vertices.
    on_axis = sorted((i for i, p in enumerate(points) if abs(p[1]) < 0.06 and p[0] > 0.3),
                     key=lambda i: -points[i][0])
    path = [on_axis[0]]
    em = edge_faces(tris)
    nbrs = {}
    for (a, b) in em:
        nbrs.setdefault(a, set()).add(b)
    while len(path) < 4:
        cur = path[-1]
        nxt = min(nbrs[cur], key=lambda v: points[v][0] + 4 * abs(points[v][1]))
        path.append(nxt)
    seam = path[:-1]  # the innermost vertex stays shared
    copy = {}
    for v in seam:
        copy[v] = len(points)
        points.append(list(points[v]))
    new = []
    for t in tris:
        cx = sum(points[v][0] for v in t) / 3
        cy = sum(points[v][1] for v in t) / 3
        if cy < 0 and cx > 0.2:  # faces below the seam use the copies
            t = tuple(copy.get(v, v) for v in t)
        new.append(t)
    points.append(list(points[5]))
    points.append(list(points[17]))
    return points, new


def write_obj(path, points, tris, header):
    with open(path, "w", newline="\n") as f:
        f.write(header)
        for p in points:
            f.write("v %.9g %.9g %.9g\n" % tuple(p))
        for t in tris:
            f.write("f %d %d %d\n" % tuple(v + 1 for v in t))


def write_windows_obj(path, points, tris):
    lines = ["# 3ds Max Wavefront OBJ Exporter v0.97b - (c)2007 guruware",
             "# File Created: 27.11.2026 10:12:33", "", "mtllib scan-disk-crlf.mtl", "",
             "#", "# object Scan01", "#", ""]
    for p in points:
        lines.append("v  %.4f %.4f %.4f" % tuple(p))
    lines.append("# %d vertices" % len(points))
    lines.append("")
    for p in points:
        lines.append("vt %.4f %.4f 0.0000" % (0.5 + p[0] / 2, 0.5 + p[1] / 2))
    lines.append("")
    lines.append("vn 0.0000 0.0000 1.0000")
    lines.append("")
    lines.append("g Scan01")
    lines.append("usemtl Scan_Material")
    lines.append("s 1")
    # Join face pairs sharing an edge into quads where the quad stays convex in the plane.
    em = edge_faces(tris)
    done = set()
    faces = []
    for f, t in enumerate(tris):
        if f in done:
            continue
        joined = False
        for c in range(3):
            a, b = t[c], t[(c + 1) % 3]
            g = em.get((b, a))
            if g is None or g in done or g == f or f % 3:
                continue
            o = tris[g]
            d = [v for v in o if v not in (a, b)][0]
            e = t[(c + 2) % 3]
            quad = [a, d, b, e]
            if all(orient(points, (quad[i], quad[(i + 1) % 4], quad[(i + 2) % 4])) > 1e-4
                   for i in range(4)):
                faces.append(quad)
                done |= {f, g}
                joined = True
                break
        if not joined:
            faces.append(list(t))
            done.add(f)
    for q in faces:
        lines.append("f " + " ".join("%d/%d/1" % (v + 1, v + 1) for v in q))
    lines.append("# %d polygons" % len(faces))
    with open(path, "w", newline="") as f:
        f.write("\r\n".join(lines) + "\r\n")


def write_binary_ply(path, points, tris):
    header = ("ply\nformat binary_little_endian 1.0\ncomment Artec Studio scan export\n"
              "element vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "property uchar red\nproperty uchar green\nproperty uchar blue\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % (len(points), len(tris)))
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        for p in points:
            f.write(struct.pack("<fffBBB", p[0], p[1], p[2], 200, 180, 160))
        for t in tris:
            f.write(struct.pack("<Biii", 3, *t))


def small_disk(rings=2, seed=3, shift=(0.0, 0.0)):
    pts, tris = ring_disk(rings, seed, jitter=0.1)
    return [[x + shift[0], y + shift[1], 0.0] for x, y in pts], tris


def main():
    points, tris, boundary = scan_disk()
    seamed, seamed_tris = with_seam(points, tris, boundary)
    header = "# scan-disk: scanned height-field disk (confvis test data, make_meshes.py)\n"
    write_obj("scan-disk.obj", seamed, seamed_tris, header)
    write_windows_obj("scan-disk-crlf.obj", points, tris)
    write_binary_ply("scan-disk.ply", points, tris)

    pts, t = small_disk()
    # A third face on the interior edge (0, 7): a fin standing up from it.
    fin = list(pts) + [[0.2, 0.1, 0.5]]
    a, b = t[0][0], t[0][1]
    write_obj("nonmanifold-edge.obj", fin, list(t) + [(a, b, len(pts))],
              "# a disk with a fin: three faces on the edge between vertices %d and %d\n"
              % (a + 1, b + 1))
    # Bowtie: a second disk touching the first at its boundary vertex 8 (1-based).
    p2, t2 = small_disk(seed=4, shift=(2.0, 0.0))
    n = len(pts)
    touch = max(range(n), key=lambda i: pts[i][0])
    far = min(range(len(p2)), key=lambda i: p2[i][0])
    remap = lambda v: touch if v == far else (n + v - (v > far))
    bow_pts = list(pts) + [p for i, p in enumerate(p2) if i != far]
    bow_tris = list(t) + [tuple(remap(v) for v in tri) for tri in t2]
    write_obj("bowtie.obj", bow_pts, bow_tris,
              "# two disks sharing vertex %d only\n" % (touch + 1))
    flipped = list(t)
    flipped[9] = tuple(reversed(flipped[9]))
    write_obj("flipped-face.obj", pts, flipped, "# a disk whose face 10 is listed clockwise\n")
    hp, ht = small_disk(rings=3, seed=5)
    write_obj("hole.obj", hp, [tri for tri in ht if 0 not in tri][:],
              "# an annulus: the disk without the faces around its centre vertex 1\n")
    write_obj("two-components.obj", pts + p2, list(t) + [tuple(v + n for v in tri) for tri in t2],
              "# two separate disks\n")


if __name__ == "__main__":
    main()
