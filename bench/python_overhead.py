#!/usr/bin/env python3
"""Overhead of the Python path against `finseg run` on the paper's four conditions
(examples/zigzag/): prints a Markdown table for BENCHMARKS.md.

    PYTHONPATH=build/release/python python3 bench/python_overhead.py build/release/finseg [REPEATS]

For each condition, the median over REPEATS (default 5) of the wall time of
  cli       `finseg run SCENE --out DIR --quiet` as a process (start, read, run, write all),
  py+out    finseg.load(SCENE).run(out=DIR) in this interpreter (the same files written),
  py        finseg.load(SCENE).run() (nothing written, no animation frames kept),
and each run's own summary wall_time_s (scene read to end of run, in-process).
"""

import glob
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import finseg


def median_wall(fn, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main():
    cli = sys.argv[1]
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    scenes = sorted(glob.glob("examples/zigzag/condition*.yaml"))
    print("| condition | cli s | py+out s | py s | py+out - cli s | py / cli |")
    print("| --- | --- | --- | --- | --- | --- |")
    with tempfile.TemporaryDirectory() as tmp:
        for scene in scenes:
            name = os.path.basename(scene)[:-5]
            out_cli, out_py = os.path.join(tmp, "cli"), os.path.join(tmp, "py")
            run_cli = lambda: subprocess.run(  # noqa: E731
                [cli, "run", scene, "--out", out_cli, "--quiet"], check=True
            )
            t_cli = median_wall(run_cli, repeats)
            t_py_out = median_wall(lambda: finseg.load(scene).run(out=out_py), repeats)
            t_py = median_wall(lambda: finseg.load(scene).run(), repeats)
            cli_inner = json.load(open(os.path.join(out_cli, "summary.json")))["wall_time_s"]
            py_inner = json.load(open(os.path.join(out_py, "summary.json")))["wall_time_s"]
            print(
                f"| {name} | {t_cli:.3f} | {t_py_out:.3f} | {t_py:.3f} | "
                f"{t_py_out - t_cli:+.3f} | {t_py / t_cli:.2f} |"
                f" <!-- in-process wall_time_s: cli {cli_inner:.3f}, py {py_inner:.3f} -->"
            )


if __name__ == "__main__":
    main()
