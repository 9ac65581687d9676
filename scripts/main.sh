#!/usr/bin/env bash
# The main job: installs what finseg needs, builds it, and runs the paper's folded strip
# (section 4) under Table 1's four working conditions (examples/zigzag/). For each condition
# results/<condition>/ receives the pull-force curve (gauge.csv, gauge.png with the deployment
# phases marked), summary.json (peak force and where it occurs, phases, solver statistics),
# VTK frames (vtk/frames.pvd, opens in ParaView) and animation.html (3-D view and force curve).
# results/pull_force.png overlays the four force curves.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/release -j"$(nproc)" --target finseg
out=${FINSEG_RESULTS:-results}
mkdir -p "$out"
failed=()
curves=()
for scene in examples/zigzag/condition*.yaml; do
  name=$(basename "$scene" .yaml)
  echo "== $name"
  if build/release/finseg run "$scene" --out "$out/$name"; then
    curves+=("'$out/$name/gauge.csv' using (1000*\$1):2 with lines lw 2 title '$name'")
  else
    failed+=("$name")
  fi
done
if ((${#curves[@]})); then
  plot=$(IFS=,; echo "${curves[*]}")
  gnuplot -e "set terminal pngcairo size 1000,650; set output '$out/pull_force.png.partial';
    set datafile separator ','; set key top left; set grid;
    set xlabel 'pull displacement [mm]'; set ylabel 'gauge force [N]';
    set title 'Folded strip pulled open: Table 1 working conditions';
    plot $plot"
  mv "$out/pull_force.png.partial" "$out/pull_force.png"
  echo "overview: $out/pull_force.png"
fi
if ((${#failed[@]})); then
  echo "main job: ${#failed[@]} condition(s) did not run to the end: ${failed[*]}" >&2
  exit 1
fi
echo "main job: all conditions done; results in $out/"
