#!/usr/bin/env bash
# Runs programs one after another on the simulated controller (run.sh) and
# prints the comparison table (compare.py).
# Usage: compare.sh OUT_DIR LABEL=PROGRAM.ngc[,TPOPT_REPORT.json] ...
# e.g.   compare.sh cnc original=blade.ngc smoothed=blade_smooth.ngc,report.json
# Each run goes to OUT_DIR/LABEL/ (trajectory.tsv, summary.json, linuxcnc.log).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
if [ $# -lt 2 ]; then
  echo "usage: $0 OUT_DIR LABEL=PROGRAM.ngc[,TPOPT_REPORT.json] ..." >&2
  exit 2
fi
out_dir="$1"
shift
columns=()
status=0
for arg in "$@"; do
  label="${arg%%=*}"
  files="${arg#*=}"
  program="${files%%,*}"
  report=""
  [ "$files" != "$program" ] && report=",${files#*,}"
  echo "running $label: $program" >&2
  "$here/run.sh" "$program" "$out_dir/$label" || status=$?
  [ -s "$out_dir/$label/summary.json" ] || { echo "$0: $label gave no summary" >&2; exit 1; }
  columns+=("$label=$out_dir/$label/summary.json$report")
done
/usr/bin/python3 "$here/compare.py" "${columns[@]}" || status=1
exit "$status"
