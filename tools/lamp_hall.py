"""The many-light test scene for tools/make_scenes.py: lamp_hall.glb.

A hall 24 x 16 m, 4 m high, with a grid of pillars, lit only by 96 small ceiling panels
(0.2 m squares in four colours) and 48 point lamps at knee height beside the pillars. Any
point sees a few lamps nearby and many far away or behind a pillar: selecting a light by its
power alone mostly picks lamps that send the point next to nothing, which is what the light
tree (src/render/light_tree.h) is for. No environment: the lamps are all the light there is.
"""

import math

HALL_X = 12.0  # the hall spans -HALL_X..HALL_X
HALL_Z = 8.0
HALL_HEIGHT = 4.0
PILLAR_HALF = 0.2
PILLAR_XS = [-8.0, -4.0, 0.0, 4.0, 8.0]
PILLAR_ZS = [-4.0, 0.0, 4.0]
PANEL_HALF = 0.1
PANEL_COLUMNS, PANEL_ROWS = 12, 8  # 96 panels, 2 m apart
PANEL_STRENGTH = 8.0
PANEL_COLOURS = [
    ("lamp_warm", (1.0, 0.72, 0.42)),
    ("lamp_cool", (0.62, 0.78, 1.0)),
    ("lamp_white", (1.0, 1.0, 1.0)),
    ("lamp_amber", (1.0, 0.55, 0.18)),
]
POINT_INTENSITY = 0.8  # candela
CAMERA_POSITION = (-11.0, 1.6, -7.0)
CAMERA_TARGET = (4.0, 0.9, 3.0)
CAMERA_YFOV = 0.9

LAMP_HALL_EDITS = {"edits": [
    {"op": "light", "node": "lamp_2_1_0", "set": {"color": [0.2, 0.5, 1.0]}},
    {"op": "transform", "node": "lamp_1_1_1", "translate": [0.0, 0.0, 0.6]},
    {"op": "emission", "material": "lamp_amber", "set": {"emission_luminance": 10.0}},
]}


def look_rotation(position, target):
    """Quaternion (x, y, z, w) turning glTF's -Z view axis toward `target`: a yaw about +Y,
    then a pitch about the camera's own X."""
    d = [t - p for t, p in zip(target, position)]
    yaw = math.atan2(-d[0], -d[2])
    pitch = math.atan2(d[1], math.hypot(d[0], d[2]))
    cy, sy = math.cos(yaw / 2.0), math.sin(yaw / 2.0)
    cp, sp = math.cos(pitch / 2.0), math.sin(pitch / 2.0)
    # q_yaw (0, sy, 0, cy) times q_pitch (sp, 0, 0, cp).
    return (cy * sp, sy * cp, -sy * sp, cy * cp)


def lamp_hall(scenes):
    """`scenes` is make_scenes (its Mesh, materials and document writer)."""
    doc = scenes.GltfDocument("lamp_hall")
    floor_lo, floor_hi = (-HALL_X, 0.0, -HALL_Z), (HALL_X, HALL_HEIGHT, HALL_Z)
    walls = [
        ("floor", scenes.axis_rect(1, 0.0, floor_lo, floor_hi), scenes.UP, scenes.WHITE),
        ("ceiling", scenes.axis_rect(1, HALL_HEIGHT, floor_lo, floor_hi), scenes.DOWN, scenes.WHITE),
        ("wall_east", scenes.axis_rect(0, HALL_X, floor_lo, floor_hi), (-1.0, 0.0, 0.0), scenes.RED),
        ("wall_west", scenes.axis_rect(0, -HALL_X, floor_lo, floor_hi), (1.0, 0.0, 0.0), scenes.GREEN),
        ("wall_north", scenes.axis_rect(2, HALL_Z, floor_lo, floor_hi), (0.0, 0.0, -1.0), scenes.WHITE),
        ("wall_south", scenes.axis_rect(2, -HALL_Z, floor_lo, floor_hi), (0.0, 0.0, 1.0), scenes.WHITE),
    ]
    for name, corners, facing, material in walls:
        doc.add_mesh_node(name, scenes.quad_mesh(corners, facing), material)

    square = [(-PILLAR_HALF, -PILLAR_HALF), (PILLAR_HALF, -PILLAR_HALF), (PILLAR_HALF, PILLAR_HALF),
              (-PILLAR_HALF, PILLAR_HALF)]
    pillar = scenes.prism_mesh(square, HALL_HEIGHT)
    for i, x in enumerate(PILLAR_XS):
        for j, z in enumerate(PILLAR_ZS):
            doc.add_mesh_node("pillar_%d_%d" % (i, j), pillar, scenes.WHITE, (x, 0.0, z))
            # Two lamps beside each pillar, on opposite sides.
            for k, (dx, dz) in enumerate(((0.5, 0.5), (-0.5, -0.5))):
                doc.add_point_light_node("lamp_%d_%d_%d" % (i, j, k), (x + dx, 0.5, z + dz), POINT_INTENSITY,
                                         (1.0, 0.85, 0.7))
    # The rest of the 48 point lamps along the long walls.
    for i in range(9):
        x = -HALL_X + 2.0 + 2.5 * i
        doc.add_point_light_node("wall_lamp_north_%d" % i, (x, 1.2, HALL_Z - 0.3), POINT_INTENSITY, (0.9, 0.9, 1.0))
        doc.add_point_light_node("wall_lamp_south_%d" % i, (x, 1.2, -HALL_Z + 0.3), POINT_INTENSITY, (0.9, 0.9, 1.0))

    # Ceiling panels: one mesh per colour, its panels a grid with the colours interleaved.
    panels = {name: scenes.Mesh() for name, _ in PANEL_COLOURS}
    y = HALL_HEIGHT - 0.01
    for c in range(PANEL_COLUMNS):
        for r in range(PANEL_ROWS):
            x = -HALL_X + 1.0 + 2.0 * c
            z = -HALL_Z + 1.0 + 2.0 * r
            name = PANEL_COLOURS[(c + 2 * r) % len(PANEL_COLOURS)][0]
            lo, hi = (x - PANEL_HALF, y, z - PANEL_HALF), (x + PANEL_HALF, y, z + PANEL_HALF)
            panels[name].add_quad(scenes.axis_rect(1, y, lo, hi), scenes.DOWN)
    for name, colour in PANEL_COLOURS:
        doc.add_mesh_node("panels_" + name[len("lamp_"):], panels[name],
                          scenes.emissive_material(name, colour, PANEL_STRENGTH))

    doc.add_camera_node("camera", CAMERA_YFOV, CAMERA_POSITION, look_rotation(CAMERA_POSITION, CAMERA_TARGET),
                        aspect_ratio=1.0)
    return doc
