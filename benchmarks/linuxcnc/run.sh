#!/usr/bin/env bash
# Runs one G-code program on LinuxCNC's simulated xyzac-trt machine (motion
# controller and trajectory planner, headless) and writes into OUT_DIR:
#   trajectory.tsv  one row per servo period (1 ms) while the program runs:
#                   t_s X Y Z A C current_vel requested_vel line motion_type
#   summary.json    cycle time, peaks and 99th percentiles per joint over
#                   cuts and rapids, stops inside cutting runs, limit excess
#   linuxcnc.log    LinuxCNC's console
# Usage: run.sh PROGRAM.ngc OUT_DIR
# Exit: 0 ran to completion, 1 the controller failed the program, 2 usage,
# 4 LinuxCNC is not installed.
# LinuxCNC refuses to run as root, so as root the stack runs as the user
# $TPOPT_CNC_USER (default tpoptcnc, created when missing) in a scratch copy
# of the config that user owns; OUT_DIR is written by the calling user.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
sample="${TPOPT_CNC_SAMPLE_CONFIG:-/usr/share/doc/linuxcnc/examples/sample-configs/sim/axis/vismach/5axis/table-rotary-tilting}"
if [ $# -ne 2 ]; then
  echo "usage: $0 PROGRAM.ngc OUT_DIR" >&2
  exit 2
fi
program="$1"
out_dir="$2"
if [ ! -r "$program" ]; then
  echo "$0: cannot read program $program" >&2
  exit 2
fi
if ! command -v linuxcnc > /dev/null || ! /usr/bin/python3 -c 'import linuxcnc' 2> /dev/null \
    || [ ! -d "$sample/remap_subs" ]; then
  echo "$0: LinuxCNC (linuxcnc-uspace with its sample configs) is not installed" >&2
  exit 4
fi
mkdir -p "$out_dir"
out_dir="$(cd "$out_dir" && pwd)"

# One LinuxCNC at a time on a machine: its shared memory is global.
exec 9> /tmp/tpopt-linuxcnc.lock
flock 9

# HAL's shared memory is machine-wide too. `rs274 -i` of an INI with
# HAL_PIN_VARS run as root leaves its segments behind (owner root, mode 0600,
# nothing attached), and then no other user's LinuxCNC can start: remove
# such leftovers, and wait while a live HAL has them attached.
hal_segments() { ipcs -m | awk '$1 == "0x48484c34" || $1 == "0x48414c32" {print $2, $6}'; }
for attempt in $(seq 1 60); do
  live=0
  while read -r id attached; do
    if [ "$attached" = 0 ]; then ipcrm -m "$id" 2> /dev/null || true; else live=1; fi
  done < <(hal_segments)
  [ "$live" = 0 ] && break
  [ "$attempt" = 1 ] && echo "$0: waiting for another HAL (LinuxCNC) instance to end" >&2
  sleep 5
done
if [ -n "$(hal_segments)" ]; then
  echo "$0: HAL shared memory is in use or cannot be removed (ipcs -m: keys 0x48484c34," \
    "0x48414c32); end that LinuxCNC or remove the segments as their owner" >&2
  exit 1
fi

scratch="$(mktemp -d /tmp/tpopt-cnc.XXXXXX)"
[ -n "${TPOPT_CNC_KEEP:-}" ] || trap 'rm -rf "$scratch"' EXIT
cp "$here/xyzac-trt.ini" "$here/sampler.hal" "$here/display.py" "$scratch/"
cp -r "$sample/remap_subs" "$sample/xyzac-trt.tbl" "$scratch/"
cp "$program" "$scratch/program.ngc"
chmod -R a+rX "$scratch"

run_as=()
if [ "$(id -u)" -eq 0 ]; then
  user="${TPOPT_CNC_USER:-tpoptcnc}"
  if ! id "$user" > /dev/null 2>&1; then
    useradd --create-home --shell /bin/bash "$user"
  fi
  chown -R "$user" "$scratch"
  run_as=(runuser -u "$user" --)
fi

# script gives LinuxCNC a terminal, so that its log comes to linuxcnc.log
# rather than to /tmp/linuxcnc.*.
status=0
cd "$scratch"
timeout "${TPOPT_CNC_TIMEOUT_S:-1800}" script -qfec \
  "${run_as[*]} env TPOPT_CNC_PROGRAM=$scratch/program.ngc TPOPT_CNC_SAMPLES=$scratch/samples.txt TPOPT_CNC_STATUS=$scratch/status.json linuxcnc $scratch/xyzac-trt.ini" \
  "$scratch/linuxcnc.log" > /dev/null 2>&1 < /dev/null || status=$?
cp "$scratch/linuxcnc.log" "$out_dir/linuxcnc.log"
if [ ! -s "$scratch/status.json" ]; then
  echo "$0: LinuxCNC ended (exit $status) without a verdict; see $out_dir/linuxcnc.log" >&2
  exit 1
fi
if ! /usr/bin/python3 "$here/analyze.py" --ini="$scratch/xyzac-trt.ini" --program="$program" \
    --status="$scratch/status.json" --samples="$scratch/samples.txt" \
    --trajectory="$out_dir/trajectory.tsv" --summary="$out_dir/summary.json"; then
  echo "$0: $program did not run to completion; see $out_dir/summary.json and linuxcnc.log" >&2
  exit 1
fi
