"""Options that change any kind of random scene after it is made, for random_scenes.py.

Each takes the finished scene and a random generator of its own (seeded from the scene's seed
and the option's name), so a seed without options writes the same file as before the options
existed, and with an option the same receiver and casters as without it:
  extra_lights   one to three more spotlights, and beam maps, colours and shadow strengths on
                 the scene's own, as --lights has them (over --sunk and --grazing, half of the
                 new lights are as low as the scene's own: 1 to 20 degrees above the receiver);
  narrow_cones   the first light (and each other spotlight with odds 1 in 2) gets a cone of 2 to
                 12 degrees aimed across the longest caster, from 15 to 50 degrees above the
                 receiver if it stood higher (issue 14's class 2: the shadow stops where the light
                 stops);
  camera_behind  the camera behind the receiver, looking at its back side from 5 cm to 4 m
                 away, or a few centimetres above it, looking along it through the gaps under
                 the casters;
  mixed_lights   two to four more lights, each of another type: a slide projector, a beam with
                 exact attenuation, a light 0.05 to 3 degrees above the receiver's plane, a 2 to
                 12 degree cone across a caster, a 160 to 179 degree cone close over the
                 casters, a 32-texel shadow map, a faint coloured shadow;
  camera_near_edge  the camera 5 cm to 1 m from a point of a caster's shadow edge on the
                 receiver (the ray from a light through the caster's outermost point across it),
                 2 to 50 cm over the surface, its near plane at 1 to 2 cm.
The receiver is the scene's first object (every kind of scene puts it first), the casters the
other objects that cast. World space in metres, y up.
"""
import math
import random

import scene_geometry as g
import scene_lights
import scene_mixed

# New options go at the end: the order names the files and applies them.
NAMES = ["extra_lights", "narrow_cones", "camera_behind", "mixed_lights", "camera_near_edge"]


def generator(seed, name):
    """The option's own random generator (a string seed is hashed the same on every run)."""
    return random.Random(f"random_scenes {name} {seed}")


def low_light(r, ground):
    """A spotlight 1 to 20 degrees above the receiver, 1.5 to 8 m from its middle (world)."""
    position = g.add([0, ground + 0.2, 0], g.mul(g.direction(r.uniform(1, 20), r.uniform(0, 2 * math.pi)),
                                                r.uniform(1.5, 8)))
    return {"position": g.r3(position), "target": g.r3([r.uniform(-1, 1), ground, r.uniform(-1, 1)]),
            "cone_degrees": round(r.uniform(30, 120), 1), "shadow_size": r.choice([64, 128, 256, 512])}


def extra_lights(scene, r, on_sphere, low):
    ground = g.ground_height(scene)
    lights = scene["lights"]
    for light in g.shadow_lights(scene):
        if "beam" not in light and r.random() < 0.5:
            light["beam"] = r.choice(scene_lights.BEAMS)
            light["color"] = g.r3([r.uniform(0.5, 1) for _ in range(3)])
            light["shadow_strength"] = round(r.uniform(0.3, 1), 2)
    for _ in range(r.randint(1, 3)):
        if len(lights) >= 16:
            break
        if low and r.random() < 0.5:
            light = low_light(r, ground)
            if r.random() < 0.75:
                light["beam"] = r.choice(scene_lights.BEAMS)
        else:
            exact_allowed = not any(l.get("attenuation", {}).get("mode") == "exact" for l in lights)
            light = scene_lights.spotlight(r, ground, on_sphere, exact_allowed)
        lights.append(light)
    return "extra lights"


def length(points):
    a, b = g.farthest_pair(points)
    return math.sqrt(g.dot(g.sub(a, b), g.sub(a, b)))


def narrow_cones(scene, r):
    casters = g.caster_points(scene)
    if not casters:
        return None
    ground = g.ground_height(scene)
    longest = max(casters, key=length)
    for k, light in enumerate(g.shadow_lights(scene)):
        if k == 0 or r.random() < 0.5:
            points = longest if r.random() < 0.7 else r.choice(casters)
            g.aim_across(r, light, points, ground)
    return "narrow cones"


def camera_behind(scene, r):
    """Moves the camera behind the receiver (its back side) or along it, under the casters."""
    receiver = scene["objects"][0]
    camera = scene["camera"]
    centre = [r.uniform(-1, 1), 0, r.uniform(-1, 1)]
    centre[1] = g.surface_height(receiver, centre[0], centre[2])
    normal = g.receiver_normal(receiver) if receiver["mesh"].get("shape") in ("plane", "box") else [0, 1, 0]
    # A frame on the receiver: two directions along it, the normal out of its lit side.
    along = g.unit(g.cross(normal, [0, 0, 1] if abs(normal[2]) < 0.9 else [1, 0, 0]))
    across = g.cross(normal, along)
    azimuth = r.uniform(0, 2 * math.pi)
    flat = g.add(g.mul(along, math.cos(azimuth)), g.mul(across, math.sin(azimuth)))
    # How far below `centre` the receiver's back lies: a box plate's thickness, or down to the
    # dunes' lowest point.
    shape = receiver["mesh"].get("shape")
    amplitude = abs(receiver["mesh"].get("amplitude", 0))
    depth = (receiver["mesh"]["size"][1] if shape == "box" else
             centre[1] - receiver.get("position", [0, 0, 0])[1] + amplitude if shape == "heightfield" else 0)
    if shape == "ring" or r.random() < 0.6:
        # Behind: below the receiver's back, looking up through it at 10 to 75 degrees.
        behind = r.choice([r.uniform(0.05, 0.4), r.uniform(0.4, 4)])
        rise = math.radians(r.uniform(10, 75))
        position = g.add(centre, g.add(g.mul(normal, -(depth + behind)),
                                       g.mul(flat, -behind / math.tan(rise))))
        target = g.add(centre, g.mul(normal, r.uniform(0, 1.5)))
        kind = "camera behind the receiver"
    else:
        # Along: a few centimetres over the surface, looking across it under the casters.
        distance = r.uniform(3, 9)
        x, z = centre[0] - flat[0] * distance, centre[2] - flat[2] * distance
        lift = (receiver["mesh"]["size"][1] if shape == "box" else 2 * amplitude) + r.uniform(0.02, 0.4)
        position = [x, g.surface_height(receiver, x, z) + lift, z]
        target = g.add(centre, g.mul(normal, lift * r.uniform(0.5, 1.5)))
        kind = "camera along the receiver"
    camera["position"], camera["target"] = g.r3(position), g.r3(target)
    view = g.unit(g.sub(camera["target"], camera["position"]))
    if abs(view[1]) > 0.95:
        camera["up"] = [1, 0, 0]
    camera["near"] = r.choice([0.02, 0.05, 0.1])
    camera["fov_degrees"] = round(r.uniform(40, 80))
    return kind


def apply(scene, seed, names, on_sphere, low):
    """Applies the named options in NAMES order; returns what each did, for the description."""
    done = []
    for name in NAMES:
        if name not in names:
            continue
        r = generator(seed, name)
        if name == "extra_lights":
            did = extra_lights(scene, r, on_sphere, low)
        elif name == "narrow_cones":
            did = narrow_cones(scene, r)
        elif name == "camera_behind":
            did = camera_behind(scene, r)
        elif name == "mixed_lights":
            did = scene_mixed.mixed_lights(scene, r, on_sphere)
        else:
            did = scene_mixed.camera_near_edge(scene, r)
        if did:
            done.append(did)
    return done
