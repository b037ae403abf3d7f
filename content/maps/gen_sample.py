#!/usr/bin/env python3
"""Generates content/maps/sample.map, Starbow's original sample world (Valve 220 format).

    python3 content/maps/gen_sample.py > content/maps/sample.map

The world is described as "air" boxes (rooms, corridors, pits). Every air box gets a
16-unit shell of solid slabs (floor, ceiling, four walls, overlapping at the corners);
then every air box is carved out of every slab, so where two air boxes touch, the wall
between them opens. The union of the shells therefore seals the union of the air: the
map cannot leak. Detail (steps, crates, a ramp, light fixtures), liquids and the brush
entities (door, lift, button, teleporter trigger) are added on top. All coordinates sit
on a 16-unit grid except a few 8-unit fixtures. Output is deterministic.
"""
import sys

T = 16  # wall thickness

# ---------------------------------------------------------------- rooms (air boxes)
# name: (mins, maxs, wall, floor, ceiling); ceiling "sky1" makes the whole top slab sky.
ROOMS = [
    ("hall",      (0, 0, 0),       (512, 384, 192),    "stone1", "tile1",   "ceil1"),
    ("pool",      (304, 96, -96),  (464, 288, 0),      "stone1", "cobble1", "stone1"),
    ("corr_east", (512, 160, 0),   (768, 224, 128),    "brick1", "metal1",  "metal1"),
    ("workshop",  (768, 0, 0),     (1152, 384, 160),   "tech1",  "metal1",  "ceil1"),
    ("shaft",     (1152, 128, 0),  (1280, 256, 384),   "metal2", "metal1",  "ceil1"),
    ("gallery",   (1280, 0, 192),  (1664, 384, 384),   "brick1", "planks1", "ceil1"),
    ("alcove",    (1664, 144, 192), (1712, 240, 320),  "metal1", "metal1",  "metal1"),
    ("corr_north", (192, 384, 0),  (320, 512, 128),    "stone1", "cobble1", "stone1"),
    ("courtyard", (-128, 512, -32), (640, 1024, 448),  "rock1",  "grass1",  "sky1"),
    ("slime_pit", (400, 768, -96), (560, 928, -32),    "rock1",  "rock1",   "rock1"),
    ("corr_west", (-256, 128, 0),  (0, 256, 128),      "brick1", "cobble1", "metal1"),
    ("reactor",   (-640, 0, 0),    (-256, 384, 192),   "metal2", "metal1",  "ceil1"),
    ("lava_pit",  (-544, 96, -64), (-352, 288, 0),     "rock1",  "rock1",   "rock1"),
]


def box_overlaps(a, b):
    return all(a[0][i] < b[1][i] and b[0][i] < a[1][i] for i in range(3))


def subtract(solid, air):
    """solid minus air, as up to six disjoint boxes (solid is returned whole if apart)."""
    if not box_overlaps(solid, air):
        return [solid]
    lo, hi = list(solid[0]), list(solid[1])
    pieces = []
    for axis in range(3):
        if lo[axis] < air[0][axis]:
            plo, phi = list(lo), list(hi)
            phi[axis] = air[0][axis]
            pieces.append((tuple(plo), tuple(phi)))
            lo[axis] = air[0][axis]
        if hi[axis] > air[1][axis]:
            plo, phi = list(lo), list(hi)
            plo[axis] = air[1][axis]
            pieces.append((tuple(plo), tuple(phi)))
            hi[axis] = air[1][axis]
    return pieces


def shell(mn, mx):
    """Six slabs around an air box: (kind, box)."""
    x0, y0, z0 = mn
    x1, y1, z1 = mx
    return [
        ("floor", ((x0 - T, y0 - T, z0 - T), (x1 + T, y1 + T, z0))),
        ("ceil",  ((x0 - T, y0 - T, z1), (x1 + T, y1 + T, z1 + T))),
        ("wall",  ((x0 - T, y0 - T, z0), (x0, y1 + T, z1))),
        ("wall",  ((x1, y0 - T, z0), (x1 + T, y1 + T, z1))),
        ("wall",  ((x0, y0 - T, z0), (x1, y0, z1))),
        ("wall",  ((x0, y1, z0), (x1, y1 + T, z1))),
    ]


# ---------------------------------------------------------------- brush faces
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def axes_for(normal):
    """Valve 220 texture axes for a face normal (world-aligned projection)."""
    ax, ay, az = (abs(c) for c in normal)
    if az >= ax and az >= ay:
        return (1, 0, 0), (0, -1, 0)
    if ax >= ay:
        return (0, 1, 0), (0, 0, -1)
    return (1, 0, 0), (0, 0, -1)


class Face:
    def __init__(self, pts, tex, centroid, align=None):
        p0, p1, p2 = pts
        # Quake's convention: normal = (p0 - p1) x (p2 - p1) points out of the brush.
        n = cross(sub(p0, p1), sub(p2, p1))
        if dot(n, sub(centroid, p1)) > 0:
            p0, p2 = p2, p0
            n = (-n[0], -n[1], -n[2])
        self.pts = (p0, p1, p2)
        self.normal = n
        self.tex = tex
        self.align = align  # a point whose texture coordinates should be (0, 0)

    def text(self):
        u, v = axes_for(self.normal)
        uo = vo = 0
        if self.align is not None:
            uo = -dot(u, self.align)
            vo = -dot(v, self.align)
        pts = " ".join("( %d %d %d )" % p for p in self.pts)
        return "%s %s [ %d %d %d %d ] [ %d %d %d %d ] 0 1 1" % (pts, self.tex, *u, uo, *v, vo)


def box_brush(mn, mx, tex, align=False):
    """An axis-aligned box. tex: one name or a dict by side (top, bottom, x, y, other)."""
    x0, y0, z0 = mn
    x1, y1, z1 = mx
    c = ((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2)
    texs = tex if isinstance(tex, dict) else {}

    def t(side):
        if not isinstance(tex, dict):
            return tex
        return texs.get(side, texs.get("other"))

    al_top = (x0, y1, z1) if align else None  # u = x, v = -y: (x0, y1) maps to (0, 0)
    al_side = (x0, y0, z1) if align else None  # v = -z: the top edge maps to t = 0
    faces = [
        Face(((x0, y0, z0), (x0, y1, z0), (x1, y0, z0)), t("bottom"), c, al_top),
        Face(((x0, y0, z1), (x1, y0, z1), (x0, y1, z1)), t("top"), c, al_top),
        Face(((x0, y0, z0), (x0, y0, z1), (x0, y1, z0)), t("x"), c, al_side),
        Face(((x1, y0, z0), (x1, y1, z0), (x1, y0, z1)), t("x"), c, al_side),
        Face(((x0, y0, z0), (x1, y0, z0), (x0, y0, z1)), t("y"), c, al_side),
        Face(((x0, y1, z0), (x0, y1, z1), (x1, y1, z0)), t("y"), c, al_side),
    ]
    return faces


def wedge_y(x0, x1, y_low, y_high, z0, z1, tex, slope_tex):
    """A ramp rising along +y from (y_low, z0) to (y_high, z1), x0..x1 wide."""
    c = ((x0 + x1) / 2, (2 * y_high + y_low) / 3, (2 * z0 + z1) / 3)
    return [
        Face(((x0, y_low, z0), (x1, y_low, z0), (x0, y_high, z0)), tex, c),          # bottom
        Face(((x0, y_high, z0), (x1, y_high, z0), (x0, y_high, z1)), tex, c),        # back
        Face(((x0, y_low, z0), (x0, y_high, z0), (x0, y_high, z1)), tex, c),         # west side
        Face(((x1, y_low, z0), (x1, y_high, z1), (x1, y_high, z0)), tex, c),         # east side
        Face(((x0, y_low, z0), (x0, y_high, z1), (x1, y_low, z0)), slope_tex, c),    # slope
    ]


# ---------------------------------------------------------------- world brushes
def world_brushes():
    airs = [(r[1], r[2]) for r in ROOMS]
    brushes = []
    for name, mn, mx, wall, floor, ceil in ROOMS:
        for kind, slab in shell(mn, mx):
            pieces = [slab]
            for air in airs:
                pieces = [p for s in pieces for p in subtract(s, air)]
            for p in pieces:
                if kind == "ceil" and ceil == "sky1":
                    tex = "sky1"
                elif kind == "floor":
                    tex = {"top": floor, "other": wall}
                elif kind == "ceil":
                    tex = {"bottom": ceil, "other": wall}
                else:
                    tex = wall
                brushes.append(box_brush(p[0], p[1], tex))

    def detail(mn, mx, tex, align=False):
        brushes.append(box_brush(mn, mx, tex, align))

    # Courtyard: two steps down from the north corridor, crates, a ledge with a ramp.
    detail((192, 512, -32), (320, 544, -16), {"top": "cobble1", "other": "stone1"})
    detail((-16, 640, -32), (48, 704, 32), "crate1", True)
    detail((48, 640, -32), (112, 704, 32), "crate1", True)
    detail((16, 640, 32), (80, 704, 96), "crate1", True)
    detail((-128, 896, -32), (128, 1024, 64), {"top": "grass1", "other": "rock1"})
    brushes.append(wedge_y(-128, -32, 704, 896, -32, 64, "rock1", "grass1"))
    # Reactor: a bridge over the lava with warning trim.
    detail((-544, 160, -64), (-352, 224, 0), {"top": "metal1", "y": "hazard1", "other": "metal2"})
    # Light fixtures (8 deep, flush with the ceilings) and wall lamps.
    for x, y in ((112, 96), (112, 272), (400, 16 + 320)):
        detail((x, y, 184), (x + 32, y + 32, 192), {"bottom": "light1", "top": "skip", "other": "metal1"}, True)
    for x, y in ((880, 96), (1024, 256)):
        detail((x, y, 152), (x + 32, y + 32, 160), {"bottom": "light1", "top": "skip", "other": "metal1"}, True)
    for x, y in ((1392, 112), (1520, 240)):
        detail((x, y, 376), (x + 32, y + 32, 384), {"bottom": "light1", "top": "skip", "other": "metal1"}, True)
    detail((1144, 48, 64), (1152, 80, 96), {"x": "+0light", "other": "metal1"}, True)     # workshop east wall
    detail((-264, 320, 96), (-256, 352, 128), {"x": "+0light", "other": "metal1"}, True)  # reactor east wall
    # Hall: a crate in the corner.
    detail((16, 320, 0), (80, 368, 48), "crate1", True)
    return brushes


# ---------------------------------------------------------------- entities
def ent(classname, origin=None, **keys):
    e = [("classname", classname)]
    if origin is not None:
        e.append(("origin", "%d %d %d" % origin))
    for k, v in keys.items():
        e.append((k, str(v)))
    return e


def point_entities():
    E = []
    E.append(ent("info_player_start", (64, 192, 24), angle=0))
    # Viewpoints (deathmatch starts) in every area.
    E.append(ent("info_player_deathmatch", (448, 352, 24), angle=225))
    E.append(ent("info_player_deathmatch", (800, 192, 24), angle=0))
    E.append(ent("info_player_deathmatch", (1600, 48, 216), angle=135))
    E.append(ent("info_player_deathmatch", (256, 576, 8), angle=90))
    E.append(ent("info_player_deathmatch", (0, 960, 88), angle=300))
    E.append(ent("info_player_deathmatch", (-304, 192, 24), angle=180))
    E.append(ent("info_player_deathmatch", (1216, 192, 40), angle=0))
    E.append(ent("info_intermission", (560, 600, 320), mangle="20 135 0"))
    E.append(ent("info_teleport_destination", (128, 96, 24), angle=45, targetname="hall_arrival"))
    # Items.
    E.append(ent("item_health", (240, 320, 0)))
    E.append(ent("item_armor1", (1088, 320, 0)))
    E.append(ent("weapon_supershotgun", (1472, 192, 192)))
    E.append(ent("item_shells", (-448, 320, 0)))
    E.append(ent("item_spikes", (480, 640, -32)))

    def light(o, level, style=None, cls="light", **k):
        kw = dict(k)
        kw["light"] = level
        if style is not None:
            kw["style"] = style
        E.append(ent(cls, o, **kw))

    # Hall: steady lights under the fixtures, one flickering torch-like light by the pool.
    light((128, 112, 168), 300)
    light((128, 288, 168), 300)
    light((416, 352, 168), 250)
    light((384, 192, 64), 200, style=1)              # flicker over the pool
    light((256, 192, 96), 150)
    # East corridor: a slow strong pulse by the door.
    light((576, 192, 96), 200, style=2)
    light((704, 192, 96), 200, style=2)
    # Workshop: fluorescent flicker and a steady fill.
    light((896, 112, 136), 280, style=10, cls="light_fluoro")
    light((1040, 272, 136), 280, style=10, cls="light_fluoro")
    light((960, 192, 64), 180)
    light((1120, 64, 80), 120, style=6)              # near the animated wall lamp
    # Lift shaft.
    light((1216, 192, 96), 200)
    light((1216, 192, 320), 200)
    # Gallery: gentle pulse and steady lights; teleporter glow.
    light((1408, 128, 360), 300, style=5)
    light((1536, 256, 360), 300)
    light((1472, 192, 256), 180)
    light((1640, 192, 256), 200, style=11, _color="200 120 255")
    # North corridor and courtyard (outdoors: strong lights high up, plus sun keys).
    light((256, 448, 96), 220)
    light((256, 768, 320), 500)
    light((0, 640, 200), 300)
    light((480, 848, 40), 180, style=3)              # slime glow, stutter
    light((0, 960, 160), 250)
    # West corridor and reactor: lava glow and a candle-like flicker.
    light((-128, 192, 96), 220)
    light((-448, 128, 32), 250, style=4, _color="255 140 60")
    light((-448, 256, 32), 250, style=4, _color="255 140 60")
    light((-448, 192, 160), 260, targetname="reactor_lamp")
    light((-304, 336, 112), 150, style=8)
    return E


def brush_entities():
    out = []
    # Door in the east corridor: slides up into the ceiling.
    out.append((ent("func_door", None, angle=-1, speed=100, wait=3, lip=8, sounds=2),
                [box_brush((624, 160, 0), (640, 224, 128), {"x": "door1", "other": "metal1"}, True)]))
    # Lift in the shaft: a plat 96 x 96, top at the gallery floor, travelling 176 units.
    out.append((ent("func_plat", None, height=176, speed=150, sounds=1),
                [box_brush((1168, 144, 176), (1264, 240, 192), {"top": "metal1", "bottom": "metal1", "other": "hazard1"},
                           True)]))
    # Reactor button on the west wall (pushes in), toggles the reactor lamp.
    out.append((ent("func_button", None, angle=180, wait=1, target="reactor_lamp"),
                [box_brush((-640, 176, 48), (-632, 208, 80), {"x": "button1", "other": "metal1"}, True)]))
    # Teleporter in the gallery alcove: the trigger volume in front of the energy field.
    out.append((ent("trigger_teleport", None, target="hall_arrival"),
                [box_brush((1664, 160, 192), (1680, 224, 304), "trigger")]))
    return out


def liquid_brushes():
    return [
        box_brush((304, 96, -96), (464, 288, -16), "*water1"),
        box_brush((400, 768, -96), (560, 928, -48), "*slime1"),
        box_brush((-544, 96, -64), (-352, 160, -24), "*lava1"),
        box_brush((-544, 224, -64), (-352, 288, -24), "*lava1"),
        box_brush((1680, 144, 192), (1712, 240, 320), "*tele1"),
    ]


def clip_brushes():
    # A clip brush over the crate stack in the courtyard (nothing stands on its top).
    return [box_brush((-16, 640, 96), (112, 704, 160), "clip")]


# ---------------------------------------------------------------- output
def write(out):
    world = world_brushes() + liquid_brushes() + clip_brushes()
    out.write("// Starbow sample world: generated by content/maps/gen_sample.py (edit that, then rerun)\n")
    out.write("// Game: Quake\n// Format: Valve\n")
    out.write("// entity 0\n{\n")
    for k, v in (("classname", "worldspawn"), ("mapversion", "220"), ("wad", "starbow.wad"),
                 ("message", "Starbow sample world"), ("worldtype", "2"), ("sounds", "0"),
                 ("_sunlight", "160"), ("_sun_mangle", "30 -55 0"), ("_sunlight_color", "255 235 210")):
        out.write('"%s" "%s"\n' % (k, v))
    for i, b in enumerate(world):
        out.write("// brush %d\n{\n" % i)
        for f in b:
            out.write(f.text() + "\n")
        out.write("}\n")
    out.write("}\n")
    n = 1
    for keys, brushes in brush_entities():
        out.write("// entity %d\n{\n" % n)
        for k, v in keys:
            out.write('"%s" "%s"\n' % (k, v))
        for i, b in enumerate(brushes):
            out.write("// brush %d\n{\n" % i)
            for f in b:
                out.write(f.text() + "\n")
            out.write("}\n")
        out.write("}\n")
        n += 1
    for keys in point_entities():
        out.write("// entity %d\n{\n" % n)
        for k, v in keys:
            out.write('"%s" "%s"\n' % (k, v))
        out.write("}\n")
        n += 1
    sys.stderr.write("sample.map: %d world brushes, %d entities\n" % (len(world), n))


if __name__ == "__main__":
    write(sys.stdout)
