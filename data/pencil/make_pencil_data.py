#!/usr/bin/env python3
"""Writes the pencil-path example of seed 004 (pure Python, no packages).

surface_120x120x55.json: a bicubic B-spline surface over 120 x 120 mm whose
heights span 55 mm (the seed's Table 1 is not in the text we have, so the
control net is ours: a free-form dome with a saddle and a tilt). Control
points sit at the Greville abscissae in x and y, so x = 120 u and y = 120 v
exactly (linear precision); only z is free-form.

flower_guides.json: a five-petal flower (r = 14 + 2 cos 5t, whose dips keep a radius of curvature above 3.8 mm: the dips of r = 12 + 5 cos 5t, of 0.4 mm, would be corners at 0.4 mm steps; as a closed
clamped cubic B-spline whose control points are points of that curve) and
an S stroke, placed over the middle of the surface, 30 mm up, turned 20
degrees about the normal.
"""
import json
import math

SIZE = 120.0
HEIGHT = 55.0
KNOTS = [0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1]
N = len(KNOTS) - 4


def greville(i):
    return sum(KNOTS[i + 1:i + 4]) / 3.0


def shape(x, y):
    a, b = x / SIZE, y / SIZE
    return (math.sin(math.pi * a) * math.sin(math.pi * b) + 0.35 * (a - 0.5) * (b - 0.5) * 4
            + 0.3 * a)


def basis(i, p, u):
    """Cox-de Boor, with the last basis function closed at u = 1."""
    if p == 0:
        if KNOTS[i] <= u < KNOTS[i + 1] or (u == 1.0 and KNOTS[i] < 1.0 == KNOTS[i + 1]):
            return 1.0
        return 0.0
    out = 0.0
    if KNOTS[i + p] > KNOTS[i]:
        out += (u - KNOTS[i]) / (KNOTS[i + p] - KNOTS[i]) * basis(i, p - 1, u)
    if KNOTS[i + p + 1] > KNOTS[i + 1]:
        out += (KNOTS[i + p + 1] - u) / (KNOTS[i + p + 1] - KNOTS[i + 1]) * basis(i + 1, p - 1, u)
    return out


def surface():
    raw = [[shape(SIZE * greville(i), SIZE * greville(j)) for j in range(N)] for i in range(N)]
    samples = []
    for a in range(61):
        nu = [basis(i, 3, a / 60) for i in range(N)]
        for b in range(61):
            nv = [basis(j, 3, b / 60) for j in range(N)]
            samples.append(sum(nu[i] * nv[j] * raw[i][j] for i in range(N) for j in range(N)))
    lo, hi = min(samples), max(samples)
    scale = HEIGHT / (hi - lo)
    net = [[[round(SIZE * greville(i), 9), round(SIZE * greville(j), 9),
             round((raw[i][j] - lo) * scale, 9)] for j in range(N)] for i in range(N)]
    return {"name": "pencil_120x120x55", "units": "mm", "kind": "bspline_surface",
            "note": "Bicubic free-form surface, 120 x 120 mm, heights spanning 55 mm "
                    "(sampled on a 61 x 61 grid); x = 120 u, y = 120 v. Made by "
                    "make_pencil_data.py.",
            "degree_u": 3, "degree_v": 3, "knots_u": KNOTS, "knots_v": KNOTS,
            "control_points": net}


def clamped_uniform_knots(count):
    spans = count - 3
    return [0.0] * 4 + [k / spans for k in range(1, spans)] + [1.0] * 4


def flower():
    points = []
    count = 61
    for k in range(count):
        t = 2 * math.pi * k / (count - 1)
        r = 14 + 2 * math.cos(5 * t)
        points.append([round(r * math.cos(t), 6), round(r * math.sin(t), 6)])
    return {"degree": 3, "knots": clamped_uniform_knots(count), "control_points": points}


def s_stroke():
    points = [[28, 14], [22, 20], [16, 16], [18, 8], [26, 4], [28, -4], [22, -10], [14, -6]]
    return {"degree": 3, "knots": clamped_uniform_knots(len(points)), "control_points": points}


def guides():
    return {"name": "flower_and_s", "units": "mm", "kind": "planar_curves",
            "note": "A five-petal flower and an S stroke (the seed engraves a plum blossom and "
                    "characters). Made by make_pencil_data.py.",
            "placement": {"anchor_uv": [0.5, 0.5], "lift_mm": 30, "spin_deg": 20},
            "curves": [flower(), s_stroke()]}


if __name__ == "__main__":
    with open("surface_120x120x55.json", "w") as f:
        json.dump(surface(), f, indent=1)
        f.write("\n")
    with open("flower_guides.json", "w") as f:
        json.dump(guides(), f, indent=1)
        f.write("\n")
