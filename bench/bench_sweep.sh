#!/usr/bin/env bash
# Wall times of a 64-case sweep of a small scene run serially, with --jobs 2 and with
# `mpirun -n 2`, and of a two-parameter fit (BENCHMARKS.md, "Sweeps and fits").
# Usage: bench/bench_sweep.sh [BUILD_DIR]   (default build/release); prints Markdown rows.
set -euo pipefail
build=$(cd "${1:-build/release}" && pwd)
finseg="$build/finseg"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# The small strip of tests/test_fit.cpp: 6 panels of 2 segments, no contact, 20 pull steps.
"$finseg" gen zigzag --segments-per-panel 2 \
  --no-contact --pull-step 1e-3 --pull-travel 0.02 --crease-stiffness 2.7e-3 \
  --bending-rigidity 4e-4 --out z.yaml > /dev/null
echo "outputs: {vtk: false, html: false, plot: false}" >> z.yaml
cat > s.yaml <<'YAML'
scene: z.yaml
parameters:
  - {path: zigzag.crease_laws.2.stiffness, from: 1.0e-3, to: 8.0e-3, steps: 8}
  - {path: stiffness.bending_rigidity, from: 1.0e-4, to: 8.0e-4, steps: 8}
outputs: [probes.gauge.peak_force_N, stats.newton_iterations]
YAML

seconds() {  # wall seconds of a command
  local t0 t1
  t0=$(date +%s.%N)
  "$@" > /dev/null 2>&1 || [ $? -eq 3 ]
  t1=$(date +%s.%N)
  echo "$t1 - $t0" | bc -l | xargs printf '%.2f'
}

serial=$(seconds "$finseg" sweep s.yaml --out serial --jobs 1 --quiet)
jobs2=$(seconds "$finseg" sweep s.yaml --out jobs2 --jobs 2 --quiet)
mpi2=$(seconds mpirun -n 2 --oversubscribe --allow-run-as-root "$finseg" sweep s.yaml --out mpi2 --quiet)
cmp -s serial/sweep.csv jobs2/sweep.csv && cmp -s serial/sweep.csv mpi2/sweep.csv \
  && same="identical" || same="DIFFERENT"
one=$(seconds "$finseg" run z.yaml --out one --quiet)

echo "| sweep (64 cases) | wall (s) | speed-up |"
echo "|---|---|---|"
echo "| serial (--jobs 1) | $serial | 1.00 |"
echo "| --jobs 2 | $jobs2 | $(echo "$serial / $jobs2" | bc -l | xargs printf '%.2f') |"
echo "| mpirun -n 2 | $mpi2 | $(echo "$serial / $mpi2" | bc -l | xargs printf '%.2f') |"
echo
echo "one case alone (finseg run): ${one} s; the three tables are $same"

# The noise-free fit of tests/test_fit.cpp: crease stiffness and density from start values
# 48 % and 38 % off.
"$finseg" run z.yaml --out truth --quiet
cat > f.yaml <<'YAML'
scene: z.yaml
curves:
  - measurements: [truth/gauge.csv]
parameters:
  - path: [zigzag.crease_laws.0.stiffness, zigzag.crease_laws.1.stiffness, zigzag.crease_laws.2.stiffness, zigzag.crease_laws.3.stiffness, zigzag.crease_laws.4.stiffness]
    initial: 4e-3
    lower: 1e-4
    upper: 1e-2
  - {path: material.density, initial: 500, lower: 10, upper: 1e4}
YAML
fit=$(seconds "$finseg" fit f.yaml --out fit --quiet --no-plot)
python3 - "$fit" <<'PY'
import json, sys
j = json.load(open("fit/fit.json"))
p = j["parameters"]
print(f"\nfit: {j['termination']}, {j['iterations']} iterations, {j['simulations']} simulations, "
      f"wall {sys.argv[1]} s ({j['wall_time_s']:.2f} s inside), "
      + ", ".join(f"{q['path'] if isinstance(q['path'], str) else q['path'][0] + ' (and the others)'}"
                  f" = {q['value']:.6g}" for q in p))
PY
