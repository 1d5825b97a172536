"""Lights of every shape over random casters, as scene files.

Used by random_scenes.py --lights. Issue #14 asks for shadows only where the light shines, for
every technique and light shape; the other kinds of scene have only the smooth cone. Each scene
here has random_scenes.py's receivers and casters under one to three spotlights, each with a beam
map (round, square, gobo, lens) or none, a cone from 10 to 170 degrees aimed off the casters as
often as at them, a shadow strength and colour of its own, attenuation per vertex or (one light
with a beam) per pixel, and sometimes a slide projector beside them (it lights, casts nothing).
World space in metres, y up.
"""

BEAMS = ["round", "square", "gobo", "lens"]
SLIDES = ["checker", "rings", "grid"]


def r3(values):
    return [round(v, 3) for v in values]


def attenuation(r, exact_allowed):
    """A light's attenuation: per vertex, per pixel (needs a beam, one light a scene), or none."""
    mode = r.choice(["none", "vertex", "exact"] if exact_allowed else ["none", "vertex"])
    if mode == "none":
        return None
    return {"mode": mode, "constant": 1, "linear": round(r.uniform(0, 0.3), 3),
            "quadratic": round(r.uniform(0, 0.05), 3)}


def spotlight(r, ground, on_sphere, exact_allowed):
    position = on_sphere(r, ground, (10, 85), (1.5, 10))
    # Half the lights aim away from the casters' middle, so the beam's edge crosses them.
    spread = 1.0 if r.random() < 0.5 else 3.5
    light = {"position": position,
             "target": r3([r.uniform(-spread, spread), ground, r.uniform(-spread, spread)]),
             "cone_degrees": round(r.choice([r.uniform(10, 40), r.uniform(30, 100), r.uniform(90, 170)]), 1),
             "color": r3([r.uniform(0.5, 1) for _ in range(3)]),
             "shadow_strength": round(r.uniform(0.3, 1), 2),
             "shadow_size": r.choice([64, 128, 256, 512])}
    if r.random() < 0.75:
        light["beam"] = r.choice(BEAMS)
    made = attenuation(r, exact_allowed and "beam" in light)
    if made is not None:
        light["attenuation"] = made
    return light


def scene(seed, r, receiver, caster, on_sphere):
    """One scene from random_scenes.py's receiver and caster builders and its on_sphere."""
    ground, objects = receiver(r)
    objects += [caster(r, i, ground) for i in range(r.randint(1, 3))]
    lights = []
    for _ in range(r.randint(1, 3)):
        exact_allowed = not any(l.get("attenuation", {}).get("mode") == "exact" for l in lights)
        lights.append(spotlight(r, ground, on_sphere, exact_allowed))
    if r.random() < 0.3:
        lights.append({"position": on_sphere(r, ground, (30, 80), (3, 8)),
                       "target": r3([r.uniform(-1, 1), ground, r.uniform(-1, 1)]),
                       "cone_degrees": round(r.uniform(30, 70), 1), "slide": r.choice(SLIDES)})
    camera = {"position": on_sphere(r, ground, (10, 70), (3, 12)),
              "target": [0, ground + 0.5, 0], "fov_degrees": round(r.uniform(35, 75)),
              "near": 0.1, "far": 100}
    width = r.choice([160, 240, 320])
    return {"description": f"tools/random_scenes.py --lights, seed {seed}",
            "screen": {"width": width, "height": width * 3 // 4},
            "camera": camera, "lights": lights, "objects": objects}
