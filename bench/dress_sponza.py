"""Dresses the Dabrovic Sponza (geometry only: ../shared/assets has no MTL or textures for it) with
an MTL of its own and generated textures, for bench/run's textured Sponza (issue 20).

Every one of the OBJ's 34 named groups gets a material by its name (MATERIALS below): diffuse
textures (map_Kd) on floors, walls, arches and ceiling, a textured and a plain plastic (Ks, Ns),
a conductor (Ks without a diffuse colour), and alpha masks (map_d) that cut the parapet into a
balustrade and the windows into grilles. The textures are procedural (stone blocks, floor tiles,
plaster, wood, two masks), written as PNGs by this module, so the scene needs nothing beyond the
asset. Everything lands in bench/run's work folder, never in the repository. Standard library
only, as bench/run.
"""
import math
import os
import random
import struct
import zlib

SIZE = 256

# Group name -> MTL statements (the name becomes the material's). Groups not named here get
# DEFAULT (stone blocks). Texture scales (-s) put about one block or tile per unit of the group's UVs.
DEFAULT = ['map_Kd stone.png']
MATERIALS = {
    'floors': ['map_Kd -s 4 4 tiles.png'],
    'walls': ['Kd 0.9 0.85 0.8', 'map_Kd plaster.png'],
    'outside01': ['map_Kd plaster.png'],
    'ceiling': ['Kd 0.85 0.8 0.75', 'map_Kd plaster.png'],
    'pillar_round': ['Kd 0.62 0.56 0.5', 'Ks 0.04 0.04 0.04', 'Ns 200', 'Ni 1.5'],
    'doors': ['map_Kd wood.png', 'Ks 0.04 0.04 0.04', 'Ns 60'],
    'relief': ['Kd 0 0 0', 'Ks 0.9 0.7 0.4', 'Ns 300'],
    'windows': ['Kd 0.3 0.3 0.35', 'map_d grille.png'],
    'parapet': ['map_Kd stone.png', 'map_d -s 2 2 balustrade.png'],
}


def write_png(path, width, height, channels, pixel):
    """An 8-bit PNG of `channels` (1 or 3) channels whose pixel (x, y), rows from the top, is
    pixel(x, y): a tuple of values in [0, 1]."""
    colour_type = {1: 0, 3: 2}[channels]
    raw = bytearray()
    for y in range(height):
        raw.append(0)
        for x in range(width):
            raw.extend(min(255, max(0, int(v * 255 + 0.5))) for v in pixel(x, y))

    def chunk(kind, data):
        body = kind + data
        return struct.pack('>I', len(data)) + body + struct.pack('>I', zlib.crc32(body))

    header = struct.pack('>IIBBBBB', width, height, 8, colour_type, 0, 0, 0)
    png = (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', header)
           + chunk(b'IDAT', zlib.compress(bytes(raw), 9)) + chunk(b'IEND', b''))
    with open(path + '.tmp', 'wb') as f:
        f.write(png)
    os.replace(path + '.tmp', path)


def value_noise(rng, cells):
    """Value noise over [0, SIZE)^2: `cells` x `cells` random values, bilinearly interpolated and
    tiling."""
    grid = [[rng.random() for _ in range(cells)] for _ in range(cells)]

    def noise(x, y):
        fx, fy = x * cells / SIZE, y * cells / SIZE
        i, j = int(fx), int(fy)
        tx, ty = fx - i, fy - j
        i1, j1 = (i + 1) % cells, (j + 1) % cells
        top = grid[j][i] * (1 - tx) + grid[j][i1] * tx
        bottom = grid[j1][i] * (1 - tx) + grid[j1][i1] * tx
        return top * (1 - ty) + bottom * ty
    return noise


def textures(rng):
    """Name -> (channels, pixel function) of each generated texture."""
    grain, marble = value_noise(rng, 32), value_noise(rng, 16)
    blotches, rings = value_noise(rng, 8), value_noise(rng, 4)
    block_tint = [[0.9 + 0.2 * rng.random() for _ in range(2)] for _ in range(4)]
    q, h, e = SIZE // 4, SIZE // 2, SIZE // 8

    def stone(x, y):  # 4 courses of 2 blocks, every other course offset by half a block
        course = y // q
        shifted = x + (course % 2) * q
        mortar = y % q < 4 or shifted % h < 4
        shade = 0.55 if mortar else block_tint[course][shifted // h % 2] * (0.85 + 0.3 * grain(x, y))
        return tuple(c * shade for c in (0.78, 0.7, 0.58))

    def tiles(x, y):  # an 8 x 8 checker of two marbles
        base = (0.85, 0.82, 0.76) if (x // e + y // e) % 2 else (0.45, 0.3, 0.25)
        return tuple(c * (0.8 + 0.2 * marble(x, y)) for c in base)

    def plaster(x, y):
        return tuple(c * (0.8 + 0.2 * blotches(x, y)) for c in (0.92, 0.88, 0.8))

    def wood(x, y):
        shade = 0.75 + 0.25 * math.sin(x * 2 * math.pi * 12 / SIZE + 6 * rings(x, y))
        return tuple(c * shade for c in (0.55, 0.36, 0.2))

    def balustrade(x, y):  # balusters between two rails; one channel, 1 solid
        baluster = abs(x % (SIZE // 8) - SIZE // 16) < (SIZE // 80) * (1.3 + math.sin(y * math.pi / SIZE))
        rail = y < SIZE // 10 or y >= SIZE - SIZE // 10
        return (1.0 if baluster or rail else 0.0,)

    def grille(x, y):  # square bars
        return (1.0 if x % q < SIZE // 24 or y % q < SIZE // 24 else 0.0,)

    return {'stone.png': (3, stone), 'tiles.png': (3, tiles), 'plaster.png': (3, plaster),
            'wood.png': (3, wood), 'balustrade.png': (1, balustrade), 'grille.png': (1, grille)}


def dress(obj, work):
    """Writes `work`/textured-<name>.obj (`obj` with mtllib and a usemtl after each named group),
    its MTL and textures, and returns the new OBJ's path. Reuses them while `obj` is older."""
    stem = 'textured-' + os.path.splitext(os.path.basename(obj))[0]
    out = os.path.abspath(os.path.join(work, stem + '.obj'))
    if os.path.exists(out) and os.path.getmtime(out) >= max(os.path.getmtime(obj),
                                                            os.path.getmtime(__file__)):
        return out
    for name, (channels, pixel) in textures(random.Random(20)).items():
        write_png(os.path.join(work, name), SIZE, SIZE, channels, pixel)
    groups = []
    with open(obj, errors='replace') as f, open(out + '.tmp', 'w') as g:
        g.write('mtllib %s.mtl\n' % stem)
        for line in f:
            g.write(line)
            words = line.split()
            if len(words) == 2 and words[0] == 'g':
                groups.append(words[1])
                g.write('usemtl %s\n' % words[1])
    with open(os.path.join(work, stem + '.mtl'), 'w') as m:
        m.write('# Generated by bench/dress_sponza.py for the Dabrovic Sponza\n')
        for name in groups:
            m.write('\nnewmtl %s\n' % name)
            for statement in MATERIALS.get(name, DEFAULT):
                m.write(statement + '\n')
    os.replace(out + '.tmp', out)
    return out
