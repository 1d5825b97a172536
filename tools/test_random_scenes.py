#!/usr/bin/env python3
"""Checks of random_scenes.py's --near-lights kind and its options (Python 3's standard library).

    python3 tools/test_random_scenes.py

Each test builds scenes as random_scenes.py does and asserts the property the kind or option
promises: the options change only the lights, the camera and the description (so an old seed's
receiver and casters are the same with them), a near light lies outside its caster and within
2.5 m of it along the direction it was placed in, a narrow cone's axis crosses a caster, a camera
behind the receiver is on its back side, --receivers' OBJ receivers are whole meshes and its
in-plane lights lie 0.05 to 3 degrees above the plane, mixed lights are of different types, a
camera near an edge is within a metre of its target on the receiver. World space in metres, y up.
"""
import copy
import json
import math
import os
import random
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import random_scenes  # noqa: E402
import scene_geometry as g  # noqa: E402
import scene_near  # noqa: E402
import scene_mixed  # noqa: E402
import scene_options  # noqa: E402
import scene_receivers  # noqa: E402

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "random_scenes.py")
SEEDS = range(17000, 17048)


def near(seed, out_dir):
    return scene_near.scene(seed, random.Random(seed), out_dir, random_scenes.caster, random_scenes.on_sphere)


def box_distance(light, obj):
    """Distance (m) from a world point to a box object, in the box's model frame (unturned)."""
    local = g.sub(light, obj["position"])
    ax, ay, az = obj.get("rotation_degrees", [0, 0, 0])
    # Undo z, then y, then x: the inverse of the loader's turn.
    local = g.rotate(local, [0, 0, -az])
    local = g.rotate(local, [0, -ay, 0])
    local = g.rotate(local, [-ax, 0, 0])
    half = [s / 2 for s in obj["mesh"]["size"]]
    outside = [max(abs(local[k]) - half[k], 0.0) for k in range(3)]
    return math.sqrt(g.dot(outside, outside))


def segment_to_line(a, b, origin, through):
    """Least distance (m) from the segment ab to the line from origin through `through`: the
    parts of a - origin and b - a across the line, the nearest point of their segment to 0."""
    d = g.unit(g.sub(through, origin))

    def across(v):
        return g.sub(v, g.mul(d, g.dot(v, d)))

    w, e = across(g.sub(a, origin)), across(g.sub(b, a))
    s = min(max(-g.dot(w, e) / g.dot(e, e), 0.0), 1.0) if g.dot(e, e) > 0 else 0.0
    p = g.add(w, g.mul(e, s))
    return math.sqrt(g.dot(p, p))


class NearLights(unittest.TestCase):
    def test_every_pairing_of_caster_and_receiver_in_24_seeds(self):
        with tempfile.TemporaryDirectory() as out:
            pairs = {near(seed, out)["description"].split(": ")[1].split(",")[0] for seed in range(17000, 17024)}
        self.assertEqual(len(pairs), len(scene_near.CASTERS) * len(scene_near.RECEIVERS), pairs)

    def test_light_outside_the_caster_and_close(self):
        with tempfile.TemporaryDirectory() as out:
            for seed in SEEDS:
                made = near(seed, out)
                big, light = made["objects"][1], made["lights"][0]["position"]
                shape = big["mesh"].get("shape")
                if shape == "box":
                    distance = box_distance(light, big)
                elif shape == "sphere":
                    offset = g.sub(light, big["position"])
                    distance = math.sqrt(g.dot(offset, offset)) - big["mesh"]["radius"]
                else:
                    continue
                self.assertGreater(distance, 0.19, f"seed {seed}: the light is inside or on '{big['name']}'")
                # Close: a floor's height can lift it, but never far past the caster's own size.
                reach = max(big["mesh"].get("size", [2 * big["mesh"].get("radius", 0)] * 3))
                self.assertLess(distance, 2.5 + reach, f"seed {seed}: the light is {distance:.2f} m away")


class Options(unittest.TestCase):
    KINDS = {"sunk": lambda seed, out: random_scenes.scene_sunk.scene(seed, random.Random(seed)),
             "grazing": lambda seed, out: random_scenes.scene(seed, True),
             "classes": lambda seed, out: random_scenes.scene_classes.scene(seed),
             "random": lambda seed, out: random_scenes.scene(seed, False),
             "near": near}

    def each(self, option):
        """(kind, seed, scene without the option, scene with it, what the option did) for 12
        seeds of each kind."""
        with tempfile.TemporaryDirectory() as out:
            for kind, make in self.KINDS.items():
                for seed in range(17000, 17012):
                    plain = make(seed, out)
                    made = copy.deepcopy(plain)
                    done = scene_options.apply(made, seed, [option], random_scenes.on_sphere,
                                               kind in ("sunk", "grazing"))
                    yield kind, seed, plain, made, done

    def test_options_keep_the_objects(self):
        for option in scene_options.NAMES:
            for kind, seed, plain, made, _ in self.each(option):
                self.assertEqual(plain["objects"], made["objects"], f"{option}, {kind} {seed}")
                self.assertEqual(plain["screen"], made["screen"], f"{option}, {kind} {seed}")

    def test_extra_lights_adds_one_to_three(self):
        for kind, seed, plain, made, _ in self.each("extra_lights"):
            added = len(made["lights"]) - len(plain["lights"])
            self.assertTrue(1 <= added <= 3 or len(made["lights"]) == 16, f"{kind} {seed}: {added}")
            self.assertLessEqual(sum(l.get("attenuation", {}).get("mode") == "exact" for l in made["lights"]), 1)

    def test_narrow_cone_crosses_a_caster(self):
        for kind, seed, plain, made, _ in self.each("narrow_cones"):
            light = g.shadow_lights(made)[0]
            self.assertTrue(2 <= light["cone_degrees"] <= 12, f"{kind} {seed}")
            axes = [g.farthest_pair(points) for points in g.caster_points(made)]
            # The axis passes through a point of some caster's longest axis (rounded to mm).
            miss = min(segment_to_line(a, b, light["position"], light["target"]) for a, b in axes)
            self.assertLess(miss, 0.02, f"{kind} {seed}: the cone's axis misses every caster by {miss:.3f} m")

    def test_camera_behind_is_under_the_receiver_or_just_over_it(self):
        kinds = set()
        for kind, seed, plain, made, done in self.each("camera_behind"):
            receiver, eye = made["objects"][0], made["camera"]["position"]
            surface = g.surface_height(receiver, eye[0], eye[2])
            amplitude = abs(receiver["mesh"].get("amplitude", 0))
            kinds.add(done[0])
            if done == ["camera behind the receiver"]:
                # Below the surface under it (a plate's plane, the dunes' lowest point, the mat).
                self.assertLess(eye[1], surface - 0.04, f"{kind} {seed}: {eye} under {surface:.3f}")
                if receiver["mesh"].get("shape") == "heightfield":
                    self.assertLess(eye[1], receiver.get("position", [0, 0, 0])[1] - amplitude, f"{kind} {seed}")
            else:
                self.assertEqual(done, ["camera along the receiver"])
                thick = receiver["mesh"]["size"][1] if receiver["mesh"].get("shape") == "box" else 0
                lift = eye[1] - surface
                self.assertTrue(0.015 < lift < 0.41 + thick + 2 * amplitude, f"{kind} {seed}: {lift:.3f} m up")
        self.assertEqual(kinds, {"camera behind the receiver", "camera along the receiver"})


def obj_faces(path):
    """(vertex count, faces as 1-based index lists) of an OBJ file."""
    vertices, faces = 0, []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices += 1
            elif line.startswith("f "):
                faces.append([int(word) for word in line.split()[1:]])
    return vertices, faces


class Receivers(unittest.TestCase):
    def test_every_kind_in_six_seeds_and_whole_meshes(self):
        with tempfile.TemporaryDirectory() as out:
            kinds = set()
            for seed in range(23000, 23012):
                made = scene_receivers.scene(seed, random.Random(seed), out)
                kinds.add(made["description"].split(": ")[1])
                for obj in made["objects"]:
                    if "obj" not in obj["mesh"]:
                        continue
                    count, faces = obj_faces(os.path.join(out, obj["mesh"]["obj"]))
                    self.assertGreater(len(faces), 0, f"{seed} {obj['name']}")
                    for face in faces:
                        self.assertEqual(len(face), 3)
                        self.assertTrue(all(1 <= i <= count for i in face), f"{seed} {obj['name']}: {face}")
        self.assertEqual(kinds, set(scene_receivers.KINDS))

    def test_in_plane_lights_are_nearly_in_the_receivers_plane(self):
        with tempfile.TemporaryDirectory() as out:
            for seed in range(23003, 23003 + 6 * 12, 6):
                made = scene_receivers.scene(seed, random.Random(seed), out)
                normal = scene_mixed.normal(made)
                for light in made["lights"]:
                    offset = g.unit(g.sub(light["position"], light["target"]))
                    # The target lies on the receiver: the angle above its plane, rounded to mm.
                    degrees = math.degrees(math.asin(g.dot(offset, normal)))
                    self.assertTrue(-0.1 < degrees < 3.1, f"{seed}: {degrees:.2f} degrees")


class MixedOptions(unittest.TestCase):
    def test_mixed_lights_adds_two_to_four_and_one_exact_at_most(self):
        for kind, seed, plain, made, done in Options().each("mixed_lights"):
            added = len(made["lights"]) - len(plain["lights"])
            self.assertTrue(2 <= added <= 4, f"{kind} {seed}: {added}")
            self.assertEqual(len(done[0].split(": ")[1].split(", ")), added, done)
            self.assertLessEqual(sum(l.get("attenuation", {}).get("mode") == "exact" for l in made["lights"]), 1)

    def test_camera_near_edge_is_close_to_a_point_on_the_receiver(self):
        moved, lit = 0, 0
        for kind, seed, plain, made, done in Options().each("camera_near_edge"):
            if not done:  # no ray past a caster meets the receiver: the camera stays
                self.assertEqual(plain["camera"], made["camera"], f"{kind} {seed}")
                continue
            moved += 1
            eye, target = made["camera"]["position"], made["camera"]["target"]
            lit += (any(scene_mixed.in_cone(light, target) for light in g.shadow_lights(made)) and
                    scene_mixed.on_receiver(made, target))
            gap = math.sqrt(g.dot(g.sub(eye, target), g.sub(eye, target)))
            self.assertTrue(0.02 < gap < 1.13, f"{kind} {seed}: {gap:.3f} m")
            on = g.surface_height(made["objects"][0], target[0], target[2])
            self.assertLess(abs(target[1] - on), 0.02, f"{kind} {seed}: {target} over {on:.3f}")
            self.assertLessEqual(made["camera"]["near"], 0.02)
        # Most seeds find an edge point, and most of those on the receiver within a light's cone.
        self.assertGreater(moved, 0.8 * 60, moved)
        self.assertGreater(lit, 0.75 * moved, (lit, moved))


class CommandLine(unittest.TestCase):
    def test_same_seed_same_files_and_options_in_the_name(self):
        with tempfile.TemporaryDirectory() as a, tempfile.TemporaryDirectory() as b:
            for out in (a, b):
                subprocess.run([sys.executable, SCRIPT, "--near-lights", "--count", "6", "--seed", "17000",
                                "--out", out], check=True, capture_output=True)
                subprocess.run([sys.executable, SCRIPT, "--sunk", "--extra-lights", "--narrow-cones",
                                "--count", "3", "--seed", "17000", "--out", out], check=True, capture_output=True)
            names = sorted(os.listdir(a))
            self.assertEqual(names, sorted(os.listdir(b)))
            self.assertIn("sunk-extra-lights-narrow-cones_17000.json", names)
            for name in names:
                with open(os.path.join(a, name), "rb") as f, open(os.path.join(b, name), "rb") as h:
                    self.assertEqual(f.read(), h.read(), name)
            with open(os.path.join(a, "sunk-extra-lights-narrow-cones_17000.json")) as f:
                self.assertIn("(extra lights, narrow cones)", json.load(f)["description"])

    def test_screen_changes_only_the_screen_and_names_the_file(self):
        with tempfile.TemporaryDirectory() as out:
            for extra in ([], ["--screen", "512x128"]):
                subprocess.run([sys.executable, SCRIPT, "--sunk", "--camera-behind", "--count", "2",
                                "--seed", "17000", "--out", out] + extra, check=True, capture_output=True)
            for seed in (17000, 17001):
                with open(os.path.join(out, f"sunk-camera-behind_{seed}.json")) as f:
                    plain = json.load(f)
                with open(os.path.join(out, f"sunk-camera-behind-screen512x128_{seed}.json")) as f:
                    made = json.load(f)
                self.assertEqual(made["screen"], {"width": 512, "height": 128})
                self.assertNotEqual(plain["screen"], made["screen"])
                self.assertTrue(made["description"].endswith(", screen 512x128)"), made["description"])
                for key in ("camera", "lights", "objects"):
                    self.assertEqual(plain[key], made[key], f"{seed}: {key}")
        for bad in ("512", "0x100", "100x3000", "axb"):
            run = subprocess.run([sys.executable, SCRIPT, "--screen", bad, "--out", "unused"],
                                 capture_output=True, text=True)
            self.assertNotEqual(run.returncode, 0, bad)
            self.assertIn("--screen", run.stderr, bad)


if __name__ == "__main__":
    unittest.main()
