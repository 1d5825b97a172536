"""Issue #14's hard classes as scene files with random sizes, angles and distances.

Used by random_scenes.py --classes. Seed n picks class n mod 6, so any six consecutive seeds
hold one scene of each:
  0 a spotlight close behind a caster wider than the floor (the caster's bounds hold the light);
  1 a long bar across a narrow oblique cone (its shadow must stop where the light stops);
  2 flags: panels that cast nothing over casters, balls that receive nothing under planks;
  3 a plate tilted towards an oblique light, small casters above it (acne on the plate);
  4 a light looking back at the camera over posts and balls (acne along lit silhouettes);
  5 two spotlights over casters on a plane, a heightfield or the ring.
World space in metres, y up; floors lie at y = 0 (the ring's mat at y = 1).
"""
import math
import random

CLASSES = ["wall_behind_light", "bar_across_cone", "flags", "tilted_plate", "light_facing_camera",
           "two_lights"]


def r3(values):
    return [round(v, 3) for v in values]


def floor(r, size=None):
    return {"name": "floor", "mesh": {"shape": "plane", "size": size or r.choice([8, 10, 14]),
                                      "divisions": r.choice([1, 4, 10, 20])},
            "color": [0.8, 0.8, 0.8], "casts_shadow": False, "receives_shadow": True}


def ground(r):
    """A receiver that is not flat, or a floor; returns (objects, height casters stand on)."""
    kind = r.choice(["plane", "heightfield", "ring"])
    if kind == "heightfield":
        return [{"name": "dunes", "mesh": {"shape": "heightfield", "size": 10, "divisions": 32,
                                           "amplitude": round(r.uniform(0.05, 0.4), 2),
                                           "wavelength": round(r.uniform(2, 6), 2)},
                 "casts_shadow": False, "receives_shadow": True}], 0.0
    if kind == "ring":
        return [{"name": "ring", "mesh": {"shape": "ring"}, "casts_shadow": False,
                 "receives_shadow": True}], 1.0
    return [floor(r)], 0.0


def polar(r, centre, elevation_degrees, distance, azimuth=None):
    """A point at the given elevation (degrees) and distance (m) from centre (world)."""
    elevation = math.radians(r.uniform(*elevation_degrees))
    azimuth = r.uniform(0, 2 * math.pi) if azimuth is None else azimuth
    d = r.uniform(*distance)
    return r3([centre[0] + d * math.cos(elevation) * math.cos(azimuth),
               centre[1] + d * math.sin(elevation),
               centre[2] + d * math.cos(elevation) * math.sin(azimuth)])


def light(position, target, cone, size):
    return {"position": position, "target": target, "cone_degrees": round(cone, 1),
            "shadow_size": size}


def camera(position, target, fov):
    return {"position": position, "target": target, "fov_degrees": fov, "near": 0.1, "far": 100}


def wall_behind_light(r):
    size = r.choice([8, 10, 12])
    height = r.uniform(1.5, 4)
    wall_z = r.uniform(-2.5, 0)
    turn = r.uniform(-30, 30)
    wall = {"name": "wall", "mesh": {"shape": "box", "size": r3([size * r.uniform(1.0, 1.6), height,
                                                                   r.uniform(0.1, 0.4)])},
            "position": r3([r.uniform(-0.5, 0.5), height / 2, wall_z]), "rotation_degrees": [0, round(turn), 0],
            "color": [0.6, 0.5, 0.4], "casts_shadow": True, "receives_shadow": r.random() < 0.5}
    # The light behind the wall (towards -z, turned with it), aimed over or through it.
    back = r.uniform(0.4, 2.5)
    a = math.radians(turn)
    lx = r.uniform(-1.5, 1.5)
    position = r3([lx * math.cos(a) - back * math.sin(a), height * r.uniform(0.5, 1.4),
                   wall_z - back * math.cos(a)])
    target = r3([r.uniform(-1, 1), 0, wall_z + r.uniform(2, 5)])
    lights = [light(position, target, r.uniform(100, 170), r.choice([64, 128, 256, 512]))]
    cam = camera(polar(r, [0, 0, wall_z + 2], (25, 65), (6, 11), azimuth=math.radians(r.uniform(45, 135))),
                 r3([0, 0, wall_z + 2]), round(r.uniform(45, 65)))
    return [floor(r, size), wall], lights, cam


def bar_across_cone(r):
    objects, base = ground(r)
    length = r.uniform(4, 10)
    thick = r.uniform(0.1, 0.4)
    shape = r.choice(["box", "cylinder"])
    mesh = ({"shape": "box", "size": r3([thick, thick, length])} if shape == "box" else
            {"shape": "cylinder", "radius": round(thick / 2, 3), "length": round(length, 2), "caps": True})
    bar = {"name": "bar", "mesh": mesh, "position": r3([0, base + r.uniform(0.4, 2.5), 0]),
           "rotation_degrees": [90 if shape == "cylinder" else 0, round(r.uniform(-180, 180)), 0],
           "color": [0.9, 0.5, 0.2], "casts_shadow": True, "receives_shadow": r.random() < 0.5}
    centre = [0, base, 0]
    lights = [light(polar(r, centre, (25, 65), (4, 9)), r3([r.uniform(-1, 1), base, r.uniform(-1, 1)]),
                    r.uniform(12, 40), r.choice([64, 128, 256]))]
    cam = camera(polar(r, centre, (30, 70), (8, 13)), r3([0, base, 0]), round(r.uniform(45, 65)))
    return objects + [bar], lights, cam


def flags(r):
    objects = [floor(r)]
    for i in range(r.randint(1, 2)):  # a panel that casts nothing, over a caster
        x, z = r.uniform(-2, 2), r.uniform(-2, 2)
        objects.append({"name": f"sign{i}", "mesh": {"shape": "box", "size": r3([r.uniform(0.8, 2), 0.08, r.uniform(0.6, 1.4)])},
                        "position": r3([x, r.uniform(2, 3.5), z]), "rotation_degrees": [0, round(r.uniform(-90, 90)), round(r.uniform(-20, 20))],
                        "color": [0.9, 0.8, 0.2], "casts_shadow": False, "receives_shadow": r.random() < 0.7})
        h = r.uniform(0.3, 1.0)
        objects.append({"name": f"pedestal{i}", "mesh": {"shape": "box", "size": r3([r.uniform(0.4, 0.9), h, r.uniform(0.4, 0.9)])},
                        "position": r3([x + r.uniform(-0.3, 0.3), h / 2, z + r.uniform(-0.3, 0.3)]),
                        "color": [0.5, 0.5, 0.6], "casts_shadow": True, "receives_shadow": True})
    for i in range(r.randint(1, 2)):  # a ball that receives nothing, under a plank that casts
        x, z = r.uniform(-2, 2), r.uniform(-2, 2)
        radius = r.uniform(0.2, 0.5)
        objects.append({"name": f"plank{i}", "mesh": {"shape": "box", "size": r3([r.uniform(0.8, 1.8), 0.1, r.uniform(0.4, 0.8)])},
                        "position": r3([x, r.uniform(1.5, 3), z]), "rotation_degrees": [0, round(r.uniform(-90, 90)), 0],
                        "color": [0.4, 0.3, 0.2], "casts_shadow": True, "receives_shadow": r.random() < 0.7})
        objects.append({"name": f"ball{i}", "mesh": {"shape": "sphere", "radius": round(radius, 2)},
                        "position": r3([x + r.uniform(-0.3, 0.3), radius, z + r.uniform(-0.3, 0.3)]),
                        "color": [0.2, 0.6, 0.9], "casts_shadow": r.random() < 0.5, "receives_shadow": False})
    lights = [light(polar(r, [0, 0, 0], (40, 85), (5, 9)), r3([r.uniform(-1, 1), 0, r.uniform(-1, 1)]),
                    r.uniform(50, 90), r.choice([128, 256, 512]))]
    cam = camera(polar(r, [0, 0, 0], (30, 60), (6, 10)), [0, 0.8, 0], round(r.uniform(45, 60)))
    return objects, lights, cam


def tilted_plate(r):
    tilt = r.uniform(10, 60) * r.choice([-1, 1])
    height = r.uniform(0.6, 1.4)
    plate = {"name": "plate", "mesh": {"shape": "box", "size": r3([r.uniform(1.5, 3), r.uniform(0.03, 0.1), r.uniform(1.5, 3)])},
             "position": r3([0, height, 0]), "rotation_degrees": [round(r.uniform(-20, 20)), round(r.uniform(-180, 180)), round(tilt)],
             "color": [0.6, 0.7, 0.8], "casts_shadow": True, "receives_shadow": True}
    objects = [floor(r), plate]
    for i in range(r.randint(1, 2)):
        side = r.uniform(0.2, 0.5)
        objects.append({"name": f"cube{i}", "mesh": {"shape": "box", "size": r3([side] * 3)},
                        "position": r3([r.uniform(-0.8, 0.8), height + r.uniform(0.8, 1.6), r.uniform(-0.8, 0.8)]),
                        "rotation_degrees": [0, round(r.uniform(-45, 45)), 0],
                        "color": [0.9, 0.4, 0.2], "casts_shadow": True, "receives_shadow": True})
    lights = [light(polar(r, [0, height, 0], (15, 60), (4, 9)), r3([0, height * 0.6, 0]),
                    r.uniform(30, 60), r.choice([128, 256, 512]))]
    cam = camera(polar(r, [0, height, 0], (25, 60), (5, 8)), r3([0, height * 0.8, 0]), round(r.uniform(45, 60)))
    return objects, lights, cam


def light_facing_camera(r):
    objects, base = ground(r)
    for i in range(r.randint(2, 4)):
        x, z = r.uniform(-1.8, 1.8), r.uniform(-2, 0.8)
        kind = r.choice(["post", "cylinder", "ball"])
        if kind == "post":
            h = r.uniform(0.8, 2)
            mesh, pos = {"shape": "box", "size": r3([r.uniform(0.2, 0.4), h, r.uniform(0.2, 0.4)])}, [x, base + h / 2, z]
        elif kind == "cylinder":
            mesh, pos = {"shape": "cylinder", "radius": round(r.uniform(0.1, 0.3), 2), "length": round(r.uniform(0.8, 2), 2), "caps": True}, [x, base, z]
        else:
            radius = r.uniform(0.2, 0.45)
            mesh, pos = {"shape": "sphere", "radius": round(radius, 2)}, [x, base + radius, z]
        objects.append({"name": f"{kind}{i}", "mesh": mesh, "position": r3(pos),
                        "rotation_degrees": [0, round(r.uniform(-45, 45)), 0],
                        "color": [0.8, 0.3, 0.2], "casts_shadow": True, "receives_shadow": r.random() < 0.8})
    # The camera looks along -z; the light stands beyond the casters and looks back along +z.
    cam_pos = r3([r.uniform(-1.5, 1.5), base + r.uniform(1, 3.5), r.uniform(5, 8)])
    light_pos = r3([r.uniform(-1.5, 1.5), base + r.uniform(2, 5), -r.uniform(5, 9)])
    lights = [light(light_pos, r3([r.uniform(-0.5, 0.5), base, r.uniform(1, 3)]), r.uniform(40, 70),
                    r.choice([128, 256, 512]))]
    return objects, lights, camera(cam_pos, r3([0, base + 0.8, 0]), round(r.uniform(45, 60)))


def two_lights(r):
    objects, base = ground(r)
    for i in range(r.randint(2, 3)):
        kind = r.choice(["box", "sphere", "fighter"])
        if kind == "box":
            size = r3([r.uniform(0.3, 1.2) for _ in range(3)])
            mesh, y = {"shape": "box", "size": size}, base + size[1] / 2 + r.choice([0, r.uniform(0.2, 1)])
        elif kind == "sphere":
            radius = r.uniform(0.2, 0.6)
            mesh, y = {"shape": "sphere", "radius": round(radius, 2)}, base + radius + r.choice([0, r.uniform(0.2, 1)])
        else:
            mesh, y = {"shape": "fighter", "pose": r.choice(["guard", "punch", "kick"]), "phase": round(r.random(), 2)}, base
        objects.append({"name": f"{kind}{i}", "mesh": mesh,
                        "position": r3([r.uniform(-1.5, 1.5), y, r.uniform(-1.5, 1.5)]),
                        "rotation_degrees": [0, round(r.uniform(-180, 180)), 0],
                        "casts_shadow": True, "receives_shadow": r.random() < 0.8})
    centre = [0, base, 0]
    lights = [light(polar(r, centre, (30, 80), (3, 9)), r3([r.uniform(-1, 1), base, r.uniform(-1, 1)]),
                    r.uniform(30, 110), r.choice([128, 256, 512])) for _ in range(2)]
    cam = camera(polar(r, centre, (20, 60), (5, 10)), r3([0, base + 0.5, 0]), round(r.uniform(40, 65)))
    return objects, lights, cam


def scene(seed):
    r = random.Random(seed)
    kind = CLASSES[seed % len(CLASSES)]
    objects, lights, cam = globals()[kind](r)
    width = r.choice([160, 240, 320, 400])
    return {"description": f"tools/random_scenes.py --classes, seed {seed}: {kind}",
            "screen": {"width": width, "height": width * 3 // 4},
            "camera": cam, "lights": lights, "objects": objects}
