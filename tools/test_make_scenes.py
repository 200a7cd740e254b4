#!/usr/bin/env python3
"""Tests for tools/make_scenes.py and the scenes it committed to assets/scenes/.

Run: python3 tools/test_make_scenes.py   (exits non-zero on failure)

The glTF checks read the files back with an independent minimal loader
rather than reusing make_scenes.py, so a bug in the generator cannot hide
itself.
"""

import base64
import json
import math
import struct
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "tools" / "make_scenes.py"
COMMITTED_DIR = ROOT / "assets" / "scenes"

SCENE_FILES = ["cornell_box.gltf", "cornell_box_moved.gltf", "cornell_sphere.glb", "furnace_sphere.gltf",
               "lamp_hall.glb"]
CORNELL_NODES = {"floor", "ceiling", "back_wall", "left_wall", "right_wall", "tall_block", "light", "camera"}
EXPECTED_NODES = {
    "cornell_box.gltf": CORNELL_NODES | {"short_block"},
    "cornell_box_moved.gltf": CORNELL_NODES | {"short_block"},
    "cornell_sphere.glb": CORNELL_NODES | {"sphere", "lamp"},
    "furnace_sphere.gltf": {"sphere", "camera"},
    "lamp_hall.glb": {"floor", "ceiling", "wall_east", "wall_west", "wall_north", "wall_south", "camera"}
    | {"pillar_%d_%d" % (i, j) for i in range(5) for j in range(3)}
    | {"lamp_%d_%d_%d" % (i, j, k) for i in range(5) for j in range(3) for k in range(2)}
    | {"wall_lamp_%s_%d" % (side, i) for side in ("north", "south") for i in range(9)}
    | {"panels_" + colour for colour in ("warm", "cool", "white", "amber")},
}
BOX_CENTER = (0.556 / 2, 0.5488 / 2, 0.5592 / 2)
WALLS = ["floor", "ceiling", "back_wall", "left_wall", "right_wall"]

COMPONENT_FORMATS = {5126: "f", 5125: "I", 5123: "H", 5121: "B"}
TYPE_WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}


def generate(out_dir):
    subprocess.run([sys.executable, str(SCRIPT), "--out", str(out_dir)], check=True)


def read_dir(directory):
    return {path.name: path.read_bytes() for path in sorted(directory.iterdir())}


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


# --- Minimal glTF reader -----------------------------------------------------

def parse_glb(data):
    """Split a GLB container into (json, bin), checking the layout rules."""
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2, "bad GLB header"
    assert length == len(data), "GLB length does not match the file size"
    chunks, offset = [], 12
    while offset < len(data):
        chunk_length, chunk_type = struct.unpack_from("<II", data, offset)
        assert chunk_length % 4 == 0, "GLB chunk not padded to 4 bytes"
        chunks.append((chunk_type, data[offset + 8:offset + 8 + chunk_length]))
        offset += 8 + chunk_length
    assert offset == len(data), "GLB chunks overrun the file"
    assert [t for t, _ in chunks] == [0x4E4F534A, 0x004E4942], "expected a JSON chunk then a BIN chunk"
    return chunks[0][1], chunks[1][1]


def load_scene(path):
    """Return (gltf JSON, list of buffer bytes) for a .gltf or .glb file."""
    if path.suffix == ".glb":
        json_chunk, bin_chunk = parse_glb(path.read_bytes())
        return json.loads(json_chunk), [bin_chunk]
    doc = json.loads(path.read_bytes())
    buffers = []
    for buffer in doc["buffers"]:
        uri = buffer["uri"]
        if uri.startswith("data:"):
            buffers.append(base64.b64decode(uri.split(",", 1)[1]))
        else:
            buffers.append((path.parent / uri).read_bytes())
    return doc, buffers


def accessor_values(doc, buffers, index):
    """The accessor's elements as tuples, checking it stays inside its view."""
    accessor = doc["accessors"][index]
    view = doc["bufferViews"][accessor["bufferView"]]
    fmt = COMPONENT_FORMATS[accessor["componentType"]]
    width = TYPE_WIDTHS[accessor["type"]]
    element_size = struct.calcsize("<" + fmt) * width
    stride = view.get("byteStride", element_size)
    start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
    view_end = view.get("byteOffset", 0) + view["byteLength"]
    assert view_end <= len(buffers[view["buffer"]]), "buffer view runs past its buffer"
    assert start + stride * (accessor["count"] - 1) + element_size <= view_end, "accessor runs past its view"
    data = buffers[view["buffer"]]
    return [struct.unpack_from(f"<{width}{fmt}", data, start + i * stride) for i in range(accessor["count"])]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def quat_rotate(q, v):
    """Rotate v by the unit quaternion q = (x, y, z, w)."""
    qv, w = q[:3], q[3]
    t = tuple(2 * c for c in cross(qv, v))
    return tuple(v[i] + w * t[i] + cross(qv, t)[i] for i in range(3))


class WorldMesh:
    """A node's triangles in world space (the scenes have no node hierarchy)."""

    def __init__(self, doc, buffers, node):
        assert "matrix" not in node and "scale" not in node, "only translation + rotation are handled"
        rotation = node.get("rotation", [0.0, 0.0, 0.0, 1.0])
        translation = node.get("translation", [0.0, 0.0, 0.0])
        (primitive,) = doc["meshes"][node["mesh"]]["primitives"]
        attributes = primitive["attributes"]
        local_positions = accessor_values(doc, buffers, attributes["POSITION"])
        local_normals = accessor_values(doc, buffers, attributes["NORMAL"])
        self.positions = [tuple(a + b for a, b in zip(quat_rotate(rotation, p), translation))
                          for p in local_positions]
        self.normals = [quat_rotate(rotation, n) for n in local_normals]
        indices = [i for (i,) in accessor_values(doc, buffers, primitive["indices"])]
        self.triangles = [tuple(indices[i:i + 3]) for i in range(0, len(indices), 3)]

    def center(self):
        return tuple(sum(p[axis] for p in self.positions) / len(self.positions) for axis in range(3))


def world_meshes(doc, buffers):
    return {node["name"]: WorldMesh(doc, buffers, node) for node in doc["nodes"] if "mesh" in node}


# --- Tests --------------------------------------------------------------------

class TestGeneration(unittest.TestCase):
    def test_output_is_deterministic(self):
        with tempfile.TemporaryDirectory() as first, tempfile.TemporaryDirectory() as second:
            generate(Path(first))
            generate(Path(second))
            self.assertEqual(read_dir(Path(first)), read_dir(Path(second)))

    def test_committed_scenes_are_up_to_date(self):
        with tempfile.TemporaryDirectory() as fresh:
            generate(Path(fresh))
            fresh_files = read_dir(Path(fresh))
        committed = read_dir(COMMITTED_DIR)
        self.assertEqual(sorted(committed), sorted(fresh_files), "assets/scenes has missing or extra files")
        for name, data in fresh_files.items():
            self.assertEqual(committed[name], data, f"{name} is stale: rerun tools/make_scenes.py")


class TestSceneFiles(unittest.TestCase):
    """Structural checks on every generated scene."""

    def scenes(self):
        for name in SCENE_FILES:
            doc, buffers = load_scene(COMMITTED_DIR / name)
            yield name, doc, buffers

    def test_node_names(self):
        for name, doc, _ in self.scenes():
            self.assertEqual({node["name"] for node in doc["nodes"]}, EXPECTED_NODES[name], name)

    def test_generator_and_extensions_declared(self):
        for name, doc, _ in self.scenes():
            self.assertEqual(doc["asset"], {"generator": "hipr make_scenes.py", "version": "2.0"})
            used = set()
            for material in doc["materials"]:
                used.update(material.get("extensions", {}))
            used.update(doc.get("extensions", {}))
            self.assertEqual(set(doc["extensionsUsed"]), used, name)

    def test_position_bounds_match_data(self):
        for name, doc, buffers in self.scenes():
            for mesh in doc["meshes"]:
                accessor_index = mesh["primitives"][0]["attributes"]["POSITION"]
                accessor = doc["accessors"][accessor_index]
                values = accessor_values(doc, buffers, accessor_index)
                for axis in range(3):
                    column = [v[axis] for v in values]
                    self.assertEqual(f32(accessor["min"][axis]), min(column), f"{name} {mesh['name']}")
                    self.assertEqual(f32(accessor["max"][axis]), max(column), f"{name} {mesh['name']}")

    def test_attributes_and_indices(self):
        for name, doc, buffers in self.scenes():
            for mesh in doc["meshes"]:
                (primitive,) = mesh["primitives"]
                attributes = primitive["attributes"]
                self.assertEqual(set(attributes), {"POSITION", "NORMAL", "TEXCOORD_0"})
                count = doc["accessors"][attributes["POSITION"]]["count"]
                for attribute in attributes.values():
                    self.assertEqual(doc["accessors"][attribute]["count"], count)
                indices = doc["accessors"][primitive["indices"]]
                self.assertIn(indices["componentType"], (5123, 5125))
                self.assertEqual(indices["count"] % 3, 0)
                values = accessor_values(doc, buffers, primitive["indices"])
                self.assertLess(max(i for (i,) in values), count, f"{name} {mesh['name']}")

    def test_normals_are_unit_length(self):
        for name, doc, buffers in self.scenes():
            for node_name, mesh in world_meshes(doc, buffers).items():
                for normal in mesh.normals:
                    self.assertAlmostEqual(math.sqrt(dot(normal, normal)), 1.0, delta=1e-5,
                                           msg=f"{name} {node_name}")

    def test_winding_matches_normals(self):
        # Counter-clockwise seen from the front: the geometric normal points
        # the same way as the shading normals.
        for name, doc, buffers in self.scenes():
            for node_name, mesh in world_meshes(doc, buffers).items():
                for a, b, c in mesh.triangles:
                    pa, pb, pc = mesh.positions[a], mesh.positions[b], mesh.positions[c]
                    geometric = cross(sub(pb, pa), sub(pc, pa))
                    shading = tuple(sum(n) for n in zip(mesh.normals[a], mesh.normals[b], mesh.normals[c]))
                    self.assertGreater(dot(geometric, shading), 0.0, f"{name} {node_name} {(a, b, c)}")


class TestBigTerrain(unittest.TestCase):
    """`--triangles N`: the generated terrain of BENCHMARKS.md "Big scenes"."""

    def terrain(self, triangles):
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run([sys.executable, str(SCRIPT), "--triangles", str(triangles), "--out", tmp],
                           check=True, stdout=subprocess.DEVNULL)
            return load_scene(Path(tmp) / f"terrain_{triangles}.glb")

    def test_at_least_the_asked_triangles_in_tiles(self):
        for asked in (1, 1000, 250000, 300000):
            doc, buffers = self.terrain(asked)
            meshes = world_meshes(doc, buffers)
            count = sum(len(mesh.triangles) for mesh in meshes.values())
            self.assertGreaterEqual(count, asked)
            self.assertLess(count, asked * 1.1 + 8, "no more than about what was asked")
            self.assertEqual(len(meshes), len(doc["meshes"]), "one node per tile")
            self.assertTrue(all(len(m.triangles) <= 131072 for m in meshes.values()))
            self.assertEqual(len(doc["cameras"]), 1)

    def test_tiles_are_valid_meshes(self):
        doc, buffers = self.terrain(5000)
        for name, mesh in world_meshes(doc, buffers).items():
            self.assertTrue(all(0 <= i < len(mesh.positions) for t in mesh.triangles for i in t), name)
            for normal in mesh.normals:
                self.assertAlmostEqual(math.sqrt(dot(normal, normal)), 1.0, delta=1e-5, msg=name)
            for a, b, c in mesh.triangles:  # counter-clockwise seen from above, as the normals
                pa, pb, pc = mesh.positions[a], mesh.positions[b], mesh.positions[c]
                geometric = cross(sub(pb, pa), sub(pc, pa))
                self.assertGreater(dot(geometric, mesh.normals[a]), 0.0, f"{name} {(a, b, c)}")
        for accessor in doc["accessors"]:
            if "min" in accessor:
                values = accessor_values(doc, buffers, doc["accessors"].index(accessor))
                for axis in range(3):
                    self.assertEqual(f32(accessor["min"][axis]), min(v[axis] for v in values))
                    self.assertEqual(f32(accessor["max"][axis]), max(v[axis] for v in values))

    def test_output_is_deterministic(self):
        self.assertEqual(self.terrain(2000), self.terrain(2000))


class TestCornellBox(unittest.TestCase):
    def setUp(self):
        self.doc, buffers = load_scene(COMMITTED_DIR / "cornell_box.gltf")
        self.meshes = world_meshes(self.doc, buffers)

    def node(self, name):
        return next(node for node in self.doc["nodes"] if node["name"] == name)

    def test_walls_face_into_the_box(self):
        for wall in WALLS:
            mesh = self.meshes[wall]
            for position, normal in zip(mesh.positions, mesh.normals):
                self.assertGreater(dot(normal, sub(BOX_CENTER, position)), 0.0, wall)

    def test_blocks_face_outward(self):
        for block in ("short_block", "tall_block"):
            mesh = self.meshes[block]
            center = mesh.center()
            for a, b, c in mesh.triangles:
                centroid = tuple(sum(x) / 3 for x in zip(mesh.positions[a], mesh.positions[b], mesh.positions[c]))
                self.assertGreater(dot(mesh.normals[a], sub(centroid, center)), 0.0, block)

    def test_blocks_reproduce_the_measured_corners(self):
        # A corner of each block's top face from the Cornell data, in meters.
        for block, corner in (("short_block", (0.130, 0.165, 0.065)), ("tall_block", (0.423, 0.330, 0.247))):
            distance = min(math.dist(p, corner) for p in self.meshes[block].positions)
            self.assertLess(distance, 1e-6, block)

    def test_light_faces_down_below_the_ceiling(self):
        light = self.meshes["light"]
        for position, normal in zip(light.positions, light.normals):
            self.assertAlmostEqual(position[1], 0.5483, delta=1e-6)
            for got, want in zip(normal, (0.0, -1.0, 0.0)):
                self.assertAlmostEqual(got, want, delta=1e-6)
        material = self.doc["materials"][self.doc["meshes"][self.node("light")["mesh"]]["primitives"][0]["material"]]
        self.assertEqual(material["name"], "light")
        self.assertFalse(material["doubleSided"])

    def test_camera_looks_into_the_box(self):
        camera_node = self.node("camera")
        self.assertEqual(camera_node["translation"], [0.278, 0.273, -0.8])
        view = quat_rotate(camera_node["rotation"], (0.0, 0.0, -1.0))
        for got, want in zip(view, (0.0, 0.0, 1.0)):
            self.assertAlmostEqual(got, want, delta=1e-6)
        perspective = self.doc["cameras"][camera_node["camera"]]["perspective"]
        self.assertAlmostEqual(perspective["yfov"], 2 * math.atan(0.025 / 2 / 0.035), delta=1e-6)

    def test_moved_scene_differs_only_by_the_tall_block_move(self):
        moved, moved_buffers = load_scene(COMMITTED_DIR / "cornell_box_moved.gltf")
        _, buffers = load_scene(COMMITTED_DIR / "cornell_box.gltf")
        self.assertEqual(moved_buffers, buffers)
        tall = next(node for node in moved["nodes"] if node["name"] == "tall_block")
        expected = [a + b for a, b in zip(self.node("tall_block")["translation"], (0.06, 0.0, -0.08))]
        for got, want in zip(tall.pop("translation"), expected):
            self.assertAlmostEqual(got, want, delta=1e-6)
        original = json.loads(json.dumps(self.doc))
        del next(node for node in original["nodes"] if node["name"] == "tall_block")["translation"]
        original["buffers"][0]["uri"] = moved["buffers"][0]["uri"]
        self.assertEqual(moved, original)


class TestCornellSphere(unittest.TestCase):
    def setUp(self):
        self.data = (COMMITTED_DIR / "cornell_sphere.glb").read_bytes()

    def test_glb_chunk_padding(self):
        # parse_glb already checks both chunk lengths are multiples of 4;
        # here check what the padding is made of and that it is minimal.
        json_chunk, bin_chunk = parse_glb(self.data)
        json_text = json_chunk.rstrip(b" ")
        self.assertLess(len(json_chunk) - len(json_text), 4)
        self.assertTrue(json_text.endswith(b"}\n"))
        byte_length = json.loads(json_chunk)["buffers"][0]["byteLength"]
        self.assertLess(len(bin_chunk) - byte_length, 4)
        self.assertGreaterEqual(len(bin_chunk), byte_length)
        self.assertEqual(bin_chunk[byte_length:], b"\0" * (len(bin_chunk) - byte_length))

    def test_sphere_rests_on_the_floor(self):
        doc, buffers = load_scene(COMMITTED_DIR / "cornell_sphere.glb")
        sphere = world_meshes(doc, buffers)["sphere"]
        self.assertAlmostEqual(min(p[1] for p in sphere.positions), 0.0, delta=1e-6)
        self.assertAlmostEqual(max(p[1] for p in sphere.positions), 0.16, delta=1e-6)

    def test_lamp_is_a_point_light(self):
        doc, _ = load_scene(COMMITTED_DIR / "cornell_sphere.glb")
        lamp = next(node for node in doc["nodes"] if node["name"] == "lamp")
        light = doc["extensions"]["KHR_lights_punctual"]["lights"][lamp["extensions"]["KHR_lights_punctual"]["light"]]
        self.assertEqual(light, {"name": "lamp", "type": "point", "color": [1.0, 1.0, 1.0], "intensity": 0.5})
        self.assertEqual(lamp["translation"], [0.278, 0.45, 0.28])

    def test_lamp_hall_has_many_small_lights_inside_the_hall(self):
        doc, buffers = load_scene(COMMITTED_DIR / "lamp_hall.glb")
        self.assertEqual(len(doc["extensions"]["KHR_lights_punctual"]["lights"]), 48)
        panels = [mesh for name, mesh in world_meshes(doc, buffers).items() if name.startswith("panels_")]
        self.assertEqual(sum(len(mesh.positions) for mesh in panels), 96 * 4)
        for mesh in panels:
            for normal in mesh.normals:
                self.assertEqual(tuple(normal), (0.0, -1.0, 0.0))
        for node in doc["nodes"]:
            x, y, z = node.get("translation", [0.0, 0.0, 0.0])
            self.assertTrue(-12.0 <= x <= 12.0 and 0.0 <= y <= 4.0 and -8.0 <= z <= 8.0, node["name"])


class TestEditScripts(unittest.TestCase):
    def check_targets(self, edits_name, scene_name):
        doc, _ = load_scene(COMMITTED_DIR / scene_name)
        nodes = {node["name"] for node in doc["nodes"]}
        materials = {material["name"] for material in doc["materials"]}
        edits = json.loads((COMMITTED_DIR / edits_name).read_bytes())["edits"]
        for edit in edits:
            target = edit["material"] if edit["op"] in ("material", "emission") else edit["node"]
            self.assertIn(target, materials if edit["op"] in ("material", "emission") else nodes, edit)
        return edits

    def test_cornell_box_edits(self):
        edits = self.check_targets("cornell_box.edits.json", "cornell_box.gltf")
        self.assertEqual([edit["op"] for edit in edits], ["transform", "material"])

    def test_cornell_sphere_edits(self):
        edits = self.check_targets("cornell_sphere.edits.json", "cornell_sphere.glb")
        self.assertEqual([edit["op"] for edit in edits], ["transform", "light", "emission", "visibility"])

    def test_lamp_hall_edits(self):
        edits = self.check_targets("lamp_hall.edits.json", "lamp_hall.glb")
        self.assertEqual([edit["op"] for edit in edits], ["light", "transform", "emission"])


if __name__ == "__main__":
    unittest.main()
