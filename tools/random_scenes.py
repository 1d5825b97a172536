#!/usr/bin/env python3
"""Random scene files for an audit on geometry the project has never seen.

Each scene has one receiver (a plane, a heightfield, the ring, or a floor with a floating wall),
one to three casters (boxes, spheres, cylinders open or capped, fighters) at random places,
turns and flags, one spotlight and one camera. With --classes, each scene is instead one of
issue #14's hard classes with random sizes, angles and distances (scene_classes.py): a light
close behind a wide caster, a long bar across a narrow cone, flags, a tilted plate under an
oblique light, a light facing the camera, two lights. With --meshes, each scene holds OBJ meshes
unlike the built-in shapes (tori, concave prisms, open bowls, crumpled sheets, some unwelded
with zero-area triangles; scene_meshes.py), written beside the scenes. With --sunk, casters lie
through dunes, the ring or a tilted plate under a light 1 to 20 degrees above it (scene_sunk.py).
With --lights, one to three spotlights of every beam shape, cone and attenuation, sometimes with a
slide projector, over the same receivers and casters (scene_lights.py). With --near-lights, a
spotlight stands 0.2 to 2.5 m behind a large caster (a wall, a crate, a sphere, a roof slab, a
mesh or a tilted panel, 3 to 8 m wide) over a floor often narrower than it, dunes, the ring or a
tilted plate (scene_near.py). With --receivers, the receiver is thin or far from flat (terraces,
sagging ropes, steep dunes, a crumpled sheet, plates stacked and pierced by poles) or lit from
0.05 to 3 degrees above its plane (scene_receivers.py). Options for every kind (scene_options.py; the same seed without
them writes the same file as before they existed): --extra-lights adds one to three spotlights
and beam maps, --narrow-cones aims cones of 2 to 12 degrees obliquely across the longest
caster, --camera-behind puts the camera behind the receiver or along it, under the casters,
--mixed-lights adds lights of two to four different types, --camera-near-edge puts the camera
a few centimetres from a shadow edge (scene_mixed.py).
Run them through every technique against the ray-cast truth with

    tools/random_scenes.py --count 60 --seed 100 --grazing --out /tmp/audit
    build/bench/hard_case_sweeps files /tmp/audit/*.json

(a `*` marks a technique that reported success with more than 0.1% interior error). The same
seed writes the same files. Python 3's standard library only.
"""
import argparse
import json
import math
import os
import random
import sys

import scene_classes
import scene_lights
import scene_meshes
import scene_near
import scene_options
import scene_receivers
import scene_sunk


def rounded(values, digits=3):
    return [round(v, digits) for v in values]


def receiver(r):
    """The receiver objects (world space, metres) and the height casters stand on."""
    kind = r.choice(["plane", "plane", "heightfield", "ring", "wall"])
    if kind == "plane":
        return 0.0, [{"name": "floor", "mesh": {"shape": "plane", "size": r.choice([6, 10, 20]),
                                                "divisions": r.choice([1, 4, 10])},
                      "casts_shadow": False, "receives_shadow": True}]
    if kind == "heightfield":
        return 0.0, [{"name": "dunes", "mesh": {"shape": "heightfield", "size": 10, "divisions": 32,
                                                "amplitude": round(r.uniform(0.05, 0.6), 2),
                                                "wavelength": round(r.uniform(1.5, 6), 2)},
                      "casts_shadow": r.random() < 0.5, "receives_shadow": True}]
    if kind == "ring":
        return 1.0, [{"name": "ring", "mesh": {"shape": "ring"},
                      "casts_shadow": r.random() < 0.3, "receives_shadow": True}]
    # A wall floating 5 cm above a floor: a slit under it, seen by a low light.
    return 0.0, [{"name": "floor", "mesh": {"shape": "plane", "size": 12, "divisions": 2},
                  "casts_shadow": False, "receives_shadow": True},
                 {"name": "wall", "mesh": {"shape": "box", "size": [0.3, round(r.uniform(1, 3), 2), 6]},
                  "position": [round(r.uniform(-3, -1.5), 2), 0.9, 0],
                  "casts_shadow": True, "receives_shadow": True}]


def caster(r, index, ground):
    shape = r.choice(["box", "sphere", "cylinder", "fighter", "box"])
    meshes = {
        "box": lambda: {"shape": "box", "size": rounded([r.uniform(0.2, 1.6) for _ in range(3)])},
        "sphere": lambda: {"shape": "sphere", "radius": round(r.uniform(0.15, 0.8), 2)},
        "cylinder": lambda: {"shape": "cylinder", "radius": round(r.uniform(0.05, 0.4), 2),
                             "length": round(r.uniform(0.5, 3), 2), "caps": r.random() < 0.8},
        "fighter": lambda: {"shape": "fighter",
                            "pose": r.choice(["guard", "punch", "kick", "step", "hit"]),
                            "phase": round(r.random(), 2), "body_color": [0.2, 0.3, 0.7]},
    }
    mesh = meshes[shape]()
    standing = shape == "fighter"
    lift = 0.0 if standing else r.choice([0.0, 0.0, r.uniform(0.05, 1.5)]) + 0.3
    return {"name": f"{shape}{index}", "mesh": mesh,
            "position": [round(r.uniform(-1.5, 1.5), 2), round(ground + lift, 2),
                         round(r.uniform(-1.5, 1.5), 2)],
            "rotation_degrees": [0 if standing else round(r.uniform(-60, 60)),
                                 round(r.uniform(-180, 180)),
                                 0 if standing else round(r.uniform(-60, 60))],
            "casts_shadow": True, "receives_shadow": r.random() < 0.8}


def on_sphere(r, ground, elevation_degrees, distance):
    """A point at a random azimuth, the given elevation and distance from (0, ground, 0)."""
    elevation = math.radians(r.uniform(*elevation_degrees))
    azimuth = r.uniform(0, 2 * math.pi)
    d = r.uniform(*distance)
    return rounded([d * math.cos(elevation) * math.cos(azimuth), ground + d * math.sin(elevation),
                    d * math.cos(elevation) * math.sin(azimuth)])


def scene(seed, grazing):
    r = random.Random(seed)
    ground, objects = receiver(r)
    objects += [caster(r, i, ground) for i in range(r.randint(1, 3))]
    # Grazing: a low light near the casters and a low camera, where texels stretch most.
    light_elevation, light_distance = ((2, 25), (0.8, 5)) if grazing else ((8, 85), (1.5, 12))
    camera_elevation = (3, 40) if grazing else (10, 70)
    light = {"position": on_sphere(r, ground, light_elevation, light_distance),
             "target": [round(r.uniform(-1, 1), 2), ground, round(r.uniform(-1, 1), 2)],
             "cone_degrees": round(r.uniform(20, 150), 1),
             "shadow_size": r.choice([64, 128, 256, 256, 512])}
    camera = {"position": on_sphere(r, ground, camera_elevation, (3, 12)),
              "target": [0, ground + 0.5, 0], "fov_degrees": round(r.uniform(35, 75)),
              "near": 0.1, "far": 100}
    width = r.choice([160, 240, 320])
    return {"description": f"tools/random_scenes.py, seed {seed}" + (", grazing" if grazing else ""),
            "screen": {"width": width, "height": width * 3 // 4},
            "camera": camera, "lights": [light], "objects": objects}


def parse_screen(parser, text):
    """--screen's WxH as (width, height) in pixels, each within the scene loader's 1 to 2048."""
    parts = text.lower().split("x")
    if len(parts) != 2 or not all(p.isdigit() for p in parts) or not all(1 <= int(p) <= 2048 for p in parts):
        parser.error(f"--screen {text}: give WIDTHxHEIGHT, each 1 to 2048 pixels")
    return int(parts[0]), int(parts[1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--count", type=int, default=40, help="how many scenes (default 40)")
    parser.add_argument("--seed", type=int, default=0, help="the first scene's seed; one more each")
    parser.add_argument("--grazing", action="store_true",
                        help="low lights near the casters and low cameras (texels stretch most)")
    parser.add_argument("--classes", action="store_true",
                        help="issue #14's hard classes with random parameters (scene_classes.py)")
    parser.add_argument("--meshes", action="store_true",
                        help="OBJ meshes unlike the built-in shapes (scene_meshes.py)")
    parser.add_argument("--sunk", action="store_true",
                        help="casters lying through a receiver that is not flat, under a low light "
                             "(scene_sunk.py)")
    parser.add_argument("--lights", action="store_true",
                        help="one to three spotlights of every beam shape, cone and attenuation, "
                             "sometimes a slide projector (scene_lights.py)")
    parser.add_argument("--near-lights", action="store_true",
                        help="a spotlight close behind a large caster of every shape, over a floor "
                             "narrower than it, dunes, the ring or a tilted plate (scene_near.py)")
    parser.add_argument("--receivers", action="store_true",
                        help="receivers thin or far from flat (terraces, ropes, steep dunes, a "
                             "crumpled sheet, stacked pierced plates) or lit from nearly in their "
                             "plane (scene_receivers.py)")
    parser.add_argument("--extra-lights", action="store_true",
                        help="option for every kind: one to three more spotlights, and beam maps on "
                             "the scene's own, as --lights has them (scene_options.py)")
    parser.add_argument("--narrow-cones", action="store_true",
                        help="option for every kind: cones of 2 to 12 degrees aimed obliquely "
                             "across the longest caster (scene_options.py)")
    parser.add_argument("--camera-behind", action="store_true",
                        help="option for every kind: the camera behind the receiver, looking at "
                             "its back side, or along it under the casters (scene_options.py)")
    parser.add_argument("--mixed-lights", action="store_true",
                        help="option for every kind: two to four more lights of different types "
                             "(slide, exact attenuation, in the receiver's plane, narrow, wide, "
                             "32 texels, faint; scene_mixed.py)")
    parser.add_argument("--camera-near-edge", action="store_true",
                        help="option for every kind: the camera 5 cm to 1 m from a point of a "
                             "shadow edge on the receiver (scene_mixed.py)")
    parser.add_argument("--screen", metavar="WxH",
                        help="option for every kind: this screen (pixels, 1 to 2048 a side, any "
                             "aspect) instead of the kind's own 4:3 one of 160 to 400 wide")
    parser.add_argument("--out", required=True, help="directory to write SEED.json files into")
    args = parser.parse_args()
    if args.count < 1:
        parser.error("--count must be at least 1")
    screen = parse_screen(parser, args.screen) if args.screen else None
    os.makedirs(args.out, exist_ok=True)
    if args.classes + args.grazing + args.meshes + args.sunk + args.lights + args.near_lights + args.receivers > 1:
        parser.error("--classes, --grazing, --meshes, --sunk, --lights, --near-lights and "
                     "--receivers are separate kinds of scene; give one")
    prefix = ("classes" if args.classes else "grazing" if args.grazing else
              "meshes" if args.meshes else "sunk" if args.sunk else
              "lights" if args.lights else "near" if args.near_lights else
              "receivers" if args.receivers else "random")
    options = [name for name in scene_options.NAMES if getattr(args, name)]
    # Options name the file too (sunk-extra-lights_17200.json), beside the same seed without them.
    prefix = "-".join([prefix] + [name.replace("_", "-") for name in options] +
                      ([f"screen{screen[0]}x{screen[1]}"] if screen else []))
    for seed in range(args.seed, args.seed + args.count):
        path = os.path.join(args.out, f"{prefix}_{seed:04d}.json")
        if args.near_lights:
            made = scene_near.scene(seed, random.Random(seed), args.out, caster, on_sphere)
        elif args.classes:
            made = scene_classes.scene(seed)
        elif args.meshes:
            made = scene_meshes.scene(seed, args.out, random.Random(seed))
        elif args.sunk:
            made = scene_sunk.scene(seed, random.Random(seed))
        elif args.receivers:
            made = scene_receivers.scene(seed, random.Random(seed), args.out)
        elif args.lights:
            made = scene_lights.scene(seed, random.Random(seed), receiver, caster, on_sphere)
        else:
            made = scene(seed, args.grazing)
        done = scene_options.apply(made, seed, options, on_sphere, low=args.grazing or args.sunk)
        if screen:
            # After the kind and the options: no random number is drawn for it, so the scene is
            # the seed's own but for its screen (the camera's fov stays vertical, the aspect follows).
            made["screen"] = {"width": screen[0], "height": screen[1]}
            done.append(f"screen {screen[0]}x{screen[1]}")
        if done:
            made["description"] += " (" + ", ".join(done) + ")"
        with open(path, "w") as f:
            json.dump(made, f, indent=1)
            f.write("\n")
    print(f"{args.count} scenes in {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
