"""Scenes of OBJ meshes unlike the built-in shapes, with random sizes, turns and flags.

Used by random_scenes.py --meshes, for an audit on geometry no scene of the project holds:
  torus      a closed surface with a hole (its shadow has one);
  prism      a concave polygon extruded (stairs, an L, an arch, a star): faces that shadow each
             other, and a silhouette that is not convex;
  bowl       an open hemisphere with no thickness, seen from inside and out;
  crumple    an open, bumpy sheet that shadows itself;
and any of them written unwelded (each triangle with its own three vertices) and with a few
zero-area triangles, as exporters leave them. The meshes are written as OBJ files next to the
scenes (counter-clockwise seen from outside, model space in metres, y up); the scenes turn them
about all three axes and scale them unevenly. World space in metres, y up.
"""
import math
import os

import scene_classes
from scene_classes import r3


def torus(r):
    """A ring of radius R about the y axis, tube radius t (model space, metres)."""
    big, tube = r.uniform(0.3, 0.8), r.uniform(0.06, 0.25)
    nu, nv = r.choice([12, 24, 36]), r.choice([8, 12, 16])
    vertices, faces = [], []
    for i in range(nu):
        u = 2 * math.pi * i / nu
        for j in range(nv):
            v = 2 * math.pi * j / nv
            ring = big + tube * math.cos(v)
            vertices.append((ring * math.cos(u), tube * math.sin(v), ring * math.sin(u)))
    for i in range(nu):
        for j in range(nv):
            a, b = i * nv + j, ((i + 1) % nu) * nv + j
            c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
            faces += [(a, d, c), (a, c, b)]
    return vertices, faces


def profile(r):
    """A simple concave polygon in the xy plane, counter-clockwise (metres)."""
    kind = r.choice(["stairs", "ell", "arch", "star"])
    if kind == "stairs":
        steps, run, rise = r.randint(2, 5), r.uniform(0.15, 0.4), r.uniform(0.1, 0.3)
        points = [(0.0, 0.0), (steps * run, 0.0)]
        for k in range(steps, 0, -1):
            points += [(k * run, k * rise), ((k - 1) * run, k * rise)]
        return points
    if kind == "ell":
        w, h, t = r.uniform(0.6, 1.5), r.uniform(0.6, 1.5), r.uniform(0.1, 0.4)
        return [(0, 0), (w, 0), (w, t), (t, t), (t, h), (0, h)]
    if kind == "arch":
        w, h, leg, top = r.uniform(0.8, 2), r.uniform(0.6, 1.6), r.uniform(0.1, 0.3), r.uniform(0.1, 0.3)
        return [(0, 0), (leg, 0), (leg, h - top), (w - leg, h - top), (w - leg, 0), (w, 0), (w, h), (0, h)]
    tips, outer, inner = r.randint(4, 7), r.uniform(0.4, 0.9), r.uniform(0.12, 0.3)
    return [((outer if k % 2 == 0 else inner) * math.cos(math.pi * k / tips),
             (outer if k % 2 == 0 else inner) * math.sin(math.pi * k / tips)) for k in range(2 * tips)]


def ear_clip(points):
    """Triangles (index triples, counter-clockwise) of a simple counter-clockwise polygon."""
    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    left, triangles = list(range(len(points))), []
    while len(left) > 3:
        for k in range(len(left)):
            i, j, m = left[k - 1], left[k], left[(k + 1) % len(left)]
            if cross(points[i], points[j], points[m]) <= 0:
                continue
            inside = any(cross(points[i], points[j], points[p]) >= 0 and
                         cross(points[j], points[m], points[p]) >= 0 and
                         cross(points[m], points[i], points[p]) >= 0
                         for p in left if p not in (i, j, m))
            if not inside:
                triangles.append((i, j, m))
                del left[k]
                break
        else:
            raise ValueError("ear_clip: the polygon is not simple and counter-clockwise")
    return triangles + [tuple(left)]


def prism(r):
    """The profile extruded along z by a random depth, closed at both ends."""
    points, depth = profile(r), r.uniform(0.2, 1.2)
    n = len(points)
    vertices = [(x, y, depth / 2) for x, y in points] + [(x, y, -depth / 2) for x, y in points]
    faces = [tuple(ear) for ear in ear_clip(points)]                       # front, +z
    faces += [(n + c, n + b, n + a) for a, b, c in ear_clip(points)]       # back, -z
    for k in range(n):
        nxt = (k + 1) % n
        faces += [(k, n + k, n + nxt), (k, n + nxt, nxt)]
    return vertices, faces


def bowl(r):
    """An open hemisphere below y = 0 with its rim at y = 0 (outward normals down and out)."""
    radius, slices, stacks = r.uniform(0.3, 0.8), r.choice([12, 20, 32]), r.choice([4, 6, 10])
    vertices = [(0.0, -radius, 0.0)]
    for s in range(1, stacks + 1):
        polar = math.pi / 2 * (1 - s / stacks)
        for k in range(slices):
            a = 2 * math.pi * k / slices
            vertices.append((radius * math.cos(polar) * math.cos(a), -radius * math.sin(polar),
                             radius * math.cos(polar) * math.sin(a)))
    faces = [(0, 1 + k, 1 + (k + 1) % slices) for k in range(slices)]
    for s in range(1, stacks):
        base, up = 1 + (s - 1) * slices, 1 + s * slices
        for k in range(slices):
            nxt = (k + 1) % slices
            faces += [(base + k, up + k, up + nxt), (base + k, up + nxt, base + nxt)]
    return vertices, faces


def crumple(r):
    """An open sheet with random bumps, facing +y (metres)."""
    size, n = r.uniform(0.8, 2.0), r.choice([4, 8, 12])
    bumps = [(r.uniform(-size / 2, size / 2), r.uniform(-size / 2, size / 2),
              r.uniform(-0.3, 0.3), r.uniform(0.1, 0.4)) for _ in range(3)]
    vertices = []
    for i in range(n + 1):
        for j in range(n + 1):
            x, z = size * (i / n - 0.5), size * (j / n - 0.5)
            y = sum(h * math.exp(-((x - bx) ** 2 + (z - bz) ** 2) / (w * w)) for bx, bz, h, w in bumps)
            vertices.append((x, y, z))
    faces = []
    for i in range(n):
        for j in range(n):
            a, b, c, d = i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1, i * (n + 1) + j + 1
            faces += [(a, d, c), (a, c, b)]
    return vertices, faces


def unweld(vertices, faces, r):
    """Each triangle with its own vertices, and a few zero-area triangles among them: an edge
    collapsed to a point (two corners at one position), as a decimating exporter leaves it."""
    loose, loose_faces = [], []
    for face in faces:
        loose_faces.append(tuple(len(loose) + k for k in range(3)))
        loose += [vertices[i] for i in face]
    for _ in range(r.randint(1, 4)):
        a, b = r.choice(faces)[:2]
        loose_faces.append((len(loose), len(loose) + 1, len(loose) + 2))
        loose += [vertices[a], vertices[b], vertices[b]]
    return loose, loose_faces


def write_obj(path, vertices, faces):
    with open(path, "w") as f:
        f.write("# tools/scene_meshes.py\n")
        for v in vertices:
            f.write("v %.5f %.5f %.5f\n" % v)
        for face in faces:
            f.write("f %d %d %d\n" % tuple(i + 1 for i in face))


def mesh_object(r, seed, index, out_dir, ground_height):
    kind = r.choice(["torus", "prism", "prism", "bowl", "crumple"])
    vertices, faces = {"torus": torus, "prism": prism, "bowl": bowl, "crumple": crumple}[kind](r)
    welded = r.random() < 0.6
    if not welded:
        vertices, faces = unweld(vertices, faces, r)
    name = f"{kind}{index}{'' if welded else '_loose'}"
    file_name = f"meshes_{seed:04d}_{name}.obj"
    write_obj(os.path.join(out_dir, file_name), vertices, faces)
    return {"name": name, "mesh": {"obj": file_name},
            "position": r3([r.uniform(-1.5, 1.5), ground_height + r.choice([0.0, r.uniform(0.1, 1.2)]),
                            r.uniform(-1.5, 1.5)]),
            "rotation_degrees": [round(r.uniform(-90, 90)), round(r.uniform(-180, 180)),
                                 round(r.uniform(-90, 90))],
            "scale": r3([r.uniform(0.6, 1.8) for _ in range(3)]),
            "casts_shadow": r.random() < 0.9, "receives_shadow": r.random() < 0.8}


def scene(seed, out_dir, r):
    """One scene: a ground, one to three OBJ meshes over it, one or two spotlights."""
    ground_objects, height = scene_classes.ground(r)
    objects = ground_objects + [mesh_object(r, seed, k, out_dir, height) for k in range(r.randint(1, 3))]
    centre = [0, height, 0]
    lights = [scene_classes.light(scene_classes.polar(r, centre, r.choice([(3, 12), (10, 80), (10, 80)]), (1.2, 8)),
                                  r3([r.uniform(-1, 1), height, r.uniform(-1, 1)]),
                                  r.uniform(30, 140), r.choice([128, 256, 256, 512]))
              for _ in range(r.choice([1, 1, 1, 2]))]
    eye = scene_classes.camera(scene_classes.polar(r, centre, (8, 60), (3, 9)), [0, height + 0.4, 0],
                               round(r.uniform(35, 70)))
    width = r.choice([160, 240, 320])
    return {"description": f"tools/random_scenes.py --meshes, seed {seed}",
            "screen": {"width": width, "height": width * 3 // 4},
            "camera": eye, "lights": lights, "objects": objects}
