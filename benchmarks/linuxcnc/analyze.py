#!/usr/bin/python3
"""Turns halsampler's record of one program run (sampler.hal) into the
trajectory table and the summary JSON of the harness (run.sh).

Derivatives are finite differences at the servo period (1 ms): velocity
(q[i+1] - q[i]) / dt, acceleration (q[i+1] - 2 q[i] + q[i-1]) / dt^2, jerk
the third difference / dt^3. halsampler prints 6 decimals, so rounding
alone can add up to 4e-6 / dt^3 = 4,000 units/s^3 to a jerk sample (and
2e-6 / dt^2 = 2 units/s^2 to an acceleration sample).

A sample belongs to the cuts when motion.motion-type is 2 (feed) or 3
(arc), to the rapids when it is 1. A cutting run is a maximal stretch of
cut samples; a stop is a stretch inside a run (touching neither of its
ends, where the planner starts from or comes to rest anyway) where
motion.current-vel is below 5% of motion.requested-vel, the programmed
feed of the move.
"""
import argparse
import configparser
import json
import os
import sys

import numpy as np

JOINTS = ["X", "Y", "Z", "A", "C"]
STOP_FRACTION = 0.05


def read_ini(path):
    ini = configparser.ConfigParser(strict=False, interpolation=None, inline_comment_prefixes=("#",))
    ini.optionxform = str
    with open(path) as f:
        ini.read_string(f.read())
    period_s = float(ini.get("EMCMOT", "SERVO_PERIOD", fallback="1000000")) * 1e-9
    limits = []
    for j in range(len(JOINTS)):
        sec = "JOINT_%d" % j
        limits.append({key: float(ini.get(sec, name)) for key, name in
                       (("min", "MIN_LIMIT"), ("max", "MAX_LIMIT"),
                        ("max_velocity", "MAX_VELOCITY"),
                        ("max_acceleration", "MAX_ACCELERATION"))})
    return period_s, limits


def runs_of(mask):
    """(start, end) index pairs, end exclusive, of the True stretches."""
    padded = np.concatenate(([False], mask, [False]))
    edges = np.flatnonzero(padded[1:] != padded[:-1])
    return list(zip(edges[0::2], edges[1::2]))


def stats(values):
    if values.size == 0:
        return {"peak": 0.0, "p99": 0.0}
    mag = np.abs(values)
    return {"peak": float(mag.max()), "p99": float(np.percentile(mag, 99))}


def summarize(samples, period_s, limits):
    q = samples[:, 0:5]
    vel = samples[:, 5]
    req = samples[:, 6]
    line = samples[:, 7].astype(int)
    kind = samples[:, 8].astype(int)
    n = len(samples)
    cut = (kind == 2) | (kind == 3)
    rapid = kind == 1
    dt = period_s
    # Derivative k is centred on samples [lo, lo + len): v on i (forward),
    # a on i, j on i (q[i-1] .. q[i+2]).
    d = {
        "velocity": (np.diff(q, 1, axis=0) / dt, 0),
        "acceleration": (np.diff(q, 2, axis=0) / dt**2, 1),
        "jerk": (np.diff(q, 3, axis=0) / dt**3, 1),
    }
    joints = {}
    excess = []
    for j, name in enumerate(JOINTS):
        entry = {}
        for label, mask in (("cuts", cut), ("rapids", rapid)):
            entry[label] = {}
            for quantity, (values, lo) in d.items():
                m = mask[lo:lo + len(values)]
                entry[label][quantity] = stats(values[m, j])
        joints[name] = entry
        lim = limits[j]
        # Excess beyond what the 6-decimal rounding can make.
        checks = [("position", q[:, j], 0, lim["min"], lim["max"], 1e-6)]
        for quantity, key, tol in (("velocity", "max_velocity", 1e-6 / dt),
                                   ("acceleration", "max_acceleration", 2e-6 / dt**2)):
            values, lo = d[quantity]
            checks.append((quantity, values[:, j], lo, -lim[key], lim[key], tol))
        for quantity, values, lo, low, high, tol in checks:
            over = np.maximum(values - high, low - values)
            bad = over > tol
            if not bad.any():
                continue
            worst = int(np.argmax(over))
            excess.append({
                "joint": name, "quantity": quantity, "limit": float(high if values[worst] > 0 else low),
                "value": float(values[worst]), "excess": float(over[worst]),
                "samples_over": int(bad.sum()), "t_s": (worst + lo) * dt,
                "program_line": int(line[worst + lo]),
                "in": "cut" if cut[worst + lo] else ("rapid" if rapid[worst + lo] else "other"),
            })
    stops = []
    runs = runs_of(cut)
    for start, end in runs:
        slow = (vel[start:end] < STOP_FRACTION * req[start:end]) & (req[start:end] > 0)
        for s, e in runs_of(slow):
            if s == 0 or e == end - start:
                continue
            stops.append({"t_s": (start + s) * dt, "duration_s": (e - s) * dt,
                          "program_line": int(line[start + s])})
    return {
        "cycle_time_s": n * dt,
        "samples": n,
        "servo_period_s": dt,
        "cut_time_s": float(cut.sum()) * dt,
        "rapid_time_s": float(rapid.sum()) * dt,
        "cutting_runs": len(runs),
        "stops_in_cuts": len(stops),
        "stops": stops,
        "joints": joints,
        "limit_excess": excess,
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--ini", required=True)
    p.add_argument("--program", required=True)
    p.add_argument("--status", required=True)
    p.add_argument("--samples", required=True)
    p.add_argument("--trajectory", required=True)
    p.add_argument("--summary", required=True)
    a = p.parse_args()
    with open(a.status) as f:
        status = json.load(f)
    period_s, limits = read_ini(a.ini)
    summary = {"program": os.path.abspath(a.program), "completed": bool(status["ok"]),
               "error": status["error"], "wall_s": status["wall_s"]}
    samples = np.zeros((0, 9))
    if os.path.exists(a.samples) and os.path.getsize(a.samples) > 0:
        samples = np.loadtxt(a.samples, ndmin=2)
    if samples.shape[0] < 4:
        summary["completed"] = False
        summary["error"] = summary["error"] or "fewer than 4 samples recorded"
    else:
        summary.update(summarize(samples, period_s, limits))
        t = np.arange(samples.shape[0]) * period_s
        table = np.column_stack((t, samples))
        tmp = a.trajectory + ".tmp"
        np.savetxt(tmp, table, fmt=["%.3f"] + ["%.6f"] * 7 + ["%d", "%d"], delimiter="\t",
                   header="t_s\tX\tY\tZ\tA\tC\tcurrent_vel\trequested_vel\tline\tmotion_type",
                   comments="")
        os.replace(tmp, a.trajectory)
    tmp = a.summary + ".tmp"
    with open(tmp, "w") as f:
        json.dump(summary, f, indent=1)
    os.replace(tmp, a.summary)
    return 0 if summary["completed"] else 1


if __name__ == "__main__":
    sys.exit(main())
