#!/usr/bin/env python3
"""Issue 11 item 7 as one command: the example cone (`finseg gen cone --top open --base open
--fold-to-gathered 0.9`, 12 pleats, 6 axial folds) at n x n segments a face, folded and then
pull-deployed on one thread as a user runs it (outputs on unless --outputs-off). Prints a
Markdown table per phase (and the fold's coarse stage): segments, steps, Newton iterations,
factorizations, contact at the end, the shape probe's RMS distance from the deployed cone, CPU
(user + sys of the finseg process; the coarse stage is inside the fold's), wall time and peak
memory, the BLAS kernels, and the total against the 10-minute target (BENCHMARKS.md, "The cone
gathered by folding").

Usage: python3 bench/bench_cone.py [BUILD_DIR] [--subdivisions N] [--outputs-off] [--keep DIR]
(default build/release, N = 8: 11 200 segments, about 10-15 minutes on a 2-core VM).
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

TARGET_S = 600.0


def run_phase(cmd, cwd, log):
    """Runs cmd in cwd (output to log); returns (cpu_s, wall_s, peak_rss_bytes)."""
    t0 = time.monotonic()
    with open(log, "w") as out:
        proc = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - t0
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        sys.exit(f"bench_cone: {' '.join(cmd)} exited with {code}; see {log}")
    return usage.ru_utime + usage.ru_stime, wall, usage.ru_maxrss * 1024


def counts(segments, dofs, st):
    """The table's count cells of one solve's stats (summary.json "stats" or a stage's)."""
    return (f"{segments} | {dofs} | {st['steps']} ({st['rejected_steps']}) "
            f"| {st['newton_iterations']} | {st['linear_solves']['factorizations']}")


def summary_rows(name, summary_file, cpu, wall, rss):
    """Rows of a run: its stages before (the fold on a coarse cut) and the run itself."""
    s = json.loads(Path(summary_file).read_text())
    m = s["model"]
    rows = [f"| {name}: {st['what']} | {counts(st['segments'], '-', st['stats'])} | - | - "
            f"| - | {st['wall_time_s']:.1f} | - |" for st in s.get("stages", [])]
    contact = s.get("probes", {}).get("contact", {}).get("final", {})
    pairs = contact.get("touching_pairs")
    points = contact.get("active_points")
    touching = "-" if pairs is None else f"{pairs:.0f} pairs, {points:.0f} points"
    # The shape probe (gen cone writes one): RMS distance from the deployed cone, mm.
    shape = s.get("probes", {}).get("shape", {}).get("final", {}).get("rms_distance_m")
    rms = "-" if shape is None else f"{1e3 * shape:.1f} mm"
    rows.append(f"| {name} | {counts(m['bodies'], m['dofs'], s['stats'])} | {touching} "
                f"| {rms} | {cpu:.1f} | {wall:.1f} | {rss / 1e9:.2f} GB |")
    return rows, s["provenance"].get("blas_kernels", "")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("build", nargs="?", default="build/release")
    p.add_argument("--subdivisions", type=int, default=8)
    p.add_argument("--outputs-off", action="store_true", help="no VTK, HTML or plots")
    p.add_argument("--keep", help="work in this folder and keep it (default: a temporary one)")
    a = p.parse_args()
    finseg = str(Path(a.build, "finseg").resolve())
    work = Path(a.keep) if a.keep else Path(tempfile.mkdtemp(prefix="bench_cone_"))
    work.mkdir(parents=True, exist_ok=True)
    sets = []
    if a.outputs_off:
        for k in ("vtk", "html", "plot"):
            sets += ["--set", f"outputs.{k}=false"]
    subprocess.run(
        [finseg, "gen", "cone", "--top", "open", "--base", "open", "--subdivisions",
         str(a.subdivisions), "--fold-to-gathered", "0.9", "--out", "cone.yaml"],
        cwd=work, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    fold = run_phase([finseg, "run", "cone.yaml", "--fold", "--out", "folded", "--threads", "1",
                      "--quiet"] + sets, work, work / "fold.log")
    deploy = run_phase([finseg, "run", "cone.yaml", "--state", "folded/checkpoint.json",
                        "--out", "deploy", "--threads", "1", "--quiet"] + sets,
                       work, work / "deploy.log")
    print("| phase | segments | DOFs | steps (rejected) | Newton iterations | factorizations "
          "| contact at the end | from the deployed cone (RMS) | CPU (s) | wall (s) | peak RSS |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    rows, _ = summary_rows("fold", work / "folded" / "summary.json", *fold)
    print("\n".join(rows))
    rows, kernels = summary_rows("deploy", work / "deploy" / "summary.json", *deploy)
    print("\n".join(rows))
    total = fold[0] + deploy[0]
    verdict = "under" if total <= TARGET_S else "over"
    print(f"\nCPU in all: {total:.1f} s, {abs(total / TARGET_S - 1) * 100:.0f} % {verdict} the "
          f"10 minutes; outputs {'off' if a.outputs_off else 'on'}; BLAS kernels: "
          f"{kernels or 'not OpenBLAS'}; work folder: {work if a.keep else '(removed)'}")
    if not a.keep:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
