"""Casters lying through a receiver that is not flat, under a low light, as scene files.

Used by random_scenes.py --sunk. The class of issue #14's scenes that the audits kept finding
wrong: a long cylinder or box half under the dunes, where the receiver's own layers sit on both
sides of a caster part and the light meets the receiver's faces at a few degrees. Each scene has
one receiver (dunes, the ring, or a plate tilted out of the xz plane), one to three casters
pushed through it (capped or open cylinders, long boxes, half-buried spheres, a fighter lying on
its side), one light 1 to 20 degrees above the receiver, one camera.
World space in metres, y up; the dunes' mean height is y = 0 (the ring's mat at y = 1).
"""
import math


def r3(values):
    return [round(v, 3) for v in values]


def receiver(r):
    """The receiver object and the height the casters are sunk to."""
    kind = r.choice(["dunes", "dunes", "ring", "tilted_plate"])
    casts = r.random() < 0.25
    if kind == "dunes":
        mesh = {"shape": "heightfield", "size": 10, "divisions": r.choice([16, 32, 48]),
                "amplitude": round(r.uniform(0.15, 0.7), 2), "wavelength": round(r.uniform(1.5, 5), 2)}
        return {"name": "dunes", "mesh": mesh, "casts_shadow": casts, "receives_shadow": True}, 0.0
    if kind == "ring":
        return {"name": "ring", "mesh": {"shape": "ring"}, "casts_shadow": casts,
                "receives_shadow": True}, 1.0
    tilt = [round(r.uniform(-25, 25), 1), 0, round(r.uniform(-25, 25), 1)]
    return {"name": "plate", "mesh": {"shape": "plane", "size": 8, "divisions": r.choice([1, 8, 20])},
            "rotation_degrees": tilt, "casts_shadow": casts, "receives_shadow": True}, 0.0


def caster(r, index, height):
    """A caster whose middle lies within a few tenths of a metre of the receiver's height."""
    kind = r.choice(["cylinder", "cylinder", "box", "sphere", "fighter"])
    turn = [round(r.uniform(60, 120)), round(r.uniform(-180, 180)), round(r.uniform(-30, 30))]
    if kind == "cylinder":
        length = round(r.uniform(1, 4), 2)
        mesh = {"shape": "cylinder", "radius": round(r.uniform(0.08, 0.5), 2), "length": length,
                "caps": r.random() < 0.7}
    elif kind == "box":
        mesh = {"shape": "box", "size": r3([r.uniform(0.15, 0.6), r.uniform(1.5, 4), r.uniform(0.15, 0.6)])}
    elif kind == "sphere":
        mesh, turn = {"shape": "sphere", "radius": round(r.uniform(0.2, 0.8), 2)}, [0, 0, 0]
    else:
        mesh = {"shape": "fighter", "pose": r.choice(["guard", "punch", "kick", "hit"]),
                "phase": round(r.random(), 2)}
        turn = [0, round(r.uniform(-180, 180)), 90]
    position = r3([r.uniform(-1.5, 1.5), height + r.uniform(-0.3, 0.2), r.uniform(-1.5, 1.5)])
    return {"name": f"{kind}{index}", "mesh": mesh, "position": position,
            "rotation_degrees": turn, "casts_shadow": True, "receives_shadow": r.random() < 0.8}


def scene(seed, r):
    ground, height = receiver(r)
    objects = [ground] + [caster(r, i, height) for i in range(r.randint(1, 3))]
    elevation, azimuth = math.radians(r.uniform(1, 20)), r.uniform(0, 2 * math.pi)
    distance = r.uniform(1.5, 8)
    light = {"position": r3([distance * math.cos(elevation) * math.cos(azimuth),
                             height + 0.2 + distance * math.sin(elevation),
                             distance * math.cos(elevation) * math.sin(azimuth)]),
             "target": r3([r.uniform(-1, 1), height, r.uniform(-1, 1)]),
             "cone_degrees": round(r.uniform(30, 120), 1),
             "shadow_size": r.choice([64, 128, 256, 512])}
    camera_elevation, camera_azimuth = math.radians(r.uniform(10, 50)), r.uniform(0, 2 * math.pi)
    camera_distance = r.uniform(4, 10)
    camera = {"position": r3([camera_distance * math.cos(camera_elevation) * math.cos(camera_azimuth),
                              height + camera_distance * math.sin(camera_elevation),
                              camera_distance * math.cos(camera_elevation) * math.sin(camera_azimuth)]),
              "target": [0, height, 0], "fov_degrees": round(r.uniform(35, 65)),
              "near": 0.1, "far": 100}
    width = r.choice([160, 240, 320])
    return {"description": f"tools/random_scenes.py --sunk, seed {seed}",
            "screen": {"width": width, "height": width * 3 // 4},
            "camera": camera, "lights": [light], "objects": objects}
