"""Receivers that are thin or far from flat, lights nearly in their plane, as scene files.

Used by random_scenes.py --receivers. The other kinds receive on a plane, the dunes, the ring or a
tilted plate; here seed n makes receiver kind n mod 6:
  terraces   an open stepped sheet (OBJ), steps 0.3 to 1.2 m deep rising or falling 0.05 to
             0.6 m, casters standing on the steps or lying across several of them;
  ropes      two to four sagging tubes 1 to 6 cm thick (OBJ, open ends) over a floor, a caster
             above them: receivers a few pixels wide;
  steep      dunes 0.5 to 1.8 m high with a wavelength of 0.8 to 3 m (slopes up to 80 degrees),
             shadowing themselves half the time, casters standing on them or sunk in them;
  sheet      a crumpled sheet 4 to 10 m wide with bumps up to 1.5 m (OBJ, sometimes unwelded with
             zero-area triangles) as the receiver, casters over and through it;
  stacked    a floor and two to four thin plates (boxes or planes) stacked over it, tilted up to
             20 degrees, with poles and bars piercing several of them at once;
  in_plane   a plane, a tilted plate or nearly flat dunes under one or two lights 0.05 to 3
             degrees above the receiver's plane (scene_mixed.in_plane_light).
Lights have shadow maps of 32 to 512 texels (32 appears in no other kind). The OBJ files are
written beside the scenes (counter-clockwise seen from the lit side, model space in metres).
The receiver is the first object, as scene_options.py expects. World space in metres, y up.
"""
import math
import os

import scene_geometry as g
import scene_meshes
import scene_mixed

KINDS = ["terraces", "ropes", "steep", "sheet", "stacked", "in_plane"]
SIZES = [32, 64, 128, 256, 512]


def obj_file(out_dir, seed, name, vertices, faces):
    file_name = f"receivers_{seed:04d}_{name}.obj"
    scene_meshes.write_obj(os.path.join(out_dir, file_name), vertices, faces)
    return file_name


def terraces(r, seed, out_dir):
    """The stepped sheet along x (model space, centred), and its height under a world point."""
    steps, width = r.randint(3, 8), r.uniform(3, 8)
    runs = [r.uniform(0.3, 1.2) for _ in range(steps)]
    heights = [0.0]
    for _ in range(steps - 1):
        heights.append(heights[-1] + r.choice([1, 1, -1]) * r.uniform(0.05, 0.6))
    x0 = -sum(runs) / 2
    edges = [x0 + sum(runs[:k]) for k in range(steps + 1)]
    vertices, faces = [], []

    def quad(a, b, c, d):
        n = len(vertices)
        vertices.extend([a, b, c, d])
        faces.extend([(n, n + 1, n + 2), (n, n + 2, n + 3)])

    z0, z1 = -width / 2, width / 2
    for k in range(steps):
        h, xa, xb = heights[k], edges[k], edges[k + 1]
        quad((xa, h, z0), (xa, h, z1), (xb, h, z1), (xb, h, z0))         # top, facing +y
        if k > 0:
            low, high = sorted((heights[k - 1], h))
            if h > heights[k - 1]:  # a riser facing the lower step (-x)
                quad((xa, low, z0), (xa, low, z1), (xa, high, z1), (xa, high, z0))
            else:                   # facing +x
                quad((xa, low, z0), (xa, high, z0), (xa, high, z1), (xa, low, z1))
    turn = round(r.uniform(-180, 180))
    receiver = {"name": "terraces", "mesh": {"obj": obj_file(out_dir, seed, "terraces", vertices, faces)},
                "rotation_degrees": [0, turn, 0], "color": [0.7, 0.7, 0.6],
                "casts_shadow": r.random() < 0.6, "receives_shadow": True}

    def height(x, z):
        local = g.rotate([x, 0, z], [0, -turn, 0])
        k = sum(1 for e in edges[1:-1] if local[0] >= e)
        return heights[k] if abs(local[2]) <= width / 2 and edges[0] <= local[0] <= edges[-1] else 0.0

    return [receiver], height, max(sum(runs), width)


def rope(r, index, seed, out_dir):
    """A sagging open tube along x from -L/2 to L/2 (model space): a parabola `sag` deep."""
    length, thick, sag = r.uniform(3, 6), r.uniform(0.005, 0.03), r.uniform(0, 0.4)
    sides, segments = r.choice([6, 8, 12]), r.choice([16, 24, 32])
    vertices, faces = [], []
    for i in range(segments + 1):
        x = length * (i / segments - 0.5)
        y = -sag * (1 - (2 * x / length) ** 2)
        for k in range(sides):
            a = 2 * math.pi * k / sides
            vertices.append((x, y + thick * math.cos(a), thick * math.sin(a)))
    for i in range(segments):
        for k in range(sides):
            a, b = i * sides + k, i * sides + (k + 1) % sides
            faces += [(a, b, b + sides), (a, b + sides, a + sides)]
    return obj_file(out_dir, seed, f"rope{index}", vertices, faces), length


def ropes(r, seed, out_dir):
    objects = [{"name": "floor", "mesh": {"shape": "plane", "size": r.choice([6, 10]), "divisions": r.choice([1, 4])},
                "casts_shadow": False, "receives_shadow": True}]
    turn, base = r.uniform(-180, 180), r.uniform(0.5, 1.5)
    for i in range(r.randint(2, 4)):
        file_name, length = rope(r, i, seed, out_dir)
        objects.append({"name": f"rope{i}", "mesh": {"obj": file_name},
                        "position": g.r3([0, base + i * r.uniform(0.15, 0.5), r.uniform(-0.5, 0.5)]),
                        "rotation_degrees": [0, round(turn + r.uniform(-15, 15)), round(r.uniform(-10, 10))],
                        "color": [0.9, 0.9, 0.9], "casts_shadow": r.random() < 0.7, "receives_shadow": True})
    return objects, lambda x, z: 0.0, 6


def steep(r, seed, out_dir):
    size = r.choice([6, 8, 12])
    mesh = {"shape": "heightfield", "size": size, "divisions": r.choice([24, 48, 96]),
            "amplitude": round(r.uniform(0.5, 1.8), 2), "wavelength": round(r.uniform(0.8, 3), 2)}
    dunes = {"name": "dunes", "mesh": mesh, "casts_shadow": r.random() < 0.5, "receives_shadow": True}
    return [dunes], lambda x, z: g.surface_height(dunes, x, z), size


def sheet(r, seed, out_dir):
    size, n = r.uniform(4, 10), r.choice([12, 16, 24, 32])
    bumps = [(r.uniform(-size / 2, size / 2), r.uniform(-size / 2, size / 2),
              r.uniform(-1.5, 1.5), r.uniform(0.4, 2)) for _ in range(r.randint(3, 6))]

    def bumpy(x, z):
        return sum(h * math.exp(-((x - bx) ** 2 + (z - bz) ** 2) / (w * w)) for bx, bz, h, w in bumps)

    vertices = [(size * (i / n - 0.5), 0.0, size * (j / n - 0.5)) for i in range(n + 1) for j in range(n + 1)]
    vertices = [(x, bumpy(x, z), z) for x, _, z in vertices]
    faces = []
    for i in range(n):
        for j in range(n):
            a, b, c, d = i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1, i * (n + 1) + j + 1
            faces += [(a, d, c), (a, c, b)]
    name = "sheet"
    if r.random() < 0.3:
        vertices, faces = scene_meshes.unweld(vertices, faces, r)
        name = "sheet_loose"
    receiver = {"name": name, "mesh": {"obj": obj_file(out_dir, seed, name, vertices, faces)},
                "color": [0.6, 0.7, 0.6], "casts_shadow": r.random() < 0.5, "receives_shadow": True}
    return [receiver], bumpy, size


def stacked(r, seed, out_dir):
    objects = [{"name": "floor", "mesh": {"shape": "plane", "size": r.choice([6, 10]), "divisions": r.choice([1, 10])},
                "casts_shadow": False, "receives_shadow": True}]
    height = 0.0
    for i in range(r.randint(2, 4)):
        height += r.uniform(0.3, 1.0)
        side = [r.uniform(1.5, 4), r.uniform(1.5, 4)]
        mesh = ({"shape": "box", "size": g.r3([side[0], r.uniform(0.02, 0.1), side[1]])} if r.random() < 0.6
                else {"shape": "plane", "size": round(side[0], 2), "divisions": r.choice([1, 4])})
        objects.append({"name": f"plate{i}", "mesh": mesh,
                        "position": g.r3([r.uniform(-0.4, 0.4), height, r.uniform(-0.4, 0.4)]),
                        "rotation_degrees": [round(r.uniform(-20, 20)), round(r.uniform(-180, 180)), round(r.uniform(-20, 20))],
                        "color": [0.7, 0.7, 0.8], "casts_shadow": r.random() < 0.8, "receives_shadow": True})
    for i in range(r.randint(1, 2)):  # through every plate, from the floor up
        tall = height + r.uniform(0.3, 1.5)
        mesh = ({"shape": "cylinder", "radius": round(r.uniform(0.03, 0.25), 3), "length": round(tall, 2),
                 "caps": r.random() < 0.7} if r.random() < 0.6 else
                {"shape": "box", "size": g.r3([r.uniform(0.05, 0.4), tall, r.uniform(0.05, 0.4)])})
        y = 0.0 if "radius" in mesh else tall / 2
        objects.append({"name": f"pole{i}", "mesh": mesh,
                        "position": g.r3([r.uniform(-0.6, 0.6), y, r.uniform(-0.6, 0.6)]),
                        "rotation_degrees": [round(r.uniform(-25, 25)), round(r.uniform(-180, 180)), round(r.uniform(-25, 25))],
                        "color": [0.8, 0.4, 0.2], "casts_shadow": True, "receives_shadow": r.random() < 0.8})
    if r.random() < 0.5:  # a bar lying across the plates, through their heights
        objects.append({"name": "bar", "mesh": {"shape": "box", "size": g.r3([0.15, 0.15, r.uniform(3, 5)])},
                        "position": g.r3([r.uniform(-0.5, 0.5), height * r.uniform(0.3, 0.9), 0]),
                        "rotation_degrees": [round(r.uniform(-60, 60)), round(r.uniform(-180, 180)), 0],
                        "casts_shadow": True, "receives_shadow": r.random() < 0.8})
    return objects, lambda x, z: 0.0, 6


def in_plane(r, seed, out_dir):
    pick = r.choice(["plane", "plate", "dunes"])
    if pick == "plane":
        mesh, turn = {"shape": "plane", "size": r.choice([6, 10, 20]), "divisions": r.choice([1, 4, 20])}, [0, 0, 0]
    elif pick == "plate":
        mesh = {"shape": "box", "size": g.r3([r.uniform(4, 10), r.uniform(0.02, 0.1), r.uniform(4, 10)])}
        turn = [round(r.uniform(-25, 25), 1), round(r.uniform(-180, 180)), round(r.uniform(-25, 25), 1)]
    else:
        mesh = {"shape": "heightfield", "size": 10, "divisions": r.choice([16, 32]),
                "amplitude": round(r.uniform(0.01, 0.1), 3), "wavelength": round(r.uniform(2, 6), 2)}
        turn = [0, 0, 0]
    receiver = {"name": "plate" if pick == "plate" else pick, "mesh": mesh, "rotation_degrees": turn,
                "casts_shadow": False, "receives_shadow": True}
    return [receiver], lambda x, z: g.surface_height(receiver, x, z), 8


def caster(r, index, ground, reach):
    """A box, sphere, cylinder or long bar standing on, lifted over or sunk into the receiver."""
    x, z = r.uniform(-reach, reach), r.uniform(-reach, reach)
    kind = r.choice(["box", "sphere", "cylinder", "bar"])
    if kind == "box":
        mesh = {"shape": "box", "size": g.r3([r.uniform(0.2, 1.2) for _ in range(3)])}
        low = -mesh["size"][1] / 2
    elif kind == "sphere":
        mesh = {"shape": "sphere", "radius": round(r.uniform(0.15, 0.7), 2)}
        low = -mesh["radius"]
    elif kind == "cylinder":
        mesh = {"shape": "cylinder", "radius": round(r.uniform(0.03, 0.3), 3),
                "length": round(r.uniform(0.5, 2.5), 2), "caps": r.random() < 0.7}
        low = 0.0
    else:  # long enough to lie across several steps, bumps or ropes
        mesh = {"shape": "box", "size": g.r3([0.12, 0.12, r.uniform(2.5, 5)])}
        low = -0.06
    lift = r.choice([0.0, r.uniform(-0.3, 0), r.uniform(0.05, 1.5)])
    turn = ([round(r.uniform(-15, 15)), round(r.uniform(-180, 180)), round(r.uniform(-15, 15))]
            if kind != "bar" else [round(r.uniform(-20, 20)), round(r.uniform(-180, 180)), 0])
    return {"name": f"{kind}{index}", "mesh": mesh,
            "position": g.r3([x, ground(x, z) - low + lift, z]), "rotation_degrees": turn,
            "casts_shadow": True, "receives_shadow": r.random() < 0.8}


def scene(seed, r, out_dir):
    kind = KINDS[seed % len(KINDS)]
    objects, ground, extent = globals()[kind](r, seed, out_dir)
    reach = min(extent / 4, 1.5)
    count = r.randint(1, 3) if kind != "stacked" else r.randint(0, 1)
    objects += [caster(r, i, ground, reach) for i in range(count)]
    top = max([ground(0, 0)] + [o["position"][1] for o in objects[1:] if "position" in o])
    if kind == "in_plane":
        lights = [scene_mixed.in_plane_light(r, {"objects": objects}) for _ in range(r.choice([1, 1, 2]))]
    else:
        lights = []
        for _ in range(r.choice([1, 1, 2])):
            e, a, d = math.radians(r.uniform(5, 85)), r.uniform(0, 2 * math.pi), r.uniform(2, 10)
            lights.append({"position": g.r3([d * math.cos(e) * math.cos(a), top + d * math.sin(e),
                                             d * math.cos(e) * math.sin(a)]),
                           "target": g.r3([r.uniform(-1, 1), ground(0, 0), r.uniform(-1, 1)]),
                           "cone_degrees": round(r.uniform(20, 150), 1), "shadow_size": r.choice(SIZES)})
    e, a, d = math.radians(r.uniform(10, 70)), r.uniform(0, 2 * math.pi), r.uniform(3, 12)
    camera = {"position": g.r3([d * math.cos(e) * math.cos(a), top + d * math.sin(e), d * math.cos(e) * math.sin(a)]),
              "target": g.r3([0, ground(0, 0) + 0.3, 0]), "fov_degrees": round(r.uniform(35, 75)),
              "near": 0.1, "far": 100}
    width = r.choice([160, 240, 320])
    return {"description": f"tools/random_scenes.py --receivers, seed {seed}: {kind}",
            "screen": {"width": width, "height": width * 3 // 4},
            "camera": camera, "lights": lights, "objects": objects}
