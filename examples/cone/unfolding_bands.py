#!/usr/bin/env python3
"""Which folds of a cone opened first, band by band: reads the order file of a cone run's
unfolding probe (finseg run ... --out D; D/unfolding_order.csv) and groups its crease lines
into the axial folds (rings: target angle 0, flat in the deployed cone) and the radial
pleats' generators of each band between them (docs/folding.md, "Which folds open first").

    python3 examples/cone/unfolding_bands.py D/unfolding_order.csv

A line's place on the flat development (flat_x_m, flat_y_m: its middle) tells its ring or
band: the development's apex is the origin, so the distance from it grows towards the base.
"""
import csv
import math
import statistics
import sys


def main(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no folded lines")
    when = next(k for k in rows[0] if k.startswith("half_open_"))
    unit = when[len("half_open_"):]

    def radius_mm(r):
        return 1e3 * math.hypot(float(r["flat_x_m"]), float(r["flat_y_m"]))

    def is_ring(r):
        return abs(float(r["target_deg"])) < 1.0

    rings = sorted({round(radius_mm(r)) for r in rows if is_ring(r)})
    # Rings' pieces lie at slightly different radii; merge those within 10 mm.
    merged = []
    for r in rings:
        if not merged or r - merged[-1][-1] > 10:
            merged.append([r])
        else:
            merged[-1].append(r)
    ring_r = [statistics.mean(m) for m in merged]
    groups = {}
    for r in rows:
        rad = radius_mm(r)
        if is_ring(r):
            k = min(range(len(ring_r)), key=lambda i: abs(ring_r[i] - rad))
            name = f"ring {k + 1} from the top (r {ring_r[k]:.0f} mm)"
        else:
            band = sum(rad > rr for rr in ring_r)
            name = f"pleats of band {band + 1} from the top"
        groups.setdefault(name, []).append(r)

    def median_time(rs):
        return statistics.median(float(r[when]) if r[when] else math.inf for r in rs)

    print(f"{'group':36s} lines  half open  first      median     last       "
          f"end opening (median)  reversed")
    for name, rs in sorted(groups.items(), key=lambda kv: median_time(kv[1])):
        ts = [float(r[when]) for r in rs if r[when]]
        ends = [float(r["final_opening"]) for r in rs]
        times = (f"{min(ts):<10.4g} {statistics.median(ts):<10.4g} {max(ts):<10.4g}"
                 if ts else f"{'-':<10s} {'-':<10s} {'-':<10s}")
        print(f"{name:36s} {len(rs):5d}  {len(ts):9d}  {times} "
              f"{statistics.median(ends):21.2f}  {sum(e < 0 for e in ends):8d}")
    print(f"(times in {unit}; opening: 0 as stowed, 1 as in the deployed cone; reversed: "
          f"ended folded the other way)")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
