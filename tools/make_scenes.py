#!/usr/bin/env python3
"""Write hipr's small glTF 2.0 test scenes into assets/scenes/.

Usage: python3 tools/make_scenes.py [--out DIR]
       python3 tools/make_scenes.py --triangles N --out DIR   (a big terrain: tools/big_scene.py)

The output is byte-for-byte deterministic so the generated files can be
committed and checked against a fresh run (tools/test_make_scenes.py):
every float is rounded to float32 (what the renderer loads) and written as
the shortest decimal that reads back as that float32, JSON objects keep a
fixed key order, and nothing depends on the time or the environment.

Conventions: meters, +Y up, cameras look down their local -Z, triangles
are counter-clockwise seen from their front side.
"""

import argparse
import base64
import json
import math
import struct
import sys
from pathlib import Path

import lamp_hall  # beside this file

GENERATOR = "hipr make_scenes.py"
DEFAULT_OUT_DIR = Path(__file__).resolve().parent.parent / "assets" / "scenes"

UP = (0.0, 1.0, 0.0)
DOWN = (0.0, -1.0, 0.0)

# glTF enums.
FLOAT = 5126
UNSIGNED_SHORT = 5123
ARRAY_BUFFER = 34962
ELEMENT_ARRAY_BUFFER = 34963
TRIANGLES = 4
GLB_MAGIC = b"glTF"
GLB_CHUNK_JSON = 0x4E4F534A
GLB_CHUNK_BIN = 0x004E4942


def mm(value):
    """Millimeters (the unit of the Cornell measurements) to meters."""
    return value / 1000.0


# --- Cornell box ----------------------------------------------------------
# Measured data from the Cornell Program of Computer Graphics "Cornell Box
# Data" page (graphics.cornell.edu/online/box/data.html), in millimeters.
# The measured walls are slightly skewed (the floor is 552.8 mm wide at the
# front and 549.6 mm at the back); they are squared up to the largest
# extents so every wall is exactly axis-aligned.
BOX_SIZE = (mm(556.0), mm(548.8), mm(559.2))  # x, y, z extents from the origin

# Block footprints: the (x, z) corners of each block's top face, in order
# around the block, as measured. The blocks are rotated about +Y.
SHORT_BLOCK_FOOTPRINT = [(130.0, 65.0), (82.0, 225.0), (240.0, 272.0), (290.0, 114.0)]
SHORT_BLOCK_HEIGHT = mm(165.0)
TALL_BLOCK_FOOTPRINT = [(423.0, 247.0), (265.0, 296.0), (314.0, 456.0), (472.0, 406.0)]
TALL_BLOCK_HEIGHT = mm(330.0)

# The measured light is 130 x 105 mm in the ceiling plane; it is lowered
# 0.5 mm so it does not coincide with the ceiling.
LIGHT_MIN_XZ = (mm(213.0), mm(227.0))
LIGHT_MAX_XZ = (mm(343.0), mm(332.0))
LIGHT_Y = BOX_SIZE[1] - mm(0.5)

# Pinhole camera at (278, 273, -800) mm looking down +Z with a 35 mm lens
# on 25 x 25 mm film.
CAMERA_POSITION = (mm(278.0), mm(273.0), mm(-800.0))
CAMERA_YFOV = 2.0 * math.atan(mm(25.0) / 2.0 / mm(35.0))
# 180 degrees about +Y turns glTF's -Z view direction into +Z. Written out
# because sin/cos of pi would leave a 1e-16 residue in the w component.
CAMERA_ROTATION = (0.0, 1.0, 0.0, 0.0)

TALL_BLOCK_MOVE = (0.06, 0.0, -0.08)  # the edit cornell_box_moved.gltf bakes in

SPHERE_RADIUS = 0.08
LAMP_POSITION = (0.278, 0.45, 0.28)


# --- Deterministic floats ---------------------------------------------------

def f32(x):
    """Round to the nearest float32; -0.0 becomes 0.0 so it never shows up in output."""
    return struct.unpack("<f", struct.pack("<f", x))[0] + 0.0


def shortest_f32(x):
    """The double of the shortest decimal that reads back as f32(x).

    json.dumps prints that double with exactly those digits, so the JSON
    shows 0.5488 rather than 0.5487999916076660.
    """
    value = f32(x)
    for digits in range(1, 9):
        candidate = float(f"{value:.{digits}g}")
        if f32(candidate) == value:
            return candidate
    return float(f"{value:.9g}")  # 9 significant digits always round-trip a float32


def clean_floats(value):
    """Apply shortest_f32 to every float inside a JSON-like value."""
    if isinstance(value, float):
        return shortest_f32(value)
    if isinstance(value, list | tuple):
        return [clean_floats(item) for item in value]
    if isinstance(value, dict):
        return {key: clean_floats(item) for key, item in value.items()}
    return value


def json_bytes(value, compact=False):
    """UTF-8 JSON with a trailing newline; compact drops all optional whitespace."""
    if compact:
        text = json.dumps(clean_floats(value), separators=(",", ":"))
    else:
        text = json.dumps(clean_floats(value), indent=2)
    return (text + "\n").encode("utf-8")


# --- Vectors -------------------------------------------------------------

def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(v):
    length = math.sqrt(dot(v, v))
    return tuple(x / length for x in v)


def yaw_quaternion(angle):
    """Quaternion (x, y, z, w) rotating by `angle` radians about +Y."""
    return (0.0, math.sin(angle / 2.0), 0.0, math.cos(angle / 2.0))


# --- Meshes ---------------------------------------------------------------

class Mesh:
    """Indexed triangles with a position, normal and texcoord per vertex."""

    def __init__(self):
        self.positions = []
        self.normals = []
        self.uvs = []
        self.indices = []

    def add_vertex(self, position, normal, uv):
        self.positions.append(position)
        self.normals.append(normal)
        self.uvs.append(uv)
        return len(self.positions) - 1

    def add_quad(self, corners, facing):
        """Add a flat planar quad whose front side faces along `facing`.

        The corners may come in either order around the quad; they are
        reversed if needed so the triangles are counter-clockwise seen from
        the front, and the flat normal points the same way.
        """
        normal = normalize(cross(sub(corners[1], corners[0]), sub(corners[2], corners[0])))
        if dot(normal, facing) < 0.0:
            corners = corners[::-1]
            normal = tuple(-x for x in normal)
        uvs = ((0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0))
        first = len(self.positions)
        for corner, uv in zip(corners, uvs):
            self.add_vertex(corner, normal, uv)
        self.indices += [first, first + 1, first + 2, first, first + 2, first + 3]


def axis_rect(axis, at, lo, hi):
    """Corners, in order around it, of the rectangle perpendicular to `axis`
    at coordinate `at` spanning lo..hi on the two other axes."""
    u, v = [a for a in range(3) if a != axis]
    corners = []
    for cu, cv in ((lo[u], lo[v]), (hi[u], lo[v]), (hi[u], hi[v]), (lo[u], hi[v])):
        point = [0.0, 0.0, 0.0]
        point[axis], point[u], point[v] = at, cu, cv
        corners.append(tuple(point))
    return corners


def quad_mesh(corners, facing):
    mesh = Mesh()
    mesh.add_quad(corners, facing)
    return mesh


def prism_mesh(footprint, height):
    """Closed box with vertical sides over a convex (x, z) footprint centered
    on the origin, from y = 0 to `height`, with flat outward normals."""
    mesh = Mesh()
    bottom = [(x, 0.0, z) for x, z in footprint]
    top = [(x, height, z) for x, z in footprint]
    mesh.add_quad(top, UP)
    mesh.add_quad(bottom, DOWN)
    for i in range(len(footprint)):
        j = (i + 1) % len(footprint)
        # The footprint is centered on the origin, so the side's horizontal
        # midpoint points away from the block.
        outward = ((bottom[i][0] + bottom[j][0]) / 2.0, 0.0, (bottom[i][2] + bottom[j][2]) / 2.0)
        mesh.add_quad([bottom[i], bottom[j], top[j], top[i]], outward)
    return mesh


def uv_sphere_mesh(radius, segments, rings):
    """Smooth UV sphere centered on the origin; u runs around +Y, v from the
    north (+Y) pole to the south pole. The seam and poles repeat vertices so
    every vertex has a single texcoord."""
    mesh = Mesh()
    for ring in range(rings + 1):
        theta = math.pi * ring / rings
        for segment in range(segments + 1):
            phi = 2.0 * math.pi * segment / segments
            normal = (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))
            position = tuple(radius * x for x in normal)
            mesh.add_vertex(position, normal, (segment / segments, ring / rings))

    def vertex(ring, segment):
        return ring * (segments + 1) + segment

    # Going down a ring then along a segment is counter-clockwise seen from
    # outside. The triangle touching a pole would be degenerate, so skip it.
    for ring in range(rings):
        for segment in range(segments):
            a, b = vertex(ring, segment), vertex(ring, segment + 1)
            c, d = vertex(ring + 1, segment), vertex(ring + 1, segment + 1)
            if ring != 0:
                mesh.indices += [a, d, b]
            if ring != rings - 1:
                mesh.indices += [a, c, d]
    return mesh


# --- Materials ---------------------------------------------------------------

def lambert_material(name, base_color):
    """Pure diffuse: no metal, full roughness and no specular lobe at all."""
    return {
        "name": name,
        "pbrMetallicRoughness": {
            "baseColorFactor": [*base_color, 1.0],
            "metallicFactor": 0.0,
            "roughnessFactor": 1.0,
        },
        "doubleSided": False,
        "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}},
    }


def emissive_material(name, color, strength):
    """Black Lambert surface that emits `color` scaled by `strength`."""
    material = lambert_material(name, (0.0, 0.0, 0.0))
    material["emissiveFactor"] = list(color)
    material["extensions"]["KHR_materials_emissive_strength"] = {"emissiveStrength": strength}
    return material


WHITE = lambert_material("white", (0.73, 0.73, 0.73))
RED = lambert_material("red", (0.63, 0.065, 0.05))
GREEN = lambert_material("green", (0.14, 0.45, 0.091))
LIGHT = emissive_material("light", (1.0, 0.7059, 0.2353), 17.0)
WHITE_LAMBERT = lambert_material("white_lambert", (1.0, 1.0, 1.0))


# --- glTF document ------------------------------------------------------------

class GltfDocument:
    """Collects nodes, meshes and materials of a single-scene glTF and packs
    all vertex data into one binary buffer."""

    def __init__(self, scene_name):
        self.scene_name = scene_name
        self.binary = bytearray()
        self.extensions_used = set()
        self.nodes, self.meshes, self.materials, self.cameras = [], [], [], []
        self.lights, self.accessors, self.buffer_views = [], [], []

    def add_mesh_node(self, name, mesh, material, translation=None, rotation=None):
        primitive = {
            "attributes": {
                "POSITION": self._add_floats(mesh.positions, "VEC3", bounds=True),
                "NORMAL": self._add_floats(mesh.normals, "VEC3"),
                "TEXCOORD_0": self._add_floats(mesh.uvs, "VEC2"),
            },
            "indices": self._add_indices(mesh.indices),
            "material": self._material_index(material),
            "mode": TRIANGLES,
        }
        self.meshes.append({"name": name, "primitives": [primitive]})
        self._add_node(name, translation, rotation, mesh=len(self.meshes) - 1)

    def add_camera_node(self, name, yfov, translation, rotation=None, aspect_ratio=None):
        camera = {"yfov": yfov, "znear": 0.01}
        if aspect_ratio is not None:
            camera["aspectRatio"] = aspect_ratio
        self.cameras.append({"name": name, "type": "perspective", "perspective": camera})
        self._add_node(name, translation, rotation, camera=len(self.cameras) - 1)

    def add_point_light_node(self, name, position, intensity, color):
        self.extensions_used.add("KHR_lights_punctual")
        self.lights.append({"name": name, "type": "point", "color": list(color), "intensity": intensity})
        light_ref = {"KHR_lights_punctual": {"light": len(self.lights) - 1}}
        self._add_node(name, position, None, extensions=light_ref)

    def to_json(self, buffer):
        """The glTF JSON with `buffer` as its only buffer entry. Empty arrays
        are left out because the glTF schema forbids them."""
        doc = {"asset": {"generator": GENERATOR, "version": "2.0"}}
        if self.extensions_used:
            doc["extensionsUsed"] = sorted(self.extensions_used)
        doc["scene"] = 0
        doc["scenes"] = [{"name": self.scene_name, "nodes": list(range(len(self.nodes)))}]
        for key, items in (("nodes", self.nodes), ("cameras", self.cameras), ("meshes", self.meshes),
                           ("materials", self.materials), ("accessors", self.accessors),
                           ("bufferViews", self.buffer_views)):
            if items:
                doc[key] = items
        doc["buffers"] = [buffer]
        if self.lights:
            doc["extensions"] = {"KHR_lights_punctual": {"lights": self.lights}}
        return doc

    def _add_node(self, name, translation, rotation, **fields):
        node = {"name": name}
        if translation is not None:
            node["translation"] = list(translation)
        if rotation is not None:
            node["rotation"] = list(rotation)
        node.update(fields)
        self.nodes.append(node)

    def _material_index(self, material):
        names = [m["name"] for m in self.materials]
        if material["name"] in names:
            return names.index(material["name"])
        self.materials.append(material)
        self.extensions_used.update(material.get("extensions", {}))
        return len(self.materials) - 1

    def _add_buffer_view(self, data, target):
        # Each view starts 4-byte aligned, as float accessors require.
        self.binary += b"\0" * (-len(self.binary) % 4)
        view = {"buffer": 0, "byteOffset": len(self.binary), "byteLength": len(data), "target": target}
        self.binary += data
        self.buffer_views.append(view)
        return len(self.buffer_views) - 1

    def _add_accessor(self, accessor):
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def _add_floats(self, vectors, kind, bounds=False):
        flat = [f32(x) for v in vectors for x in v]
        view = self._add_buffer_view(struct.pack(f"<{len(flat)}f", *flat), ARRAY_BUFFER)
        accessor = {"bufferView": view, "componentType": FLOAT, "count": len(vectors), "type": kind}
        if bounds:
            # Bounds of the float32 values actually stored, not of the doubles.
            width = len(vectors[0])
            accessor["min"] = [min(flat[i::width]) for i in range(width)]
            accessor["max"] = [max(flat[i::width]) for i in range(width)]
        return self._add_accessor(accessor)

    def _add_indices(self, indices):
        # Every scene here has far fewer than 65536 vertices per mesh.
        data = struct.pack(f"<{len(indices)}H", *indices)
        view = self._add_buffer_view(data, ELEMENT_ARRAY_BUFFER)
        return self._add_accessor(
            {"bufferView": view, "componentType": UNSIGNED_SHORT, "count": len(indices), "type": "SCALAR"})


# --- Scenes -----------------------------------------------------------------

def block_yaw(footprint):
    """Rotation about +Y (radians) that lines a block's local X/Z axes up with
    its measured edges: the mean edge direction folded into [-45, 45) degrees."""
    angles = []
    for (x0, z0), (x1, z1) in zip(footprint, footprint[1:] + footprint[:1]):
        # Rotating local +X by `angle` about +Y gives (cos, 0, -sin).
        angle = math.atan2(-(z1 - z0), x1 - x0)
        angles.append((angle + math.pi / 4.0) % (math.pi / 2.0) - math.pi / 4.0)
    return sum(angles) / len(angles)


def footprint_center(footprint):
    """Mean of the measured (x, z) corners, in meters."""
    return (mm(sum(x for x, _ in footprint) / len(footprint)), mm(sum(z for _, z in footprint) / len(footprint)))


def add_block(doc, name, footprint, height, offset=(0.0, 0.0, 0.0)):
    """Add a measured block as a mesh in its own frame (centered on its
    footprint, y from 0), placed by the node's translation and yaw so that
    the world-space corners are the measured ones."""
    cx, cz = footprint_center(footprint)
    yaw = block_yaw(footprint)
    cos_yaw, sin_yaw = math.cos(yaw), math.sin(yaw)
    # Undo the node's yaw: world (x, z) = R(yaw) local, so local = R(-yaw) world.
    local = []
    for x, z in footprint:
        dx, dz = mm(x) - cx, mm(z) - cz
        local.append((dx * cos_yaw - dz * sin_yaw, dx * sin_yaw + dz * cos_yaw))
    translation = (cx + offset[0], offset[1], cz + offset[2])
    doc.add_mesh_node(name, prism_mesh(local, height), WHITE, translation, yaw_quaternion(yaw))


def add_room(doc):
    """Floor, ceiling and the three walls, all facing into the box; the -Z
    side is open towards the camera."""
    width, height, depth = BOX_SIZE
    origin = (0.0, 0.0, 0.0)
    walls = [
        ("floor", axis_rect(1, 0.0, origin, BOX_SIZE), UP, WHITE),
        ("ceiling", axis_rect(1, height, origin, BOX_SIZE), DOWN, WHITE),
        ("back_wall", axis_rect(2, depth, origin, BOX_SIZE), (0.0, 0.0, -1.0), WHITE),
        # The camera looks down +Z, so the +X wall is the one on its left.
        ("left_wall", axis_rect(0, width, origin, BOX_SIZE), (-1.0, 0.0, 0.0), RED),
        ("right_wall", axis_rect(0, 0.0, origin, BOX_SIZE), (1.0, 0.0, 0.0), GREEN),
    ]
    for name, corners, facing, material in walls:
        doc.add_mesh_node(name, quad_mesh(corners, facing), material)


def add_area_light(doc):
    """The classic ceiling light: a single-sided quad facing down."""
    lo = (LIGHT_MIN_XZ[0], 0.0, LIGHT_MIN_XZ[1])
    hi = (LIGHT_MAX_XZ[0], 0.0, LIGHT_MAX_XZ[1])
    doc.add_mesh_node("light", quad_mesh(axis_rect(1, LIGHT_Y, lo, hi), DOWN), LIGHT)


def add_cornell_camera(doc):
    doc.add_camera_node("camera", CAMERA_YFOV, CAMERA_POSITION, CAMERA_ROTATION, aspect_ratio=1.0)


def cornell_box(tall_block_offset=(0.0, 0.0, 0.0)):
    doc = GltfDocument("cornell_box")
    add_room(doc)
    add_block(doc, "short_block", SHORT_BLOCK_FOOTPRINT, SHORT_BLOCK_HEIGHT)
    add_block(doc, "tall_block", TALL_BLOCK_FOOTPRINT, TALL_BLOCK_HEIGHT, tall_block_offset)
    add_area_light(doc)
    add_cornell_camera(doc)
    return doc


def cornell_sphere():
    """The Cornell box with a sphere resting where the short block stood,
    plus a point lamp in addition to the area light."""
    doc = GltfDocument("cornell_sphere")
    add_room(doc)
    cx, cz = footprint_center(SHORT_BLOCK_FOOTPRINT)
    doc.add_mesh_node("sphere", uv_sphere_mesh(SPHERE_RADIUS, 32, 16), WHITE, (cx, SPHERE_RADIUS, cz))
    add_block(doc, "tall_block", TALL_BLOCK_FOOTPRINT, TALL_BLOCK_HEIGHT)
    add_area_light(doc)
    doc.add_point_light_node("lamp", LAMP_POSITION, 0.5, (1.0, 1.0, 1.0))
    add_cornell_camera(doc)
    return doc


def furnace_sphere():
    """A white Lambert unit sphere for furnace tests under a uniform environment."""
    doc = GltfDocument("furnace_sphere")
    doc.add_mesh_node("sphere", uv_sphere_mesh(1.0, 64, 32), WHITE_LAMBERT)
    doc.add_camera_node("camera", 0.6, (0.0, 0.0, 4.0))
    return doc


CORNELL_BOX_EDITS = {"edits": [
    {"op": "transform", "node": "tall_block", "translate": list(TALL_BLOCK_MOVE)},
    {"op": "material", "material": "red", "set": {"base_color": [0.05, 0.1, 0.65]}},
]}

CORNELL_SPHERE_EDITS = {"edits": [
    {"op": "transform", "node": "sphere", "translate": [-0.1, 0.0, 0.05]},
    {"op": "light", "node": "lamp", "set": {"intensity": 2.0, "color": [1.0, 0.9, 0.8]}},
    {"op": "emission", "material": "light", "set": {"emission_luminance": 30.0}},
    {"op": "visibility", "node": "tall_block", "visible": False},
]}

README = """\
# Test scenes

Generated by tools/make_scenes.py — do not edit by hand. Regenerate with
`python3 tools/make_scenes.py` and check with `python3 tools/test_make_scenes.py`.

| File | Purpose |
| --- | --- |
| `cornell_box.gltf` + `cornell_box.bin` | Classic Cornell box from the Cornell measurement data, in meters: Lambert walls, rotated blocks, area light, the classic 35 mm camera. |
| `cornell_box.edits.json` | Edit script: move `tall_block` by (0.06, 0, -0.08), recolor the `red` material. |
| `cornell_box_moved.gltf` + `cornell_box_moved.bin` | `cornell_box` with the `tall_block` move already applied; reference for the transform edit. |
| `cornell_sphere.glb` | Binary glTF: the Cornell box with a sphere in place of the short block and a `lamp` point light (KHR_lights_punctual). |
| `cornell_sphere.edits.json` | Edit script: transform, light, emission and visibility edits on `cornell_sphere.glb`. |
| `furnace_sphere.gltf` | White Lambert unit sphere with an embedded (data URI) buffer and no lights, for furnace tests. |
| `lamp_hall.glb` | Many lights: a pillared hall 24 x 16 m lit only by 96 small emissive ceiling panels (four colours) and 48 point lamps (tools/lamp_hall.py). |
| `lamp_hall.edits.json` | Edit script: recolour a lamp, move another, dim the amber panels. |
"""


# --- Output ---------------------------------------------------------------

def write_gltf_external(doc, path):
    """.gltf JSON next to a .bin file of the same stem."""
    bin_path = path.with_suffix(".bin")
    bin_path.write_bytes(bytes(doc.binary))
    buffer = {"byteLength": len(doc.binary), "uri": bin_path.name}
    path.write_bytes(json_bytes(doc.to_json(buffer)))


def write_gltf_embedded(doc, path):
    """.gltf JSON with the buffer inlined as a base64 data URI."""
    uri = "data:application/octet-stream;base64," + base64.b64encode(doc.binary).decode("ascii")
    path.write_bytes(json_bytes(doc.to_json({"byteLength": len(doc.binary), "uri": uri})))


def glb_chunk(chunk_type, data, pad_byte):
    """One GLB chunk, padded to a multiple of 4 bytes as the container requires."""
    data = data + pad_byte * (-len(data) % 4)
    return struct.pack("<II", len(data), chunk_type) + data


def write_glb(doc, path):
    """Binary glTF: header, JSON chunk padded with spaces, BIN chunk padded with zeros."""
    json_data = json_bytes(doc.to_json({"byteLength": len(doc.binary)}), compact=True)
    chunks = glb_chunk(GLB_CHUNK_JSON, json_data, b" ") + glb_chunk(GLB_CHUNK_BIN, bytes(doc.binary), b"\0")
    header = struct.pack("<4sII", GLB_MAGIC, 2, 12 + len(chunks))
    path.write_bytes(header + chunks)


def write_all(out_dir):
    out_dir.mkdir(parents=True, exist_ok=True)
    write_gltf_external(cornell_box(), out_dir / "cornell_box.gltf")
    (out_dir / "cornell_box.edits.json").write_bytes(json_bytes(CORNELL_BOX_EDITS))
    write_gltf_external(cornell_box(TALL_BLOCK_MOVE), out_dir / "cornell_box_moved.gltf")
    write_glb(cornell_sphere(), out_dir / "cornell_sphere.glb")
    (out_dir / "cornell_sphere.edits.json").write_bytes(json_bytes(CORNELL_SPHERE_EDITS))
    write_gltf_embedded(furnace_sphere(), out_dir / "furnace_sphere.gltf")
    write_glb(lamp_hall.lamp_hall(sys.modules[__name__]), out_dir / "lamp_hall.glb")
    (out_dir / "lamp_hall.edits.json").write_bytes(json_bytes(lamp_hall.LAMP_HALL_EDITS))
    (out_dir / "README.md").write_bytes(README.encode("utf-8"))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT_DIR,
                        help="output directory (default: assets/scenes)")
    parser.add_argument("--triangles", type=int,
                        help="instead, write terrain_<N>.glb: a terrain of at least N triangles")
    args = parser.parse_args(argv)
    if args.triangles is None:
        write_all(args.out)
        return
    if args.triangles < 1:
        parser.error("--triangles must be at least 1")
    import big_scene  # beside this file: only the big-scene mode needs it
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / f"terrain_{args.triangles}.glb"
    count = big_scene.write_terrain(args.triangles, path)
    print(f"wrote {path}: {count} triangles, {path.stat().st_size} bytes")


if __name__ == "__main__":
    main()
