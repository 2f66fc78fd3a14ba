#!/usr/bin/python3
"""The DISPLAY program of the headless harness (LinuxCNC runs it as
`display.py -ini FILE` and shuts down when it exits).

Resets estop, switches the machine on, homes, opens the program named by
TPOPT_CNC_PROGRAM, starts halsampler into TPOPT_CNC_SAMPLES, runs the
program and waits until the interpreter is idle and the motion queue empty.
Writes TPOPT_CNC_STATUS as JSON: {"ok": bool, "error": str, "wall_s": s}.
An RCS_ERROR state or an operator error message is a failure.
"""
import json
import os
import signal
import subprocess
import sys
import time

import linuxcnc

TIMEOUT_S = float(os.environ.get("TPOPT_CNC_TIMEOUT_S", "1800"))


def wait_for(predicate, stat, timeout_s, what):
    deadline = time.time() + timeout_s
    while time.time() < deadline:
        stat.poll()
        if predicate(stat):
            return
        time.sleep(0.02)
    raise RuntimeError("timed out waiting for " + what)


def check_errors(err_channel, stat):
    message = err_channel.poll()
    if message:
        kind, text = message
        if kind in (linuxcnc.NML_ERROR, linuxcnc.OPERATOR_ERROR):
            raise RuntimeError("LinuxCNC error: " + text)
        print("linuxcnc message:", text, flush=True)
    if stat.state == linuxcnc.RCS_ERROR:
        raise RuntimeError("RCS_ERROR at program line %d" % stat.motion_line)


def run(program, samples_file):
    stat = linuxcnc.stat()
    cmd = linuxcnc.command()
    err = linuxcnc.error_channel()
    # Task may take a moment to answer.
    deadline = time.time() + 30
    while True:
        try:
            stat.poll()
            break
        except linuxcnc.error:
            if time.time() > deadline:
                raise
            time.sleep(0.1)
    cmd.state(linuxcnc.STATE_ESTOP_RESET)
    cmd.state(linuxcnc.STATE_ON)
    wait_for(lambda s: s.task_state == linuxcnc.STATE_ON, stat, 10, "machine on")
    cmd.mode(linuxcnc.MODE_MANUAL)
    cmd.wait_complete()
    cmd.teleop_enable(0)
    cmd.home(-1)
    wait_for(lambda s: all(s.homed[i] for i in range(s.joints)), stat, 30, "homing")
    cmd.mode(linuxcnc.MODE_AUTO)
    cmd.wait_complete()
    cmd.program_open(program)
    cmd.wait_complete()
    check_errors(err, stat)
    # halsampler reads the sampler's FIFO (gated by halui.program.is-running)
    # until it is stopped.
    with open(samples_file, "w") as out:
        sampler = subprocess.Popen(["halsampler", "-c", "0"], stdout=out)
        try:
            time.sleep(0.2)
            start = time.time()
            cmd.auto(linuxcnc.AUTO_RUN, 0)
            wait_for(lambda s: s.interp_state != linuxcnc.INTERP_IDLE, stat, 10,
                     "the program to start")
            while True:
                if time.time() - start > TIMEOUT_S:
                    raise RuntimeError("program still running after %g s" % TIMEOUT_S)
                stat.poll()
                check_errors(err, stat)
                if stat.interp_state == linuxcnc.INTERP_IDLE and stat.queue == 0:
                    break
                time.sleep(0.05)
            wall_s = time.time() - start
            # Let halsampler drain the FIFO.
            time.sleep(0.5)
        finally:
            sampler.send_signal(signal.SIGINT)
            try:
                sampler.wait(timeout=5)
            except subprocess.TimeoutExpired:
                sampler.kill()
    check_errors(err, stat)
    return wall_s


def main():
    status_file = os.environ["TPOPT_CNC_STATUS"]
    result = {"ok": False, "error": "", "wall_s": 0.0}
    try:
        result["wall_s"] = run(os.environ["TPOPT_CNC_PROGRAM"], os.environ["TPOPT_CNC_SAMPLES"])
        result["ok"] = True
    except Exception as e:  # any failure ends the run and is reported
        result["error"] = str(e)
        print("display.py:", e, file=sys.stderr, flush=True)
    with open(status_file + ".tmp", "w") as f:
        json.dump(result, f)
    os.replace(status_file + ".tmp", status_file)
    return 0 if result["ok"] else 1


if __name__ == "__main__":
    sys.exit(main())
