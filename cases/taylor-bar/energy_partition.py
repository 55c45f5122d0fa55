#!/usr/bin/env python3
"""Where the Taylor bar's kinetic energy went (the measurements of README.md, "Where the energy goes").

    python3 cases/taylor-bar/energy_partition.py RUN_FOLDER [SPECIFIC_HEAT TAYLOR_QUINNEY ROOM_TEMPERATURE]

Reads the first and the last frame of a run (particles.pvd; run without output.vtu=false) and prints, for
the model (the quarter bar):
  - the kinetic energy at the start and the internal energy at the end (J);
  - the plastic work, from the adiabatic heating: W_p = m c_p (T - T_room) / beta per particle (F eq 3.14;
    defaults: the case's copper, c_p 383 J/(kg K), beta 0.9, T_room 294 K);
  - the rest of the internal energy, internal - plastic work: heat of the artificial viscosity, plus the
    elastic and compression energy still stored (small once the bar is at rest);
  both per slab of the bar's initial height, and then the outer radius of the bar per 1 mm of final height.
The bar's axis is the line x = y = 0 along z, with the wall at z = 0 (cases/taylor-bar). Standard library
only.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'hard'))
from isolated_particles import read_vtu  # noqa: E402


def main():
    if len(sys.argv) not in (2, 5):
        sys.exit(__doc__)
    run = sys.argv[1]
    c_p, beta, t_room = (float(a) for a in sys.argv[2:5]) if len(sys.argv) == 5 else (383.0, 0.9, 294.0)
    if not beta > 0:
        sys.exit('energy_partition.py: the Taylor-Quinney factor must be > 0 (the plastic work is read from the heating)')
    pvd_path = os.path.join(run, 'particles.pvd')
    if not os.path.exists(pvd_path):
        sys.exit('energy_partition.py: no %s; run the case without --set output.vtu=false' % pvd_path)
    frames = re.findall(r'timestep="([^"]+)" group="" part="0" file="([^"]+)"', open(pvd_path).read())
    if len(frames) < 2:
        sys.exit('energy_partition.py: %s has fewer than two frames' % pvd_path)
    first = read_vtu(os.path.join(run, frames[0][1]))
    last = read_vtu(os.path.join(run, frames[-1][1]))
    z0 = [p[2] for p in first['Points']]
    mass = last['mass']
    kinetic0 = sum(0.5 * m * sum(c * c for c in v) for m, v in zip(first['mass'], first['velocity']))
    internal = [m * e for m, e in zip(mass, last['internal_energy'])]
    plastic = [m * c_p * (t - t_room) / beta for m, t in zip(mass, last['temperature'])]
    total_i, total_p = sum(internal), sum(plastic)
    print('t = %s us: kinetic energy at the start %.3f J; internal energy %.3f J, of it plastic work %.3f J '
          '(%.1f %% of the start kinetic energy) and the rest %.3f J (%.1f %%)' % (
              '%.1f' % (float(frames[-1][0]) * 1e6), kinetic0, total_i, total_p, 100 * total_p / kinetic0,
              total_i - total_p, 100 * (total_i - total_p) / kinetic0))
    length0 = max(z0) - min(z0)
    slabs = 8
    print('%18s %12s %10s %8s' % ('initial height mm', 'plastic J', 'rest J', 'rest %'))
    for k in range(slabs):
        lo, hi = min(z0) + k * length0 / slabs, min(z0) + (k + 1) * length0 / slabs
        sel = [i for i, z in enumerate(z0) if lo <= z < hi or (k == slabs - 1 and z == hi)]
        p = sum(plastic[i] for i in sel)
        r = sum(internal[i] for i in sel) - p
        print('%8.2f - %6.2f %12.3f %10.3f %8.1f' % (lo * 1e3, hi * 1e3, p, r, 100 * r / (p + r) if p + r > 0 else 0))
    radius = {}
    for (x, y, z) in last['Points']:
        k = int(math.floor(z * 1e3))
        radius[k] = max(radius.get(k, 0.0), math.hypot(x, y))
    print('outer particle radius per mm of final height (mm): ' +
          ' '.join('%d:%.2f' % (k, radius[k] * 1e3) for k in sorted(radius)))


if __name__ == '__main__':
    main()
