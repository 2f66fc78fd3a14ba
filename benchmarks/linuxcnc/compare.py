#!/usr/bin/python3
"""Prints the comparison table of harness summaries (run.sh), one column
each: compare.py LABEL=summary.json[,tpopt_report.json] ...

With a tpopt report (tpopt smooth/evaluate --report), the column also shows
tpopt's predicted time of the program it wrote (or read): on the planner
(planner_time_s, model/machine/planner_time.h) and at the feeds alone
(machining_time_s).
Exit 1 when a run did not complete."""
import json
import sys


def predicted_time(report, key):
    for side in ("output", "input"):
        if isinstance(report.get(side), dict) and key in report[side]:
            return report[side][key]
    return report.get(key)


def rows_of(summary, report):
    j = summary.get("joints", {})

    def g(axis, where, quantity, stat):
        return j.get(axis, {}).get(where, {}).get(quantity, {}).get(stat)

    rows = [("completed", "yes" if summary.get("completed") else "NO: " + summary.get("error", "")),
            ("cycle time, s", summary.get("cycle_time_s"))]
    if report is not None:
        rows.append(("tpopt predicted time on the planner, s",
                     predicted_time(report, "planner_time_s")))
        rows.append(("tpopt predicted time at the feeds, s",
                     predicted_time(report, "machining_time_s")))
    rows.append(("stops in cuts", summary.get("stops_in_cuts")))
    for quantity, unit in (("acceleration", "deg/s^2"), ("jerk", "deg/s^3")):
        for axis in ("A", "C"):
            for stat in ("peak", "p99"):
                rows.append(("%s %s %s in cuts, %s" % (stat, axis, quantity, unit),
                             g(axis, "cuts", quantity, stat)))
    for axis in ("X", "Y", "Z"):
        rows.append(("peak %s acceleration (cuts / rapids), mm/s^2" % axis,
                     "%.0f / %.0f" % (g(axis, "cuts", "acceleration", "peak") or 0,
                                       g(axis, "rapids", "acceleration", "peak") or 0)))
    excess = summary.get("limit_excess", [])
    rows.append(("joint limits exceeded",
                 ", ".join("%s %s %.4g>%g (%s, line %d)" % (e["joint"], e["quantity"][:5],
                                                           abs(e["value"]), abs(e["limit"]),
                                                           e["in"], e["program_line"])
                           for e in excess) or "none"))
    return rows


def fmt(v):
    if v is None:
        return "-"
    if isinstance(v, float):
        return "%.1f" % v if abs(v) < 1000 else "{:,.0f}".format(v)
    return str(v)


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    labels, columns, ok = [], [], True
    for arg in argv[1:]:
        label, _, files = arg.partition("=")
        summary_file, _, report_file = files.partition(",")
        with open(summary_file) as f:
            summary = json.load(f)
        report = None
        if report_file:
            with open(report_file) as f:
                report = json.load(f)
        ok = ok and bool(summary.get("completed"))
        labels.append(label)
        columns.append(rows_of(summary, report))
    names = []
    for col in columns:
        for name, _ in col:
            if name not in names:
                names.append(name)
    print("| | " + " | ".join(labels) + " |")
    print("|---|" + "---|" * len(labels))
    for name in names:
        cells = [fmt(dict(col).get(name)) for col in columns]
        print("| " + name + " | " + " | ".join(cells) + " |")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
