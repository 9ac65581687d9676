#!/usr/bin/env python3
"""Sections of the inflated Miura tube (examples/tube/miura_inflate.yaml) against the closed form.

Reads the run's point probes s<j>_r1, s<j>_t, s<j>_r2, s<j>_b (the ridge, top and bottom vertices
of the section at fold line j) and chamber_tube.csv, and prints per output time: pressure,
volume over the largest (N b a^2 sin^2 gamma), the end-to-end length |R1(N) - R1(0)| against
the closed form N S at the mean fold angle, and each section's fold angle theta from its
height 2 H = 2 a sin(theta) sin(gamma), and how far its width 2 L is from the rhombus's
(L^2 + H^2 = a^2: the section's sides kept). Then the time at which each section first comes
within 5 deg of 45 deg (the largest volume): which folds open first.
    python3 miura_sections.py OUT_DIR [a b gamma_deg columns]
"""
import csv
import math
import os
import sys


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def main():
    out = sys.argv[1]
    a, b, gamma_deg, n = (0.02, 0.02, 60.0, 10) if len(sys.argv) < 6 else (
        float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5]))
    g = math.radians(gamma_deg)
    v_max = n * b * a * a * math.sin(g) ** 2
    _, gas = read(os.path.join(out, 'chamber_tube.csv'))
    lines = [j for j in range(n + 1) if os.path.exists(os.path.join(out, 's%d_r1.csv' % j))]
    pts = {}
    for j in lines:
        for k in ('r1', 't', 'r2', 'b'):
            _, rows = read(os.path.join(out, 's%d_%s.csv' % (j, k)))
            pts[j, k] = [r[1:4] for r in rows]

    def dist(p, q):
        return math.sqrt(sum((x - y) ** 2 for x, y in zip(p, q)))

    def cell_S(theta):  # Schenk and Guest's S of the sheet (side_a = a straight, side_b = b)
        return b * math.cos(theta) * math.tan(g) / math.sqrt(1 + (math.cos(theta) * math.tan(g)) ** 2)

    caps = {}  # the caps' corners, where probed: (end, corner) -> positions
    for end, j in ((0, 0), (1, n)):
        for k in ('r1', 't', 'r2', 'b'):
            path = os.path.join(out, 'cap%d_%s.csv' % (end, k))
            if os.path.exists(path) and j in lines:
                caps[end, k] = [r[1:4] for r in read(path)[1]]
    opened, widest = {}, [0.0, 0.0]
    print('t_ms  p_kPa  V/Vmax  length_mm (closed form)  theta_deg per section j=%s  '
          'max |2L - 2L(H)|/a  cap gaps mm' % lines)
    for k, row in enumerate(gas):
        t, p, vol = row[0], row[1], row[2]
        thetas, width_err = [], 0
        for j in lines:
            h = dist(pts[j, 't'][k], pts[j, 'b'][k]) / 2
            w = dist(pts[j, 'r1'][k], pts[j, 'r2'][k]) / 2
            th = math.asin(min(1.0, h / (a * math.sin(g))))
            thetas.append(math.degrees(th))
            width_err = max(width_err, abs(w - math.sqrt(max(0.0, a * a - h * h))) / a)
            if abs(math.degrees(th) - 45) < 5 and j not in opened:
                opened[j] = t
        length = dist(pts[lines[-1], 'r1'][k], pts[lines[0], 'r1'][k])
        mean = math.radians(sum(thetas) / len(thetas))
        gaps = []  # each cap's largest corner distance from the section it closes
        for end, j in ((0, 0), (1, n)):
            if (end, 'r1') in caps:
                gaps.append(max(dist(caps[end, c][k], pts[j, c][k]) for c in ('r1', 't', 'r2', 'b')))
                widest[end] = max(widest[end], gaps[-1])
        print('%5.1f %6.2f %6.3f %7.1f (%5.1f)  %s  %.3f  %s' % (
            t * 1e3, p / 1e3, vol / v_max, length * 1e3, n * cell_S(mean) * 1e3,
            ' '.join('%5.1f' % x for x in thetas), width_err,
            ' '.join('%.2f' % (x * 1e3) for x in gaps)))
    print('largest cap gaps (the soft seams\' stretch): fixed end %.2f mm, free end %.2f mm'
          % (widest[0] * 1e3, widest[1] * 1e3))
    print('within 5 deg of 45 deg first at (ms):',
          ', '.join('j=%d %.1f' % (j, opened[j] * 1e3) if j in opened else 'j=%d never' % j
                    for j in lines))


if __name__ == '__main__':
    main()
