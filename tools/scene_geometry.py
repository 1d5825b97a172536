"""Vector helpers and where the scene files' objects lie, for the scene generators.

Shared by scene_near.py, scene_options.py and scene_mixed.py: the transform of
docs/scene_format.md (scale, then rotate about x, then y, then z, then translate), a few points
on each built-in shape in world space (enough to find a caster's extent along a direction and
its longest axis), the height of a receiver's surface above a point of the xz plane, and what a
scene's options read of it (its ground, lights that cast shadows, casters' points) and the
narrow cone they aim across a caster. World space in metres, y up.
"""
import math


def add(a, b):
    return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def mul(a, s):
    return [a[0] * s, a[1] * s, a[2] * s]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    length = math.sqrt(dot(a, a))
    return mul(a, 1.0 / length)


def r3(values):
    return [round(v, 3) for v in values]


def rotate(p, degrees):
    """p turned about x, then y, then z by `degrees` (right-handed), as the scene loader does."""
    ax, ay, az = (math.radians(d) for d in degrees)
    x, y, z = p
    y, z = y * math.cos(ax) - z * math.sin(ax), y * math.sin(ax) + z * math.cos(ax)
    x, z = x * math.cos(ay) + z * math.sin(ay), -x * math.sin(ay) + z * math.cos(ay)
    x, y = x * math.cos(az) - y * math.sin(az), x * math.sin(az) + y * math.cos(az)
    return [x, y, z]


def direction(elevation_degrees, azimuth_radians):
    """A unit world direction at the given elevation above the xz plane and azimuth about y."""
    e = math.radians(elevation_degrees)
    return [math.cos(e) * math.cos(azimuth_radians), math.sin(e), math.cos(e) * math.sin(azimuth_radians)]


def to_world(obj, model_points):
    """Model-space points of an object placed by its scale, rotation and position (world)."""
    scale = obj.get("scale", 1)
    scale = [scale] * 3 if not isinstance(scale, list) else scale
    turn = obj.get("rotation_degrees", [0, 0, 0])
    position = obj.get("position", [0, 0, 0])
    return [add(rotate([p[0] * scale[0], p[1] * scale[1], p[2] * scale[2]], turn), position)
            for p in model_points]


def model_points(mesh):
    """Model-space points that bound a built-in shape (box corners, a sphere's six poles, a
    cylinder's rim, a fighter's feet-to-head column), or None for an OBJ mesh or the ring."""
    shape = mesh.get("shape")
    if shape == "box":
        w, h, d = (s / 2 for s in mesh.get("size", [1, 1, 1]))
        return [[sx * w, sy * h, sz * d] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    if shape == "sphere":
        # Every direction is within 15 degrees of one of these, so on a sphere 1/cos 15 degrees
        # larger they reach at least the radius along any direction (extent_along).
        r = mesh.get("radius", 0.5) / math.cos(math.radians(15))
        return [mul(direction(e, math.radians(a)), r) for e in range(-90, 91, 15) for a in range(0, 360, 15)]
    if shape == "cylinder":
        # The rims as octagons whose sides touch the circle: they bound the round cylinder.
        r, length = mesh.get("radius", 0.5) / math.cos(math.pi / 8), mesh.get("length", 1)
        return [[r * math.cos(a), y, r * math.sin(a)] for y in (0, length)
                for a in (k * math.pi / 4 for k in range(8))]
    if shape == "fighter":
        return [[0, 0, 0], [0, 1.8, 0], [0.4, 0.9, 0], [-0.4, 0.9, 0]]
    if shape in ("plane", "heightfield"):
        s = mesh.get("size", 10) / 2
        a = abs(mesh.get("amplitude", 0))
        return [[sx * s, sy * a, sz * s] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    return None


def world_points(obj, obj_vertices=None):
    """World-space points bounding one scene object; `obj_vertices` are an OBJ mesh's own
    (model space). An OBJ mesh without them, or the ring, gives its position alone."""
    points = obj_vertices if obj_vertices is not None else model_points(obj["mesh"])
    if points is None:
        return [list(obj.get("position", [0, 0, 0]))]
    return to_world(obj, points)


def extent_along(points, centre, u):
    """How far the points reach from `centre` along the unit direction u (metres)."""
    return max(dot(sub(p, centre), u) for p in points)


def farthest_pair(points):
    """The two points furthest apart (a caster's longest axis, end to end)."""
    best, pair = -1.0, (points[0], points[0])
    for i, a in enumerate(points):
        for b in points[i + 1:]:
            d = dot(sub(a, b), sub(a, b))
            if d > best:
                best, pair = d, (a, b)
    return pair


def receiver_normal(obj):
    """The world direction a plane-like receiver faces (+y turned by its rotation)."""
    return unit(rotate([0, 1, 0], obj.get("rotation_degrees", [0, 0, 0])))


def surface_height(obj, x, z):
    """The receiver's surface height (world y, metres) above the point (x, z): a plane or box
    plate through its position (turned), the dunes' height function, the ring's mat at 1 m; an
    OBJ mesh's is taken as the horizontal plane through its position."""
    mesh = obj["mesh"]
    shape = mesh.get("shape")
    position = obj.get("position", [0, 0, 0])
    if "obj" in mesh:
        return position[1]
    if shape == "heightfield":
        a, l = mesh.get("amplitude", 0.2), mesh.get("wavelength", 4)
        return position[1] + a * math.sin(2 * math.pi * x / l) * math.cos(2 * math.pi * z / l)
    if shape == "ring":
        return 1.0
    n = receiver_normal(obj)
    top = mesh["size"][1] / 2 if shape == "box" else 0.0
    # The plane through the top face: n . (p - (position + n top)) = 0, solved for y.
    origin = add(position, mul(n, top))
    return origin[1] - (n[0] * (x - origin[0]) + n[2] * (z - origin[2])) / n[1]


def ground_height(scene):
    return 1.0 if scene["objects"][0]["mesh"].get("shape") == "ring" else 0.0


def shadow_lights(scene):
    return [light for light in scene["lights"] if "slide" not in light]


def caster_points(scene):
    """Each caster's world points (a box's corners, a cylinder's rims, ...; an OBJ mesh's
    position alone)."""
    return [world_points(obj) for obj in scene["objects"][1:] if obj.get("casts_shadow", True)]


def aim_across(r, light, points, ground):
    """A narrow cone from `light` through a point of the caster's longest axis to the ground."""
    a, b = farthest_pair(points)
    through = add(a, mul(sub(b, a), r.uniform(0.2, 0.8)))
    offset = sub(light["position"], through)
    horizontal = math.hypot(offset[0], offset[2])
    if math.degrees(math.atan2(offset[1], max(horizontal, 1e-6))) > 50:
        # Oblique: the same distance and azimuth, 15 to 50 degrees above the point.
        azimuth = math.atan2(offset[2], offset[0]) if horizontal > 1e-6 else r.uniform(0, 2 * math.pi)
        distance = math.sqrt(dot(offset, offset))
        light["position"] = r3(add(through, mul(direction(r.uniform(15, 50), azimuth), distance)))
    position = light["position"]
    target = through
    if position[1] > through[1] + 1e-3:
        # Where the ray from the light through the caster meets the ground's height, unless far.
        t = (position[1] - ground) / (position[1] - through[1])
        hit = add(position, mul(sub(through, position), t))
        if math.hypot(hit[0], hit[2]) < 12:
            target = hit
    light["target"] = r3(target)
    light["cone_degrees"] = round(r.uniform(2, 12), 1)
