#!/usr/bin/env python3
"""How full the lanes of the host build's cluster pairs are (gpu/solver_clusters.hpp), counted on a lattice.

For a cube of N^3 lattice points (spacing 1), every point's list holds the points within the list radius
(default 2.52: the support 2 h at h_factor 1.2, plus the Verlet skin of 5 %). Clusters are consecutive ranks
of the Morton order on cells of the spacing, as set_cluster_ranks makes them. For each layout (cluster size,
clusters per lane set) the script counts, over a sample of rows, the lane slots a row sweeps and the list
entries among them:

  * "by residue": lane set part r takes the row's clusters whose index is r modulo the parts (each lane sums
    the same points in the same order whatever else the list holds: bits independent of the sort);
  * "by position": the row's clusters in order, filling the parts one after another (fewer slots, but the
    lanes' sums then depend on which clusters the list holds).

Usage: python3 benchmarks/cluster-occupancy.py [N ...] (default 20 47: the 8000 and 103823 blocks of bench_gpu)
"""
import random
import sys


def spread(v):
    r = 0
    for b in range(21):
        if v >> b & 1:
            r |= 1 << (3 * b)
    return r


def occupancy(n, radius=2.52, sample=3000, layouts=((16, 1), (8, 1), (8, 2), (4, 2), (4, 4))):
    points = [(x, y, z) for x in range(n) for y in range(n) for z in range(n)]
    order = sorted(points, key=lambda p: spread(p[0]) | spread(p[1]) << 1 | spread(p[2]) << 2)
    rank = {p: r for r, p in enumerate(order)}
    reach = int(radius) + 1
    offsets = [(a, b, c) for a in range(-reach, reach + 1) for b in range(-reach, reach + 1)
               for c in range(-reach, reach + 1) if 0 < a * a + b * b + c * c < radius * radius]
    random.seed(1)
    rows = random.sample(points, min(sample, len(points)))
    lists = []
    for p in rows:
        lists.append([rank[q] for q in ((p[0] + a, p[1] + b, p[2] + c) for a, b, c in offsets) if q in rank])
    entries = sum(len(l) for l in lists) / len(lists)
    print(f"{n}^3 block: {entries:.1f} list entries a row (radius {radius} spacings)")
    for size, parts in layouts:
        by_residue = by_position = clusters = 0
        for l in lists:
            mine = {r // size for r in l}
            count = [0] * parts
            for c in mine:
                count[c % parts] += 1
            clusters += len(mine)
            by_residue += max(count) * size * parts
            by_position += -(-len(mine) // parts) * size * parts
        k = len(lists)
        print(f"  clusters of {size:2d}, {parts} a lane set: {clusters / k:5.1f} clusters a row; lane slots a row "
              f"{by_residue / k:5.0f} by residue ({entries * k / by_residue:.2f} full), "
              f"{by_position / k:5.0f} by position ({entries * k / by_position:.2f} full)")


if __name__ == "__main__":
    for n in [int(a) for a in sys.argv[1:]] or [20, 47]:
        occupancy(n)
