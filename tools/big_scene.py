"""A generated terrain of any triangle count, for hipr's big-scene measurements.

Used through `python3 tools/make_scenes.py --triangles N [--out DIR]`, which writes
`terrain_<N>.glb` (BENCHMARKS.md "Big scenes" runs it from 1k to 10M triangles).

The terrain is a square of rolling hills cut into tiles, each tile its own mesh and node (as
an exported landscape is), with float positions and normals and 32-bit indices: 24 bytes per
vertex and 12 per triangle in the file, nothing compressed. A camera looks over it; there are
no lights, so hipr lights it with its default environment. The output is deterministic.
"""

import array
import json
import math
import struct
import sys

from make_scenes import (ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, FLOAT, GLB_CHUNK_BIN, GLB_CHUNK_JSON,
                         GLB_MAGIC, TRIANGLES, glb_chunk)

UNSIGNED_INT = 5125

SIDE = 100.0  # meters across the whole terrain
MAX_QUADS_PER_TILE = 256 * 256  # a tile is at most 131072 triangles


def tiling(triangles):
    """(tiles per side, quads per tile side) giving at least `triangles` triangles."""
    quads = max(1, (triangles + 1) // 2)
    tiles = max(1, math.ceil(math.sqrt(quads / MAX_QUADS_PER_TILE)))
    per_side = max(1, math.ceil(math.sqrt(quads / (tiles * tiles))))
    return tiles, per_side


def height_and_slope(x, z):
    """Hills: two crossed waves. Returns h and its partial derivatives (dh/dx, dh/dz)."""
    a, ka, kb = 3.0, 0.11, 0.07
    b, kc = 1.2, 0.31
    h = a * math.sin(ka * x) * math.cos(kb * z) + b * math.cos(kc * x) * math.sin(kc * z)
    dx = a * ka * math.cos(ka * x) * math.cos(kb * z) - b * kc * math.sin(kc * x) * math.sin(kc * z)
    dz = -a * kb * math.sin(ka * x) * math.sin(kb * z) + b * kc * math.cos(kc * x) * math.cos(kc * z)
    return h, dx, dz


def tile_vertices(x0, z0, size, n):
    """Positions and normals (float32, little-endian bytes) of an (n+1) x (n+1) grid, and the
    position bounds glTF requires."""
    positions = array.array("f")
    normals = array.array("f")
    lo = [math.inf] * 3
    hi = [-math.inf] * 3
    step = size / n
    for j in range(n + 1):
        z = z0 + j * step
        for i in range(n + 1):
            x = x0 + i * step
            h, dx, dz = height_and_slope(x, z)
            inv = 1.0 / math.sqrt(dx * dx + 1.0 + dz * dz)
            positions.extend((x, h, z))
            normals.extend((-dx * inv, inv, -dz * inv))
    for k in range(3):
        column = positions[k::3]
        lo[k], hi[k] = min(column), max(column)
    if sys.byteorder != "little":
        positions.byteswap()
        normals.byteswap()
    return positions.tobytes(), normals.tobytes(), lo, hi


def grid_indices(n):
    """Two counter-clockwise (seen from +Y) triangles per quad of an (n+1)-wide grid."""
    indices = array.array("I")
    row = n + 1
    for j in range(n):
        for i in range(n):
            a = j * row + i
            indices.extend((a, a + row, a + 1, a + 1, a + row, a + row + 1))
    if sys.byteorder != "little":
        indices.byteswap()
    return indices.tobytes()


def terrain_glb(triangles):
    """The GLB bytes of a terrain of at least `triangles` triangles, and its exact count."""
    tiles, n = tiling(triangles)
    tile_size = SIDE / tiles
    indices = grid_indices(n)  # every tile has the same topology (each still gets its own copy)
    binary = bytearray()
    views, accessors, meshes, nodes = [], [], [], []

    def add_view(data, target):
        binary.extend(b"\0" * (-len(binary) % 4))
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data), "target": target})
        binary.extend(data)
        return len(views) - 1

    vertex_count = (n + 1) * (n + 1)
    for ty in range(tiles):
        for tx in range(tiles):
            x0 = -SIDE / 2 + tx * tile_size
            z0 = -SIDE / 2 + ty * tile_size
            positions, normals, lo, hi = tile_vertices(x0, z0, tile_size, n)
            first = len(accessors)
            accessors.append({"bufferView": add_view(positions, ARRAY_BUFFER), "componentType": FLOAT,
                              "count": vertex_count, "type": "VEC3", "min": lo, "max": hi})
            accessors.append({"bufferView": add_view(normals, ARRAY_BUFFER), "componentType": FLOAT,
                              "count": vertex_count, "type": "VEC3"})
            accessors.append({"bufferView": add_view(indices, ELEMENT_ARRAY_BUFFER),
                              "componentType": UNSIGNED_INT, "count": 6 * n * n, "type": "SCALAR"})
            meshes.append({"name": f"tile_{tx}_{ty}", "primitives": [{
                "attributes": {"POSITION": first, "NORMAL": first + 1}, "indices": first + 2,
                "material": 0, "mode": TRIANGLES}]})
            nodes.append({"name": f"tile_{tx}_{ty}", "mesh": len(meshes) - 1})

    # A camera 40 m up at the south edge, pitched 30 degrees down over the terrain.
    pitch = math.radians(-30.0)
    nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 40.0, SIDE * 0.55],
                  "rotation": [math.sin(pitch / 2), 0.0, 0.0, math.cos(pitch / 2)]})
    document = {
        "asset": {"version": "2.0", "generator": "hipr make_scenes.py --triangles"},
        "scene": 0,
        "scenes": [{"name": f"terrain_{triangles}", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": [{"name": "ground", "pbrMetallicRoughness": {
            "baseColorFactor": [0.45, 0.42, 0.3, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.8}}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(binary)}],
    }
    json_data = json.dumps(document, separators=(",", ":")).encode("utf-8")
    chunks = glb_chunk(GLB_CHUNK_JSON, json_data, b" ") + glb_chunk(GLB_CHUNK_BIN, bytes(binary), b"\0")
    header = struct.pack("<4sII", GLB_MAGIC, 2, 12 + len(chunks))
    return header + chunks, tiles * tiles * 2 * n * n


def write_terrain(triangles, path):
    """Writes terrain_<N>.glb-style output to `path`; returns the exact triangle count."""
    data, count = terrain_glb(triangles)
    with open(path, "wb") as out:
        out.write(data)
    return count
