#!/usr/bin/env python3
"""RMS distance between the segment centres of two finseg state files (checkpoint.json) of the
same model, after the rigid motion that fits the first onto the second best (Horn's unit
quaternion method), e.g. a deployed cone against the target cone's start state. Prints the RMS
and the largest distance, m. Standard library only.

usage: shape_rms.py STATE.json TARGET.json
"""
import json
import math
import sys


def centres(path):
    with open(path) as f:
        return [b["p_W_m"] for b in json.load(f)["bodies"]]


def largest_eigenvector(n):
    """Eigenvector of the largest eigenvalue of a symmetric 4 x 4 matrix (cyclic Jacobi)."""
    a = [row[:] for row in n]
    v = [[float(i == j) for j in range(4)] for i in range(4)]
    for _ in range(100):
        off = sum(a[i][j] ** 2 for i in range(4) for j in range(4) if i != j)
        if off < 1e-30:
            break
        for p in range(4):
            for q in range(p + 1, 4):
                if abs(a[p][q]) < 1e-300:
                    continue
                th = 0.5 * math.atan2(2 * a[p][q], a[q][q] - a[p][p])
                c, s = math.cos(th), math.sin(th)
                for k in range(4):  # A <- A J
                    akp, akq = a[k][p], a[k][q]
                    a[k][p], a[k][q] = c * akp - s * akq, s * akp + c * akq
                for k in range(4):  # A <- J^T A
                    apk, aqk = a[p][k], a[q][k]
                    a[p][k], a[q][k] = c * apk - s * aqk, s * apk + c * aqk
                for k in range(4):
                    vkp, vkq = v[k][p], v[k][q]
                    v[k][p], v[k][q] = c * vkp - s * vkq, s * vkp + c * vkq
    i = max(range(4), key=lambda j: a[j][j])
    return [v[k][i] for k in range(4)]


def main():
    a, b = centres(sys.argv[1]), centres(sys.argv[2])
    if len(a) != len(b):
        sys.exit(f"{sys.argv[1]}: {len(a)} bodies, {sys.argv[2]}: {len(b)}; not the same model")
    ca = [sum(p[k] for p in a) / len(a) for k in range(3)]
    cb = [sum(p[k] for p in b) / len(b) for k in range(3)]
    s = [[sum((p[i] - ca[i]) * (q[j] - cb[j]) for p, q in zip(a, b)) for j in range(3)]
         for i in range(3)]
    (sxx, sxy, sxz), (syx, syy, syz), (szx, szy, szz) = s
    n = [[sxx + syy + szz, syz - szy, szx - sxz, sxy - syx],
         [syz - szy, sxx - syy - szz, sxy + syx, szx + sxz],
         [szx - sxz, sxy + syx, -sxx + syy - szz, syz + szy],
         [sxy - syx, szx + sxz, syz + szy, -sxx - syy + szz]]
    w, x, y, z = largest_eigenvector(n)
    r = [[w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]]
    dist = []
    for p, q in zip(a, b):
        d = [p[k] - ca[k] for k in range(3)]
        moved = [sum(r[i][k] * d[k] for k in range(3)) + cb[i] for i in range(3)]
        dist.append(math.dist(moved, q))
    rms = math.sqrt(sum(d * d for d in dist) / len(dist))
    print(f"rms {rms:.6g} m, largest {max(dist):.6g} m, {len(a)} segments")


if __name__ == "__main__":
    main()
