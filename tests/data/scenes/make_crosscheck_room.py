#!/usr/bin/env python3
"""Writes crosscheck-room.obj/.mtl and checker.png: the real-content scene of the Vulkan/Embree
cross-check suite (tests/backend_cross_check_content_test.cpp). Run from this folder; the files
are committed, so tests never run this."""
import math, struct, zlib

def png(path, w, h, rgb):
    raw = b''.join(b'\0' + bytes(v for x in range(w) for v in rgb(x, y)) for y in range(h))
    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff)
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
                + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))

# 8 x 8 texels, squares of 2 x 2 texels: white and brick red.
png('checker.png', 8, 8, lambda x, y: (240, 240, 240) if (x // 2 + y // 2) % 2 else (170, 40, 30))

v, vt, faces = [], [], []
def quad(corners, material, uvs=None):
    base = len(v)
    v.extend(corners)
    if uvs:
        tbase = len(vt)
        vt.extend(uvs)
        faces.append((material, [(base + i, tbase + i) for i in (0, 1, 2)]))
        faces.append((material, [(base + i, tbase + i) for i in (0, 2, 3)]))
    else:
        faces.append((material, [(base + i, None) for i in (0, 1, 2)]))
        faces.append((material, [(base + i, None) for i in (0, 2, 3)]))

def box(x0, x1, y0, y1, z0, z1, material):
    """Four sides (no caps) of an axis-aligned box, each face wound outward."""
    quad([(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)], material)  # +z
    quad([(x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0)], material)  # -z
    quad([(x1, y0, z1), (x1, y0, z0), (x1, y1, z0), (x1, y1, z1)], material)  # +x
    quad([(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)], material)  # -x

# A textured ground plane 1.2 m under the viewer, 40 m across in two triangles (uv 0..20: the
# texture repeats), and a ceiling 0.6 m above it in two triangles: large near triangles.
quad([(-20, -1.2, 20), (20, -1.2, 20), (20, -1.2, -20), (-20, -1.2, -20)], 'ground',
     [(0, 0), (20, 0), (20, 20), (0, 20)])
quad([(-20, 0.6, -20), (20, 0.6, -20), (20, 0.6, 20), (-20, 0.6, 20)], 'ceiling')
# Thin poles (12 cm square, floor to ceiling) 3 m away in eight directions, and two wires (8 cm)
# across the front and the left 4 m away: a few pixels wide on 96-pixel CAVE walls.
for i in range(8):
    a = math.pi * i / 4 + 0.3
    x, z = 3 * math.sin(a), -3 * math.cos(a)
    box(x - 0.06, x + 0.06, -1.2, 0.6, z - 0.06, z + 0.06, 'pole')
box(-6, 6, -0.04, 0.04, -4.04, -3.96, 'wire')
box(-4.04, -3.96, 0.26, 0.34, -6, 6, 'wire')

with open('crosscheck-room.mtl', 'w') as f:
    f.write('newmtl ground\nKd 1 1 1\nmap_Kd checker.png\n\n')
    f.write('newmtl ceiling\nKd 0.9 0.6 0.1\n\nnewmtl pole\nKd 0.1 0.3 0.9\n\n')
    f.write('newmtl wire\nKd 0.1 0.9 0.3\n')
with open('crosscheck-room.obj', 'w') as f:
    f.write('# The cross-check suite\'s room (make_crosscheck_room.py), metres, viewer at the origin\n')
    f.write('mtllib crosscheck-room.mtl\n')
    for p in v:
        f.write('v %.4f %.4f %.4f\n' % p)
    for t in vt:
        f.write('vt %g %g\n' % t)
    current = None
    for material, corners in faces:
        if material != current:
            f.write('usemtl %s\n' % material)
            current = material
        f.write('f ' + ' '.join('%d/%d' % (a + 1, b + 1) if b is not None else '%d' % (a + 1)
                                for a, b in corners) + '\n')
