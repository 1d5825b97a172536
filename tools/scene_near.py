"""A spotlight close behind a large caster, of every shape, over every receiver, as scene files.

Used by random_scenes.py --near-lights. Issue #14's class 1 (a wide spotlight a metre behind a
caster wider than the floor) appeared in the other kinds of scene only as a wall on a flat floor
(scene_classes.py). Here seed n puts caster kind n mod 6 over receiver kind (n div 6) mod 4, so
any 24 consecutive seeds hold every pairing:
  casters    wall (3 to 8 m wide, standing, sunk or floating over a gap), box (a crate 3 to 8 m
             wide, on the receiver or lifted), sphere (3 to 6 m across, partly sunk or floating),
             slab (a roof 3 to 8 m wide, 1 to 3 m up, the light above it), mesh (scene_meshes.py's
             torus, prism, bowl or crumpled sheet scaled to 3 to 8 m, sometimes unwelded),
             panel (a board tilted 20 to 70 degrees, the light on its upper side);
  receivers  floor (3 to 12 m, often narrower than the caster), dunes, the ring, a tilted plate
             (a plane or a thin box, turned 5 to 30 degrees).
The light stands 0.2 to 2.5 m beyond the caster's farthest point along a direction away from the
receiver (so outside it), aimed through the caster at the receiver, with a cone of 100 to 170
degrees (3 in 5), 40 to 100 (1 in 4) or 3 to 12 (the rest), sometimes a beam map; up to two small
casters of random_scenes.py under it, sometimes one or two more spotlights as --lights has them;
the camera faces the shadow, or (1 in 3) stands behind the receiver or along it
(scene_options.camera_behind). World space in metres, y up.
"""
import math
import os

import scene_geometry as g
import scene_lights
import scene_meshes
import scene_options

CASTERS = ["wall", "box", "sphere", "slab", "mesh", "panel"]
RECEIVERS = ["floor", "dunes", "ring", "plate"]


def receiver(r, kind):
    """The receiver object and the height the casters stand on near the middle (world y)."""
    if kind == "floor":
        return {"name": "floor", "mesh": {"shape": "plane", "size": r.choice([3, 4, 5, 6, 8, 12]),
                                          "divisions": r.choice([1, 4, 10])},
                "color": [0.8, 0.8, 0.8], "casts_shadow": False, "receives_shadow": True}, 0.0
    if kind == "dunes":
        mesh = {"shape": "heightfield", "size": r.choice([6, 10]), "divisions": r.choice([16, 32]),
                "amplitude": round(r.uniform(0.05, 0.5), 2), "wavelength": round(r.uniform(2, 6), 2)}
        return {"name": "dunes", "mesh": mesh, "casts_shadow": r.random() < 0.25,
                "receives_shadow": True}, 0.0
    if kind == "ring":
        return {"name": "ring", "mesh": {"shape": "ring"}, "casts_shadow": r.random() < 0.25,
                "receives_shadow": True}, 1.0
    side = r.uniform(4, 8)
    turn = [round(r.uniform(5, 30) * r.choice([-1, 1]), 1), round(r.uniform(-180, 180)),
            round(r.uniform(0, 25) * r.choice([-1, 1]), 1)]
    mesh = ({"shape": "plane", "size": round(side, 2), "divisions": r.choice([1, 8, 20])}
            if r.random() < 0.5 else
            {"shape": "box", "size": g.r3([side, r.uniform(0.03, 0.1), side * r.uniform(0.7, 1.2)])})
    return {"name": "plate", "mesh": mesh, "rotation_degrees": turn, "casts_shadow": r.random() < 0.3,
            "receives_shadow": True}, 0.0


def settle(obj, points, ground, lift):
    """Moves obj (and its world points) up or down so its lowest point is `lift` above the
    receiver's surface under it (negative: sunk into it)."""
    low = min(points, key=lambda p: p[1])
    dy = ground(low[0], low[2]) + lift - low[1]
    obj["position"] = g.r3(g.add(obj["position"], [0, dy, 0]))
    return [g.add(p, [0, dy, 0]) for p in points]


def big_caster(r, kind, seed, out_dir, ground):
    """The large caster, its world points, and the direction (unit, world) the light lies in."""
    width = r.uniform(3, 8)
    centre = [r.uniform(-0.5, 0.5), 0, r.uniform(-0.5, 0.5)]
    azimuth = r.uniform(0, 2 * math.pi)
    obj = {"name": kind, "position": centre, "color": [0.6, 0.5, 0.4], "casts_shadow": True,
           "receives_shadow": r.random() < 0.6}
    vertices = None
    lift = r.choice([r.uniform(-0.2, 0), r.uniform(0.05, 0.5)])
    if kind == "wall":
        yaw = r.uniform(-180, 180)
        obj["mesh"] = {"shape": "box", "size": g.r3([width, r.uniform(1.5, 4), r.uniform(0.1, 0.4)])}
        obj["rotation_degrees"] = [0, round(yaw), 0]
        back = g.rotate([0, 0, -1], [0, round(yaw), 0])
        u = g.unit(g.add(g.mul(back, 1.0), [0, math.tan(math.radians(r.uniform(0, 35))), 0]))
    elif kind == "box":
        obj["mesh"] = {"shape": "box", "size": g.r3([width, r.uniform(1, 3), r.uniform(2, 5)])}
        obj["rotation_degrees"] = [0, round(r.uniform(-180, 180)), 0]
        lift = r.choice([r.uniform(-0.2, 0), 0, r.uniform(0.05, 1.5)])
        u = g.direction(r.uniform(10, 75), azimuth)
    elif kind == "sphere":
        radius = min(width / 2, 3)
        obj["mesh"] = {"shape": "sphere", "radius": round(radius, 2), "slices": 32, "stacks": 20}
        lift = radius * r.uniform(-0.6, 0.3)
        u = g.direction(r.uniform(10, 80), azimuth)
    elif kind == "slab":
        obj["mesh"] = {"shape": "box", "size": g.r3([width, r.uniform(0.1, 0.4), r.uniform(3, 6)])}
        obj["rotation_degrees"] = [round(r.uniform(-10, 10)), round(r.uniform(-180, 180)), round(r.uniform(-10, 10))]
        lift = r.uniform(1, 3)
        u = g.direction(r.uniform(45, 90), azimuth)
    elif kind == "mesh":
        make = r.choice(["torus", "prism", "bowl", "crumple"])
        vertices, faces = getattr(scene_meshes, make)(r)
        if r.random() < 0.4:
            vertices, faces = scene_meshes.unweld(vertices, faces, r)
            make += "_loose"
        across = max(max(v[0] for v in vertices) - min(v[0] for v in vertices),
                     max(v[2] for v in vertices) - min(v[2] for v in vertices), 0.1)
        s = width / across
        file_name = f"near_{seed:04d}_{make}.obj"
        scene_meshes.write_obj(os.path.join(out_dir, file_name), vertices, faces)
        obj["name"] = make
        obj["mesh"] = {"obj": file_name}
        obj["scale"] = g.r3([s * r.uniform(0.8, 1.2), s * r.uniform(0.6, 1.4), s * r.uniform(0.8, 1.2)])
        obj["rotation_degrees"] = [round(r.uniform(-60, 60)), round(r.uniform(-180, 180)), round(r.uniform(-60, 60))]
        u = g.direction(r.uniform(10, 80), azimuth)
    else:
        obj["mesh"] = {"shape": "box", "size": g.r3([width, r.uniform(0.05, 0.15), r.uniform(2, 5)])}
        obj["rotation_degrees"] = [round(r.uniform(20, 70) * r.choice([-1, 1])), round(r.uniform(-180, 180)), 0]
        lift = r.uniform(0.2, 1.5)
        n = g.receiver_normal(obj)
        u = g.unit(g.add(n, g.mul(g.direction(0, azimuth), 0.3)))
    points = settle(obj, g.world_points(obj, vertices), ground, lift)
    if u[1] < 0.05:  # raised a little so lifting the light later keeps it outside the caster
        u = g.unit([u[0], 0.05, u[2]])
    return obj, points, u


def near_light(r, points, u, ground):
    """The light 0.2 to 2.5 m beyond the caster's farthest point along u, aimed through it."""
    centre = g.mul([sum(p[k] for p in points) for k in range(3)], 1.0 / len(points))
    # A base point off the caster's middle, so the light is not always on its axis.
    side = g.unit(g.cross(u, [0, 1, 0])) if abs(u[1]) < 0.99 else [1, 0, 0]
    spread = max(g.extent_along(points, centre, side), 0.2)
    base = g.add(centre, g.mul(side, r.uniform(-0.6, 0.6) * spread))
    gap = r.choice([r.uniform(0.2, 1.0), r.uniform(1.0, 2.5)])
    position = g.add(base, g.mul(u, g.extent_along(points, base, u) + gap))
    # Above the receiver by 0.3 m at least (u rises, so this only moves it further out).
    position[1] = max(position[1], ground(position[0], position[2]) + 0.3)
    through = g.add(centre, [r.uniform(-1, 1), 0, r.uniform(-1, 1)])
    target = g.add(centre, g.mul(g.unit([-u[0], 0, -u[2]]) if math.hypot(u[0], u[2]) > 1e-3 else [1, 0, 0],
                                 r.uniform(1, 4)))
    if position[1] > through[1] + 0.1:
        t = (position[1] - ground(through[0], through[2])) / (position[1] - through[1])
        hit = g.add(position, g.mul(g.sub(through, position), t))
        if math.hypot(hit[0], hit[2]) < 10:
            target = hit
    target[1] = ground(target[0], target[2])
    pick = r.random()
    cone = r.uniform(100, 170) if pick < 0.6 else r.uniform(40, 100) if pick < 0.85 else r.uniform(3, 12)
    light = {"position": g.r3(position), "target": g.r3(target), "cone_degrees": round(cone, 1),
             "shadow_size": r.choice([64, 128, 256, 512])}
    if r.random() < 0.4:
        light["beam"] = r.choice(scene_lights.BEAMS)
        made = scene_lights.attenuation(r, True)
        if made is not None:
            light["attenuation"] = made
    return light, gap


def clear_of(points, *spots):
    """Whether the spots (world) lie outside the object's bounding sphere by 0.2 m."""
    centre = g.mul([sum(p[k] for p in points) for k in range(3)], 1.0 / len(points))
    radius = max(math.sqrt(g.dot(g.sub(p, centre), g.sub(p, centre))) for p in points)
    return all(math.sqrt(g.dot(g.sub(s, centre), g.sub(s, centre))) > radius + 0.2 for s in spots)


def front_camera(r, light, points):
    """A camera facing the shadow: on the far side of the caster from the light, outside it."""
    target = light["target"]
    away = math.atan2(target[2] - light["position"][2], target[0] - light["position"][0])
    for _ in range(20):
        direction = g.direction(r.uniform(15, 65), away + math.radians(r.uniform(-70, 70)))
        position = g.add(target, g.mul(direction, r.uniform(5, 12)))
        if clear_of(points, position):
            break
    return {"position": g.r3(position), "target": g.r3(g.add(target, [0, 0.3, 0])),
            "fov_degrees": round(r.uniform(40, 70)), "near": 0.1, "far": 100}


def scene(seed, r, out_dir, small_caster, on_sphere):
    """One scene; `small_caster` and `on_sphere` are random_scenes.py's caster and on_sphere."""
    kind, under = CASTERS[seed % len(CASTERS)], RECEIVERS[(seed // len(CASTERS)) % len(RECEIVERS)]
    floor, base = receiver(r, under)

    def ground(x, z):
        return g.surface_height(floor, x, z)

    big, points, u = big_caster(r, kind, seed, out_dir, ground)
    light, gap = near_light(r, points, u, ground)
    objects = [floor, big]
    for i in range(r.randint(0, 2)):
        small = small_caster(r, i, base)
        if clear_of(g.world_points(small), light["position"]):
            objects.append(small)
    lights = [light]
    if r.random() < 0.35:
        for _ in range(r.randint(1, 2)):
            exact_allowed = not any(l.get("attenuation", {}).get("mode") == "exact" for l in lights)
            lights.append(scene_lights.spotlight(r, base, on_sphere, exact_allowed))
    made = {"description": f"tools/random_scenes.py --near-lights, seed {seed}: {kind} over {under}, "
                           f"the light {gap:.2f} m behind it",
            "screen": {"width": 0, "height": 0}, "camera": front_camera(r, light, points),
            "lights": lights, "objects": objects}
    if r.random() < 1 / 3:
        made["description"] += ", " + scene_options.camera_behind(made, r)
    width = r.choice([160, 240, 320])
    made["screen"] = {"width": width, "height": width * 3 // 4}
    return made
