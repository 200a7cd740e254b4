"""Render an independent reference image of a Lambert glTF scene with Blender Cycles.

Usage:
    blender -b --factory-startup --python tools/reference/cycles_cornell.py -- \
        SCENE.gltf OUT.exr [--size 64] [--spp N] [--max-bounces B] [--seed S]
        [--threads T] [--emitter-back black|transparent]

The glTF file is read directly (JSON + .bin via numpy); Blender's glTF importer is
NOT used, so nothing is re-oriented, merged, re-normalised or converted to a
Principled BSDF.  Geometry is kept in glTF world coordinates (Y up): Blender does
not care which axis is "up" for rendering, and both glTF and Blender cameras look
down their local -Z with local +Y up, so the glTF camera node's world matrix is
used unchanged as the Blender camera's matrix.

Materials:
  * non-emissive: plain Diffuse BSDF, roughness 0 (pure Lambert), colour =
    baseColorFactor.rgb (linear).  Textures are not supported (error).
  * emissive: Emission shader, colour = emissiveFactor, strength =
    KHR_materials_emissive_strength.emissiveStrength (so emitted radiance =
    product, as for a Cycles mesh emitter strength 1 == radiance 1).  Emission
    is made one-sided with Geometry.Backfacing: the back side (opposite to the
    triangle winding normal) emits nothing and is opaque black (or fully
    transparent with --emitter-back transparent).  If the emissive material
    also has a non-black base colour, a diffuse lobe is added on top.

Output: OpenEXR, 32-bit float, RGBA, linear scene-referred, SIZE x SIZE.
"""

import base64
import json
import math
import os
import struct
import sys
import time

import bpy
import numpy as np
from mathutils import Matrix, Quaternion, Vector


# --------------------------------------------------------------------------- args

def parse_args():
    argv = sys.argv
    argv = argv[argv.index("--") + 1:] if "--" in argv else []
    import argparse

    ap = argparse.ArgumentParser(prog="cycles_cornell.py")
    ap.add_argument("scene")
    ap.add_argument("out")
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--spp", type=int, default=1024)
    ap.add_argument("--max-bounces", type=int, default=64)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--threads", type=int, default=0, help="0 = all cores")
    ap.add_argument("--emitter-back", choices=["black", "transparent"], default="black")
    return ap.parse_args(argv)


# --------------------------------------------------------------------------- glTF reading

COMPONENT_DTYPE = {5120: np.int8, 5121: np.uint8, 5122: np.int16,
                   5123: np.uint16, 5125: np.uint32, 5126: np.float32}
TYPE_COUNT = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}


class Gltf:
    def __init__(self, path):
        self.path = os.path.abspath(path)
        with open(self.path, "rb") as f:
            raw = f.read()
        self.glb_bin = None
        if raw[:4] == b"glTF":
            # binary container: header, JSON chunk, optional BIN chunk
            off = 12
            self.j = None
            while off < len(raw):
                clen, ctype = struct.unpack_from("<II", raw, off)
                chunk = raw[off + 8: off + 8 + clen]
                if ctype == 0x4E4F534A:
                    self.j = json.loads(chunk.decode("utf-8"))
                elif ctype == 0x004E4942:
                    self.glb_bin = chunk
                off += 8 + clen
        else:
            self.j = json.loads(raw.decode("utf-8"))
        self._buffers = {}

    def buffer(self, i):
        if i not in self._buffers:
            b = self.j["buffers"][i]
            uri = b.get("uri")
            if uri is None:
                data = self.glb_bin
            elif uri.startswith("data:"):
                data = base64.b64decode(uri.split(",", 1)[1])
            else:
                from urllib.parse import unquote
                with open(os.path.join(os.path.dirname(self.path), unquote(uri)), "rb") as f:
                    data = f.read()
            if len(data) < b["byteLength"]:
                raise ValueError("buffer %d shorter than byteLength" % i)
            self._buffers[i] = data
        return self._buffers[i]

    def accessor(self, i):
        a = self.j["accessors"][i]
        if "sparse" in a:
            raise NotImplementedError("sparse accessors")
        dt = np.dtype(COMPONENT_DTYPE[a["componentType"]]).newbyteorder("<")
        ncomp = TYPE_COUNT[a["type"]]
        count = a["count"]
        if "bufferView" not in a:
            return np.zeros((count, ncomp), dtype=dt)
        bv = self.j["bufferViews"][a["bufferView"]]
        data = self.buffer(bv["buffer"])
        base = bv.get("byteOffset", 0) + a.get("byteOffset", 0)
        elem = dt.itemsize * ncomp
        stride = bv.get("byteStride", elem)
        out = np.empty((count, ncomp), dtype=dt)
        if stride == elem:
            out[:] = np.frombuffer(data, dtype=dt, count=count * ncomp, offset=base).reshape(count, ncomp)
        else:
            for k in range(count):
                out[k] = np.frombuffer(data, dtype=dt, count=ncomp, offset=base + k * stride)
        if a.get("normalized"):
            raise NotImplementedError("normalized accessors")
        return out


def node_local_matrix(n):
    if "matrix" in n:
        m = n["matrix"]  # column-major
        return Matrix([[m[c * 4 + r] for c in range(4)] for r in range(4)])
    t = n.get("translation", [0.0, 0.0, 0.0])
    r = n.get("rotation", [0.0, 0.0, 0.0, 1.0])  # x, y, z, w
    s = n.get("scale", [1.0, 1.0, 1.0])
    T = Matrix.Translation(Vector(t))
    R = Quaternion((r[3], r[0], r[1], r[2])).to_matrix().to_4x4()
    S = Matrix.Diagonal(Vector((s[0], s[1], s[2], 1.0)))
    return T @ R @ S


def walk_nodes(g):
    """Yield (node_index, node, world_matrix) for all nodes of the default scene."""
    j = g.j
    scenes = j.get("scenes")
    if scenes:
        roots = scenes[j.get("scene", 0)]["nodes"]
    else:
        roots = list(range(len(j.get("nodes", []))))
    stack = [(i, Matrix.Identity(4)) for i in reversed(roots)]
    while stack:
        i, parent = stack.pop()
        n = j["nodes"][i]
        w = parent @ node_local_matrix(n)
        yield i, n, w
        for c in reversed(n.get("children", [])):
            stack.append((c, w))


def mat_to_np(m):
    return np.array([[m[r][c] for c in range(4)] for r in range(4)], dtype=np.float64)


# --------------------------------------------------------------------------- Blender scene

def clear_scene():
    for ob in list(bpy.data.objects):
        bpy.data.objects.remove(ob, do_unlink=True)
    for coll in (bpy.data.meshes, bpy.data.materials, bpy.data.cameras, bpy.data.lights):
        for d in list(coll):
            coll.remove(d)


def make_material(g, mi, emitter_back):
    """Return (blender material, description string, is_emissive)."""
    if mi is None:
        m = {"name": "gltf_default"}
    else:
        m = g.j["materials"][mi]
    name = m.get("name", "material_%s" % mi)
    pbr = m.get("pbrMetallicRoughness", {})
    for key in ("baseColorTexture", "metallicRoughnessTexture"):
        if key in pbr:
            raise NotImplementedError("%s on material %s" % (key, name))
    for key in ("emissiveTexture", "normalTexture", "occlusionTexture"):
        if key in m:
            raise NotImplementedError("%s on material %s" % (key, name))
    base = list(pbr.get("baseColorFactor", [1.0, 1.0, 1.0, 1.0]))[:3]
    metallic = pbr.get("metallicFactor", 1.0)
    ext = m.get("extensions", {})
    spec = ext.get("KHR_materials_specular", {}).get("specularFactor", 1.0)
    emis = list(m.get("emissiveFactor", [0.0, 0.0, 0.0]))
    strength = ext.get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
    radiance = [e * strength for e in emis]
    is_emissive = max(radiance) > 0.0
    if not is_emissive and (metallic != 0.0 or spec != 0.0):
        print("WARNING: material %s has metallic=%g specularFactor=%g; rendering it as pure "
              "Lambert anyway" % (name, metallic, spec))

    bm = bpy.data.materials.new(name)
    bm.use_nodes = True
    nt = bm.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    out.target = "CYCLES"

    diffuse = None
    if max(base) > 0.0:
        diffuse = nt.nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = (base[0], base[1], base[2], 1.0)
        diffuse.inputs["Roughness"].default_value = 0.0  # 0 => Lambert, not Oren-Nayar

    if not is_emissive:
        if diffuse is None:  # black Lambert: plain absorber
            diffuse = nt.nodes.new("ShaderNodeBsdfDiffuse")
            diffuse.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
            diffuse.inputs["Roughness"].default_value = 0.0
        nt.links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
        desc = "Lambert albedo=(%.6g, %.6g, %.6g)" % tuple(base)
        bm.cycles.sample_as_light = False
        return bm, desc, False

    # Emissive: front = emission (+ diffuse if any), back = black absorber or transparent.
    em = nt.nodes.new("ShaderNodeEmission")
    em.inputs["Color"].default_value = (emis[0], emis[1], emis[2], 1.0)
    em.inputs["Strength"].default_value = strength
    front = em.outputs["Emission"]
    if diffuse is not None:
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(em.outputs["Emission"], add.inputs[0])
        nt.links.new(diffuse.outputs["BSDF"], add.inputs[1])
        front = add.outputs["Shader"]
    geo = nt.nodes.new("ShaderNodeNewGeometry")
    mix = nt.nodes.new("ShaderNodeMixShader")
    if emitter_back == "transparent":
        back = nt.nodes.new("ShaderNodeBsdfTransparent")
        back.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        back_out = back.outputs["BSDF"]
    else:
        # Diffuse BSDF with black colour == no closure at all: opaque, absorbing, no emission
        back = nt.nodes.new("ShaderNodeBsdfDiffuse")
        back.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
        back.inputs["Roughness"].default_value = 0.0
        back_out = back.outputs["BSDF"]
    nt.links.new(geo.outputs["Backfacing"], mix.inputs["Fac"])  # 0 = front, 1 = back
    nt.links.new(front, mix.inputs[1])
    nt.links.new(back_out, mix.inputs[2])
    nt.links.new(mix.outputs["Shader"], out.inputs["Surface"])
    bm.cycles.sample_as_light = True  # MIS / next-event estimation on the emitter
    desc = ("one-sided emitter radiance=(%.6g, %.6g, %.6g) [factor (%.6g, %.6g, %.6g) x strength %.6g], "
            "albedo=(%.6g, %.6g, %.6g), back=%s" % (tuple(radiance) + tuple(emis) + (strength,) +
                                                   tuple(base) + (emitter_back,)))
    return bm, desc, True


def build_scene(g, emitter_back):
    j = g.j
    mat_cache = {}
    camera = None
    report = []
    for ni, n, w in walk_nodes(g):
        name = n.get("name", "node_%d" % ni)
        W = mat_to_np(w)
        if "mesh" in n:
            mesh = j["meshes"][n["mesh"]]
            det = np.linalg.det(W[:3, :3])
            nmat = np.linalg.inv(W[:3, :3]).T
            for pi, prim in enumerate(mesh["primitives"]):
                mode = prim.get("mode", 4)
                if mode != 4:
                    raise NotImplementedError("primitive mode %d (only TRIANGLES)" % mode)
                attrs = prim["attributes"]
                P = g.accessor(attrs["POSITION"]).astype(np.float64)
                acc = j["accessors"][attrs["POSITION"]]
                if "min" in acc and "max" in acc:
                    lo, hi = P.min(axis=0), P.max(axis=0)
                    if not (np.allclose(lo, acc["min"], atol=1e-6) and np.allclose(hi, acc["max"], atol=1e-6)):
                        print("WARNING: %s POSITION min/max differ from accessor bounds" % name)
                if "indices" in prim:
                    idx = g.accessor(prim["indices"]).astype(np.int64).reshape(-1)
                else:
                    idx = np.arange(P.shape[0], dtype=np.int64)
                tris = idx.reshape(-1, 3)
                # bake the node's world transform into the vertices (no Blender object transform)
                Pw = P @ W[:3, :3].T + W[:3, 3]
                if det < 0.0:  # glTF: negative determinant flips the front-face winding
                    tris = tris[:, ::-1]
                # geometric (winding) normals in world space
                e1 = Pw[tris[:, 1]] - Pw[tris[:, 0]]
                e2 = Pw[tris[:, 2]] - Pw[tris[:, 0]]
                gn = np.cross(e1, e2)
                area = 0.5 * np.linalg.norm(gn, axis=1)
                if np.any(area <= 0.0):
                    print("WARNING: %s has %d degenerate triangles" % (name, int(np.sum(area <= 0))))
                gn = gn / np.maximum(np.linalg.norm(gn, axis=1, keepdims=True), 1e-300)
                # compare with the authored NORMAL attribute (flat shading is used for rendering)
                normal_note = "no NORMAL"
                if "NORMAL" in attrs:
                    N = g.accessor(attrs["NORMAL"]).astype(np.float64) @ nmat.T
                    N = N / np.maximum(np.linalg.norm(N, axis=1, keepdims=True), 1e-300)
                    nt = N[tris].mean(axis=1)
                    nt = nt / np.maximum(np.linalg.norm(nt, axis=1, keepdims=True), 1e-300)
                    d = np.sum(nt * gn, axis=1)
                    normal_note = "min dot(NORMAL, winding normal)=%.6f" % d.min()
                    if d.min() < 0.999:
                        print("WARNING: %s: authored normals disagree with the winding normal "
                              "(min dot %.4f); Cycles uses winding for front/back" % (name, d.min()))
                mi = prim.get("material")
                if mi not in mat_cache:
                    mat_cache[mi] = make_material(g, mi, emitter_back)
                bmat, desc, emissive = mat_cache[mi]

                me = bpy.data.meshes.new("%s_%d" % (name, pi))
                me.from_pydata([tuple(v) for v in Pw], [], [tuple(int(x) for x in t) for t in tris])
                me.update()
                if len(me.polygons) != len(tris) or len(me.vertices) != len(Pw):
                    raise RuntimeError("Blender changed the topology of %s" % name)
                for poly in me.polygons:
                    poly.use_smooth = False  # flat: shading normal == geometric normal
                me.materials.append(bmat)
                ob = bpy.data.objects.new(me.name, me)
                bpy.context.scene.collection.objects.link(ob)
                for attr, val in (("shadow_terminator_geometry_offset", 0.0),
                                  ("shadow_terminator_offset", 0.0)):
                    if hasattr(ob, attr):
                        setattr(ob, attr, val)
                # verify what Blender stores against what we computed
                bv = np.array([v.co[:] for v in me.vertices], dtype=np.float64)
                if np.abs(bv - Pw).max() > 1e-5 * max(1.0, np.abs(Pw).max()):
                    raise RuntimeError("vertex positions changed for %s" % name)
                bn = np.array([p.normal[:] for p in me.polygons], dtype=np.float64)
                if np.sum(bn * gn, axis=1).min() < 0.9999:
                    raise RuntimeError("Blender face normals differ from winding for %s" % name)
                mean_n = (gn * area[:, None]).sum(axis=0)
                if np.linalg.norm(mean_n) < 1e-6 * area.sum():
                    front_note = "closed surface (area-weighted normals sum to 0)"
                else:
                    mean_n /= np.linalg.norm(mean_n)
                    front_note = "front normal(avg)=(%.3f, %.3f, %.3f)" % tuple(mean_n)
                report.append("  %-14s %5d tris  area=%.6f m^2  bounds=%s..%s  %s  %s\n"
                              "                 material: %s" %
                              (name, len(tris), area.sum(), np.round(Pw.min(axis=0), 6).tolist(),
                               np.round(Pw.max(axis=0), 6).tolist(), front_note, normal_note, desc))
        if "camera" in n:
            if camera is not None:
                print("WARNING: several cameras; using the first one")
                continue
            camera = (name, j["cameras"][n["camera"]], w.copy())
    if camera is None:
        raise RuntimeError("no camera node in glTF")
    return camera, report


def setup_camera(camera, size):
    name, cj, w = camera
    if cj.get("type") != "perspective":
        raise NotImplementedError("camera type %s" % cj.get("type"))
    p = cj["perspective"]
    yfov = p["yfov"]
    aspect = p.get("aspectRatio", 1.0)
    if abs(aspect - 1.0) > 1e-6:
        print("WARNING: glTF camera aspectRatio %g but image is square; yfov is kept vertical" % aspect)
    cam = bpy.data.cameras.new("gltf_camera")
    cam.type = "PERSP"
    cam.sensor_fit = "VERTICAL"   # glTF yfov is the vertical field of view
    cam.sensor_width = cam.sensor_height  # square sensor, so angle_x == angle_y for a square image
    cam.angle_y = yfov
    cam.shift_x = cam.shift_y = 0.0
    cam.dof.use_dof = False
    # Cycles does not intersect geometry closer than clip_start; keep it tiny so nothing is clipped.
    cam.clip_start = 1e-4
    cam.clip_end = max(1e6, p.get("zfar", 0.0) or 0.0)
    ob = bpy.data.objects.new("gltf_camera", cam)
    bpy.context.scene.collection.objects.link(ob)
    # Remove any scale from the node matrix (glTF cameras must not be scaled, but be safe).
    loc, rot, _scale = w.decompose()
    ob.matrix_world = Matrix.Translation(loc) @ rot.to_matrix().to_4x4()
    bpy.context.scene.camera = ob
    fwd = rot @ Vector((0.0, 0.0, -1.0))
    up = rot @ Vector((0.0, 1.0, 0.0))
    return ("  camera node %s: position=(%.6f, %.6f, %.6f) forward=(%.6f, %.6f, %.6f) up=(%.6f, %.6f, %.6f)\n"
            "  yfov=%.9f rad (%.6f deg) -> Blender sensor_fit=VERTICAL angle_y=%.9f (angle_x=%.9f), "
            "lens=%.6f mm, sensor_height=%.3f mm" %
            (name, loc.x, loc.y, loc.z, fwd.x, fwd.y, fwd.z, up.x, up.y, up.z,
             yfov, math.degrees(yfov), cam.angle_y, cam.angle_x, cam.lens, cam.sensor_height))


def setup_render(args):
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    cy = sc.cycles
    cy.device = "CPU"
    cy.feature_set = "SUPPORTED"
    if hasattr(cy, "progressive"):
        cy.progressive = "PATH"
    cy.samples = args.spp
    cy.use_adaptive_sampling = False
    cy.time_limit = 0.0
    cy.seed = args.seed
    cy.use_animated_seed = False
    cy.use_denoising = False
    if hasattr(cy, "use_preview_denoising"):
        cy.use_preview_denoising = False
    for vl in sc.view_layers:
        vl.cycles.use_denoising = False
        vl.use_pass_combined = True
    cy.pixel_filter_type = "BOX"
    cy.filter_width = 1.0
    cy.sample_clamp_direct = 0.0
    cy.sample_clamp_indirect = 0.0
    cy.blur_glossy = 0.0
    cy.caustics_reflective = True
    cy.caustics_refractive = True
    B = args.max_bounces
    cy.max_bounces = B
    cy.diffuse_bounces = B
    cy.glossy_bounces = B
    cy.transmission_bounces = B
    cy.volume_bounces = B
    cy.transparent_max_bounces = B
    cy.min_light_bounces = 0
    cy.min_transparent_bounces = 0
    cy.ao_bounces = 0
    cy.ao_bounces_render = 0
    if hasattr(cy, "use_fast_gi"):
        cy.use_fast_gi = False
    if hasattr(cy, "light_sampling_threshold"):
        cy.light_sampling_threshold = 0.0
    if hasattr(cy, "use_light_tree"):
        cy.use_light_tree = False
    if hasattr(cy, "film_exposure"):
        cy.film_exposure = 1.0
    sc.render.film_transparent = False
    sc.render.use_motion_blur = False
    sc.render.use_border = False
    sc.render.use_persistent_data = False
    sc.render.threads_mode = "FIXED" if args.threads > 0 else "AUTO"
    if args.threads > 0:
        sc.render.threads = args.threads
    sc.render.resolution_x = args.size
    sc.render.resolution_y = args.size
    sc.render.resolution_percentage = 100
    sc.render.pixel_aspect_x = 1.0
    sc.render.pixel_aspect_y = 1.0
    sc.render.use_compositing = False
    sc.render.use_sequencer = False
    sc.display_settings.display_device = "sRGB"
    sc.view_settings.view_transform = "Standard"
    sc.view_settings.look = "None"
    sc.view_settings.exposure = 0.0
    sc.view_settings.gamma = 1.0
    sc.view_settings.use_curve_mapping = False
    sc.sequencer_colorspace_settings.name = "Linear"

    world = bpy.data.worlds.new("black") if sc.world is None else sc.world
    sc.world = world
    world.use_nodes = True
    wt = world.node_tree
    for n in list(wt.nodes):
        wt.nodes.remove(n)
    bg = wt.nodes.new("ShaderNodeBackground")
    bg.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    bg.inputs["Strength"].default_value = 0.0
    wo = wt.nodes.new("ShaderNodeOutputWorld")
    wt.links.new(bg.outputs["Background"], wo.inputs["Surface"])
    if hasattr(world, "cycles"):
        world.cycles.sample_as_light = False

    im = sc.render.image_settings
    im.file_format = "OPEN_EXR"
    im.color_mode = "RGBA"
    im.color_depth = "32"
    im.exr_codec = "ZIP"  # lossless
    if hasattr(im, "color_management"):
        im.color_management = "FOLLOW_SCENE"
    sc.render.use_file_extension = False
    sc.render.filepath = os.path.abspath(args.out)


def main():
    args = parse_args()
    t_load0 = time.perf_counter()
    clear_scene()
    g = Gltf(args.scene)
    camera, report = build_scene(g, args.emitter_back)
    cam_report = setup_camera(camera, args.size)
    setup_render(args)
    t_load1 = time.perf_counter()

    print("=" * 78)
    print("Blender %s, Cycles CPU; scene %s" % (bpy.app.version_string, args.scene))
    print("\n".join(report))
    print(cam_report)
    print("size=%dx%d spp=%d max_bounces=%d seed=%d threads=%s emitter_back=%s" %
          (args.size, args.size, args.spp, args.max_bounces, args.seed,
           args.threads or "auto", args.emitter_back))
    print("scene build time %.3f s" % (t_load1 - t_load0))
    print("=" * 78, flush=True)

    # Blender 3.4's render_stats handler receives no text, so capture the C-level stdout
    # (the "Fra:1 ... | Time:MM:SS.ss | ... | Sample i/N" lines) during the render.
    import tempfile
    sys.stdout.flush()
    cap = tempfile.TemporaryFile(mode="w+b")
    saved_fd = os.dup(1)
    os.dup2(cap.fileno(), 1)
    t0 = time.perf_counter()
    try:
        bpy.ops.render.render(write_still=False)
    finally:
        t1 = time.perf_counter()
        sys.stdout.flush()
        os.dup2(saved_fd, 1)
        os.close(saved_fd)
    cap.seek(0)
    log = cap.read().decode("utf-8", "replace")
    cap.close()
    img = bpy.data.images["Render Result"]
    img.save_render(os.path.abspath(args.out), scene=bpy.context.scene)
    t2 = time.perf_counter()

    def parse_time(tstr):
        secs = 0.0
        for field in tstr.strip().split(":"):
            secs = secs * 60.0 + float(field)
        return secs

    blender_time = None      # Blender's "Time:" on the last status line (whole render)
    pt_start = None          # Blender's "Time:" when path tracing starts ("Sample 0/N")
    last_line = ""
    for line in log.replace("\r", "\n").split("\n"):
        if "| Time:" not in line:
            continue
        fields = [f.strip() for f in line.split("|")]
        tval = None
        for f in fields:
            if f.startswith("Time:"):
                tval = parse_time(f[5:])
        if tval is None:
            continue
        blender_time = tval
        last_line = line.strip()
        if pt_start is None and any(f.startswith("Sample 0/") for f in fields):
            pt_start = tval
    render_s = blender_time if blender_time is not None else (t1 - t0)
    npix = args.size * args.size
    print("last Blender status line: %s" % last_line)
    print("RENDER_TIME_S %.3f (Blender-reported render time; wall around render op %.3f s; "
          "EXR save %.3f s)" % (render_s, t1 - t0, t2 - t1))
    print("SAMPLES_PER_S %.4g  (%d px x %d spp / %.3f s)" %
          (npix * args.spp / render_s, npix, args.spp, render_s))
    if pt_start is not None and blender_time is not None and blender_time > pt_start:
        print("PATH_TRACING_TIME_S %.3f (from 'Sample 0/%d' to end; excludes sync/BVH) -> "
              "%.4g samples/s" % (blender_time - pt_start, args.spp,
                                  npix * args.spp / (blender_time - pt_start)))
    print("wrote %s" % os.path.abspath(args.out), flush=True)


main()
