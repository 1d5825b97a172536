"""The --mixed-lights and --camera-near-edge options of random_scenes.py (scene_options.py applies
them, each with its own random generator, after the older options).

  mixed_lights      two to four more lights, each of a different type (TYPES): lights of every
                    type in one frame, where the other kinds have one type per scene at most;
  camera_near_edge  the camera a few centimetres to a metre from a point of a shadow edge on the
                    receiver, so one texel's error covers many pixels.
The receiver is the scene's first object; an OBJ receiver's surface is taken as the horizontal
plane through its position. World space in metres, y up.
"""
import math

import scene_geometry as g
import scene_lights

TYPES = ["slide", "exact", "in_plane", "narrow", "wide", "tiny_map", "faint"]


def surface(scene):
    """The receiver's height (world y) above a point (x, z) of the xz plane."""
    receiver = scene["objects"][0]
    return lambda x, z: g.surface_height(receiver, x, z)


def normal(scene):
    receiver = scene["objects"][0]
    return g.receiver_normal(receiver) if receiver["mesh"].get("shape") in ("plane", "box") else [0, 1, 0]


def in_plane_light(r, scene):
    """0.05 to 3 degrees above the receiver's plane, 2 to 15 m from a point near its middle."""
    n, height = normal(scene), surface(scene)
    x, z = r.uniform(-1, 1), r.uniform(-1, 1)
    centre = [x, height(x, z), z]
    along = g.unit(g.cross(n, [0, 0, 1] if abs(n[2]) < 0.9 else [1, 0, 0]))
    across = g.cross(n, along)
    a, e = r.uniform(0, 2 * math.pi), math.radians(r.uniform(0.05, 3))
    flat = g.add(g.mul(along, math.cos(a)), g.mul(across, math.sin(a)))
    position = g.add(centre, g.mul(g.add(g.mul(flat, math.cos(e)), g.mul(n, math.sin(e))), r.uniform(2, 15)))
    return {"position": g.r3(position), "target": g.r3(centre), "cone_degrees": round(r.uniform(20, 150), 1),
            "shadow_size": r.choice([32, 64, 128, 256, 512])}


def light_of(kind, r, scene, on_sphere):
    ground = g.ground_height(scene)
    lights = scene["lights"]
    exact_taken = any(l.get("attenuation", {}).get("mode") == "exact" for l in lights)
    if kind == "slide":
        return {"position": on_sphere(r, ground, (30, 80), (3, 8)),
                "target": g.r3([r.uniform(-1, 1), ground, r.uniform(-1, 1)]),
                "cone_degrees": round(r.uniform(30, 70), 1), "slide": r.choice(scene_lights.SLIDES)}
    if kind == "in_plane":
        return in_plane_light(r, scene)
    light = scene_lights.spotlight(r, ground, on_sphere, False)
    if kind == "exact" and not exact_taken:
        light["beam"] = r.choice(scene_lights.BEAMS)
        light["attenuation"] = {"mode": "exact", "constant": 1, "linear": round(r.uniform(0, 0.3), 3),
                                "quadratic": round(r.uniform(0, 0.05), 3)}
    elif kind == "narrow":
        casters = g.caster_points(scene)
        if casters:
            g.aim_across(r, light, r.choice(casters), ground)
    elif kind == "wide":
        light["position"] = on_sphere(r, ground, (40, 90), (1, 3))
        light["cone_degrees"] = round(r.uniform(160, 179), 1)
    elif kind == "tiny_map":
        light["shadow_size"] = 32
    elif kind == "faint":
        light["shadow_strength"] = round(r.uniform(0.05, 0.3), 2)
        light["color"] = g.r3([r.uniform(0.2, 1) for _ in range(3)])
    return light


def mixed_lights(scene, r, on_sphere):
    kinds = r.sample(TYPES, r.randint(2, 4))
    added = []
    for kind in kinds:
        if len(scene["lights"]) >= 16:
            break
        scene["lights"].append(light_of(kind, r, scene, on_sphere))
        added.append(kind.replace("_", " "))
    return "mixed lights: " + ", ".join(added)


def first_hit(start, direction, height, reach, step=0.01):
    """Where the ray from `start` along the unit `direction` first goes from above the surface
    `height` (world) to below it, or None within `reach` metres (a surface taken as unbounded
    may lie above a light beside a tilted plate)."""
    t, above = 0.0, False
    while t < reach:
        p = g.add(start, g.mul(direction, t))
        if p[1] > height(p[0], p[2]):
            above = True
        elif above:
            return p
        t += step
    return None


def in_cone(light, point):
    """Whether a world point lies within 0.9 of the spotlight's half cone (so it is lit)."""
    a, d = g.sub(light["target"], light["position"]), g.sub(point, light["position"])
    cos = g.dot(a, d) / math.sqrt(g.dot(a, a) * g.dot(d, d))
    return math.degrees(math.acos(max(-1.0, min(1.0, cos)))) < 0.45 * light["cone_degrees"]


def on_receiver(scene, point):
    """Whether a world point lies over the receiver's extent (a plane's, the dunes' or a plate's
    square, the ring's mat; an OBJ mesh's is not known, so always), in its model frame."""
    receiver = scene["objects"][0]
    mesh = receiver["mesh"]
    local = g.sub(point, receiver.get("position", [0, 0, 0]))
    ax, ay, az = receiver.get("rotation_degrees", [0, 0, 0])
    local = g.rotate(g.rotate(g.rotate(local, [0, 0, -az]), [0, -ay, 0]), [-ax, 0, 0])
    shape = mesh.get("shape")
    if shape in ("plane", "heightfield"):
        half = [mesh.get("size", 10) / 2] * 2
    elif shape == "box":
        half = [mesh["size"][0] / 2, mesh["size"][2] / 2]
    elif shape == "ring":
        half = [3.0, 3.0]
    else:
        return True
    return abs(local[0]) <= half[0] and abs(local[2]) <= half[1]


def edge_point(scene, r, light, points, toward):
    """Where the ray from the light past the caster's outermost point across its view, in the
    direction `toward` (world), meets the receiver: a point of that caster's shadow edge."""
    centre = g.mul([sum(p[k] for p in points) for k in range(3)], 1.0 / len(points))
    axis = g.sub(centre, light["position"])
    if g.dot(axis, axis) < 1e-6:
        return None
    side = g.cross(g.cross(g.unit(axis), toward), g.unit(axis))  # toward, across the view
    outer = max(points, key=lambda p: g.dot(g.sub(p, centre), side))
    ray = g.sub(outer, light["position"])
    if g.dot(ray, ray) < 1e-9:
        return None
    # From the light: a sunk caster's outermost point may lie under the surface, and then the
    # edge is where the ray goes into the receiver, before it.
    return first_hit(light["position"], g.unit(ray), surface(scene), math.sqrt(g.dot(ray, ray)) + 15)


def camera_near_edge(scene, r):
    lights = g.shadow_lights(scene)
    casters = g.caster_points(scene)
    if not lights or not casters:
        return None
    # Up to 60 tries for an edge point on the receiver that the light reaches (in its cone); else
    # the last one found. Half the tries look for the caster's edge towards the beam's axis.
    hit = None
    for k in range(60):
        light = r.choice(lights)
        points = r.choice(casters)
        toward = [r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)]
        if k % 2:
            centre = g.mul([sum(p[i] for p in points) for i in range(3)], 1.0 / len(points))
            toward = g.sub(light["target"], centre)
        found = edge_point(scene, r, light, points, toward)
        if found is not None:
            hit = found
            if in_cone(light, found) and on_receiver(scene, found):
                break
    if hit is None:
        return None
    n = normal(scene)
    a = r.uniform(0, 2 * math.pi)
    flat = g.unit(g.cross(n, [math.cos(a), 0, math.sin(a)]))
    distance, lift = r.uniform(0.05, 1.0), r.uniform(0.02, 0.5)
    camera = scene["camera"]
    camera["position"] = g.r3(g.add(hit, g.add(g.mul(flat, distance), g.mul(n, lift))))
    camera["target"] = g.r3(hit)
    view = g.unit(g.sub(camera["target"], camera["position"]))
    if abs(view[1]) > 0.95:
        camera["up"] = [1, 0, 0]
    else:
        camera.pop("up", None)
    camera["near"] = r.choice([0.01, 0.02])
    camera["fov_degrees"] = round(r.uniform(30, 80))
    return f"camera {distance:.2f} m from a shadow edge"
