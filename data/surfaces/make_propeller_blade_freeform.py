#!/usr/bin/env python3
"""Writes propeller_blade_freeform.json: a bicubic B-spline blade surface.

u runs along the span (x, 0..120 mm), v across the chord (60 mm). Each
chordwise section is a parabola of depth `camber(x)` (concave towards the
cutter on +z for depth > 0), rotated about the span by a pitch twist that
grows linearly from 10 to 40 deg. The depth changes abruptly between
x = 52 and x = 64 mm, from 3 mm (concave, radius about 150 mm) to -2.5 mm
(convex, about 180 mm): the "abrupt curvature change" of the seed's test
blade. Control points are the shape sampled at the Greville abscissae (the
spline is the surface by definition; it follows the sampled shape closely
where the knots are dense, which they are around the transition).
"""
import json
import math

SPAN, HALF_CHORD = 120.0, 30.0


def camber(x):
    t = min(max((x - 52.0) / 12.0, 0.0), 1.0)
    smooth = t * t * (3 - 2 * t)
    return 3.0 + (-2.5 - 3.0) * smooth


def point(x, c):
    twist = math.radians(10.0 + 30.0 * x / SPAN)
    zc = camber(x) * (c / HALF_CHORD) ** 2
    return [x, c * math.cos(twist) - zc * math.sin(twist),
            c * math.sin(twist) + zc * math.cos(twist)]


def clamped(interior):
    return [0.0] * 4 + interior + [1.0] * 4


def greville(knots, count):
    return [sum(knots[i + 1:i + 4]) / 3.0 for i in range(count)]


def main():
    interior_u = [0.1, 0.2, 0.3, 0.38, 0.42, 0.46, 0.5, 0.54, 0.58, 0.62, 0.7, 0.8, 0.9]
    interior_v = [0.25, 0.5, 0.75]
    knots_u, knots_v = clamped(interior_u), clamped(interior_v)
    nu, nv = len(knots_u) - 4, len(knots_v) - 4
    gu, gv = greville(knots_u, nu), greville(knots_v, nv)
    net = [[[round(w, 6) for w in point(SPAN * a, HALF_CHORD * (2 * b - 1))] for b in gv]
           for a in gu]
    surface = {
        "name": "propeller_blade_freeform",
        "units": "mm",
        "kind": "bspline_surface",
        "note": "Written by make_propeller_blade_freeform.py: twisted blade whose chordwise "
                "camber turns from concave to convex between x = 52 and 64 mm.",
        "cutter_side": "positive",
        "degree_u": 3,
        "degree_v": 3,
        "knots_u": knots_u,
        "knots_v": knots_v,
        "control_points": net,
    }
    with open("propeller_blade_freeform.json", "w") as out:
        json.dump(surface, out, indent=1)
        out.write("\n")


if __name__ == "__main__":
    main()
