#!/usr/bin/env python3
"""The plugging shear band of a plate run, frame by frame (the measurements of README.md, "Where the
spacing enters").

    python3 cases/plate-8mm/shear_band.py RUN_FOLDER [PROJECTILE_RADIUS_MM] [--half-window MM]

For each frame of the run (particles.pvd; run without output.vtu=false) it prints the time, the plug's
displacement against the plate (mean axial position of the plate particles within half the projectile
radius of the axis, against those of a ring 1.4-1.6 radii out), the projectile's nose, the number of
failed plate particles (D >= 0.99), the equivalent plastic strain of the plate particles in the band
0.9-1.1 radii from the axis (mean and largest), the band's width, and the plastic work density at
failure: the median of W = rho0 w_p (MJ/m^3) over the failed plate particles, which keep the w_p they
failed with. Under F's critical plastic strain it is the W_p(eps_c) that the crack-band criterion's
Gamma = W_p(eps_c) k h0 carries over (cases/materials/weldox-460e.toml).

The band width is the energy width of the radial profile of the plastic work density W = rho0 w_p
(J/m^3) across the band: W is averaged in rings dx/2 wide within 5 dx of the projectile's radius (dx the
lattice spacing, read from the particle masses; --half-window MM sets this reach in mm instead, the same at
every spacing), the mean of the two outermost rings on each side is the background, and the width is the
area under the profile above it divided by its peak above it,
  w = sum_rings (W_ring - W_bg) dx/2 / (W_peak - W_bg),
printed in mm and in initial smoothing lengths h0 = h_factor dx (h_factor from the run's summary.json,
else 1.2). It is the width the crack-band criterion assumes (common/models/damage_fracture_energy.hpp): a band that dissipates
Gamma per unit area fails where its peak reaches Gamma / w. The axis is the line x = y = 0 along z (the
plate cases' quarter models); the target is body 0 and the projectile body 1, the order of the case's
[[bodies]]. Standard library only.
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'hard'))
from isolated_particles import pvd_frames, read_vtu  # noqa: E402


def main():
    args = sys.argv[1:]
    half_window = None
    if '--half-window' in args:
        k = args.index('--half-window')
        try:
            half_window = float(args[k + 1]) * 1e-3
        except (IndexError, ValueError):
            half_window = math.nan
        if not half_window > 0:
            sys.exit('shear_band.py: --half-window needs a positive length in mm (e.g. --half-window 5), got %s'
                     % (args[k + 1] if k + 1 < len(args) else 'nothing'))
        del args[k:k + 2]
    if len(args) not in (1, 2):
        sys.exit(__doc__)
    run = args[0]
    radius = (float(args[1]) if len(args) == 2 else 10.0) * 1e-3
    pvd_path = os.path.join(run, 'particles.pvd')
    if not os.path.exists(pvd_path):
        sys.exit('shear_band.py: no %s; run the case without --set output.vtu=false' % pvd_path)
    h_factor = 1.2
    summary = os.path.join(run, 'summary.json')
    if os.path.exists(summary):
        s = json.load(open(summary))
        h_factor = s['smoothing_length_m'] / s['spacing_m']
    print('%8s %12s %10s %7s %10s %9s %10s %8s %12s' % ('t [us]', 'plug dz [mm]', 'nose [mm]', 'failed', 'band eps',
                                                       'band max', 'width [mm]', 'width/h0', 'W fail [MJ/m3]'))
    for t, path in pvd_frames(run):
        a = read_vtu(path)
        pos, body, damage, eps = a['Points'], a['body_id'], a['damage'], a['plastic_strain']
        width, dx = band_width(a, radius, half_window)
        band, failed, nose = [], 0, math.inf
        for k, p in enumerate(pos):
            if body[k] == 1:
                nose = min(nose, p[2])
                continue
            if body[k] != 0:
                continue
            if 0.9 * radius < math.hypot(p[0], p[1]) < 1.1 * radius:
                band.append(eps[k])
            if damage[k] >= 0.99:
                failed += 1
        dz = plug_displacement(a, radius)
        print('%8.1f %12.2f %10.2f %7d %10.3f %9.3f %10.2f %8.2f %12.1f' % (
            float(t) * 1e6, dz * 1e3, nose * 1e3, failed, sum(band) / len(band) if band else float('nan'),
            max(band) if band else float('nan'), width * 1e3, width / (h_factor * dx), failure_work(a) * 1e-6))


def plug_displacement(a, radius):
    """The plug's axial displacement against the plate (m): the mean axial position of the plate particles
    (body 0) within half the projectile radius of the axis against those of a ring 1.4-1.6 radii out; nan
    when either is empty."""
    centre, ring = [], []
    for k, p in enumerate(a['Points']):
        if a['body_id'][k] != 0:
            continue
        r = math.hypot(p[0], p[1])
        if r < 0.5 * radius:
            centre.append(p[2])
        elif 1.4 * radius < r < 1.6 * radius:
            ring.append(p[2])
    return sum(ring) / len(ring) - sum(centre) / len(centre) if centre and ring else float('nan')


def reference_density(a):
    """The plate's rho0 (kg/m^3), read as the median density of its particles."""
    rho = sorted(a['density'][k] for k in range(len(a['Points'])) if a['body_id'][k] == 0)
    return rho[len(rho) // 2]


def failure_work(a):
    """Median plastic work density rho0 w_p (J/m^3) of the failed plate particles (D >= 0.99); nan if none."""
    rho0 = reference_density(a)
    w = sorted(rho0 * a['plastic_work'][k] for k in range(len(a['Points']))
               if a['body_id'][k] == 0 and a['damage'][k] >= 0.99)
    return w[len(w) // 2] if w else float('nan')


def band_width(a, radius, half_window=None):
    """The energy width (m) of the plastic work profile across the band at `radius`, and the spacing (m).
    The profile reaches half_window (m) to each side of `radius`, 5 dx when None."""
    pos, body, mass, rho, work = a['Points'], a['body_id'], a['mass'], a['density'], a['plastic_work']
    volumes = sorted(mass[k] / rho[k] for k in range(len(pos)) if body[k] == 0)
    dx = volumes[len(volumes) // 2] ** (1.0 / 3.0)
    rho0 = reference_density(a)
    ring = 0.5 * dx
    reach = 5 * dx if half_window is None else half_window
    count = 2 * int(round(reach / ring))
    sums, counts = [0.0] * count, [0] * count
    for k, p in enumerate(pos):
        if body[k] != 0:
            continue
        b = int(math.floor((math.hypot(p[0], p[1]) - (radius - 0.5 * count * ring)) / ring))
        if 0 <= b < count:
            sums[b] += rho0 * work[k]
            counts[b] += 1
    profile = [sums[b] / counts[b] for b in range(count) if counts[b] > 0]
    if len(profile) < 6:
        return float('nan'), dx
    background = 0.25 * (profile[0] + profile[1] + profile[-1] + profile[-2])
    peak = max(profile)
    if not peak > background:
        return float('nan'), dx
    return sum(max(w - background, 0.0) for w in profile) * ring / (peak - background), dx


if __name__ == '__main__':
    main()
