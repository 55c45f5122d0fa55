#!/usr/bin/env python3
"""The plugging shear band of a plate run, frame by frame (the measurements of README.md, "Where the
spacing enters").

    python3 cases/plate-8mm/shear_band.py RUN_FOLDER [PROJECTILE_RADIUS_MM]

For each frame of the run (particles.pvd; run without output.vtu=false) it prints the time, the plug's
displacement against the plate (mean axial position of the plate particles within half the projectile
radius of the axis, against those of a ring 1.4-1.6 radii out), the projectile's nose, the number of
failed plate particles (D >= 0.99), and the equivalent plastic strain of the plate particles in the band
0.9-1.1 radii from the axis (mean and largest). The axis is the line x = y = 0 along z (the plate cases'
quarter models); the target is body 0 and the projectile body 1, the order of the case's [[bodies]].
Standard library only.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'hard'))
from isolated_particles import read_vtu  # noqa: E402


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    run = sys.argv[1]
    radius = (float(sys.argv[2]) if len(sys.argv) == 3 else 10.0) * 1e-3
    pvd_path = os.path.join(run, 'particles.pvd')
    if not os.path.exists(pvd_path):
        sys.exit('shear_band.py: no %s; run the case without --set output.vtu=false' % pvd_path)
    frames = re.findall(r'timestep="([^"]+)" group="" part="0" file="([^"]+)"', open(pvd_path).read())
    print('%8s %12s %10s %7s %10s %9s' % ('t [us]', 'plug dz [mm]', 'nose [mm]', 'failed', 'band eps', 'band max'))
    for t, name in frames:
        a = read_vtu(os.path.join(run, name))
        pos, body, damage, eps = a['Points'], a['body_id'], a['damage'], a['plastic_strain']
        centre, ring, band, failed, nose = [], [], [], 0, math.inf
        for k, p in enumerate(pos):
            if body[k] == 1:
                nose = min(nose, p[2])
                continue
            if body[k] != 0:
                continue
            r = math.hypot(p[0], p[1])
            if r < 0.5 * radius:
                centre.append(p[2])
            elif 1.4 * radius < r < 1.6 * radius:
                ring.append(p[2])
            if 0.9 * radius < r < 1.1 * radius:
                band.append(eps[k])
            if damage[k] >= 0.99:
                failed += 1
        dz = sum(ring) / len(ring) - sum(centre) / len(centre) if centre and ring else float('nan')
        print('%8.1f %12.2f %10.2f %7d %10.3f %9.3f' % (float(t) * 1e6, dz * 1e3, nose * 1e3, failed,
                                                      sum(band) / len(band) if band else float('nan'),
                                                      max(band) if band else float('nan')))


if __name__ == '__main__':
    main()
