#!/usr/bin/env python3
"""The impact foot of a Taylor-bar run: how non-affine its particles move, and whether the rim's plastic
strain keeps up with its hoop stretch (issue 19's two foot measures).

    python3 cases/taylor-bar/foot.py RUN_FOLDER [--json]

Frames are the VTU files of the run's particles.pvd (run without output.vtu=false); particles keep their
order in every frame (the writer's order is the scene's), so frame 0 gives each particle's initial place.
The bar's axis is z, its impact face the plane z = 0 (the Taylor cases' quarter models, the wall a
symmetry plane or a [[boundaries.wall]] at z = 0); the mirror images across the case's symmetry planes
and walls take part in the sums with their velocity mirrored, as the solver's ghosts do (for a wall, as
if every particle near it were still held by it).

Non-affinity (per frame). For particle i with neighbours j in the kernel support 2 h_ij, h_ij = (h_i + h_j)/2,
the corrected velocity gradient G_i = [sum_j V_j v_ji (x) grad_i W_ij] L_i^-1, L_i = sum_j V_j x_ji (x)
grad_i W_ij (V_j = m_j / rho_j, v_ji = v_j - v_i, x_ji = x_j - x_i; the solver's first-order correction,
common/correction.hpp), and
    xi_i = sum_j W_ij |v_ji - G_i x_ji|^2 / sum_j W_ij |v_ji|^2,
the share of the neighbours' relative motion that the gradient does not see: 0 for any linear velocity
field, near 1 when the neighbours shuffle. Printed: the median of xi over the foot (the particles within
one millimetre of the impact face) and over the neck (the particles 3-5 mm from it), and the foot's mean
radial speed (m/s), so that frames where the foot no longer moves, and xi only measures noise, can be
told apart. The issue's target is the foot's xi below 0.1 while it flows.

Rim consistency (last frame). The rim: the particles of the bottom lattice layer (frame 0: z < dx, dx
the spacing from summary.json) whose initial radius r0 is within dx of the outermost one. For each,
its equivalent plastic strain eps_p against its hoop log-strain ln(r/r0). In axisymmetric flow the
hoop rate is the particle's d ln r / dt, and the equivalent plastic rate of an isochoric flow is at
least the magnitude of any one principal rate (|d_theta| <= sqrt(2/3 d:d)), so a continuum has
eps_p >= ln(r/r0) less the elastic share (about 1e-3): the ratio sum eps_p / sum ln(r/r0) below 1
measures how much of the rim's stretch is particles sliding apart rather than straining. Target: within
10 % (at least 0.9).

Standard library only (the VTU reader of cases/hard/isolated_particles.py).
"""
import json
import math
import os
import re
import sys
import tomllib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'hard'))
from isolated_particles import read_vtu  # noqa: E402

FOOT_HEIGHT = 1e-3         # m: the foot is the bottom millimetre (issue 19's measure)
NECK_BAND = (3e-3, 5e-3)   # m above the face: the flowing neck above the foot


def wendland_c2(r, h):
    """W (1/m^3) and the gradient factor F, grad_i W_ij = F (x_i - x_j) (common/kernels.hpp)."""
    q = r / h
    if q >= 2:
        return 0.0, 0.0
    alpha = 21.0 / (16.0 * math.pi * h ** 3)
    t = 1 - 0.5 * q
    return alpha * t ** 4 * (2 * q + 1), -5 * alpha * t ** 3 / (h * h)


def cubic_spline(r, h):
    q = r / h
    alpha = 1.0 / (math.pi * h ** 3)
    if q < 1:
        return alpha * (1 - 1.5 * q * q + 0.75 * q ** 3), alpha * (-3 + 2.25 * q) / (h * h)
    if q < 2:
        t = 2 - q
        return alpha * 0.25 * t ** 3, -0.75 * alpha * t * t / (q * h * h)
    return 0.0, 0.0


def inverse3(a):
    (a00, a01, a02), (a10, a11, a12), (a20, a21, a22) = a
    det = a00 * (a11 * a22 - a12 * a21) - a01 * (a10 * a22 - a12 * a20) + a02 * (a10 * a21 - a11 * a20)
    if abs(det) < 1e-300:
        return None
    c = [[a11 * a22 - a12 * a21, a02 * a21 - a01 * a22, a01 * a12 - a02 * a11],
         [a12 * a20 - a10 * a22, a00 * a22 - a02 * a20, a02 * a10 - a00 * a12],
         [a10 * a21 - a11 * a20, a01 * a20 - a00 * a21, a00 * a11 - a01 * a10]]
    return [[c[i][k] / det for k in range(3)] for i in range(3)]


def images(pos, vel, planes, reach):
    """Real particles and their mirror images across each plane in turn (corners included): positions,
    velocities (normal component negated) and the index of the real particle each one is."""
    pts, vs, src = [list(p) for p in pos], [list(v) for v in vel], list(range(len(pos)))
    for axis, at in planes:
        for k in range(len(pts)):
            if abs(pts[k][axis] - at) < reach:
                p, v = list(pts[k]), list(vs[k])
                p[axis] = 2 * at - p[axis]
                v[axis] = -v[axis]
                pts.append(p)
                vs.append(v)
                src.append(src[k])
    return pts, vs, src


def non_affinity(frame, planes, kernel, which):
    """xi_i for the particles `which` (indices) of one frame."""
    pos, vel, h = frame['Points'], frame['velocity'], frame['smoothing_length']
    vol = [m / rho for m, rho in zip(frame['mass'], frame['density'])]
    reach = 2 * max(h)
    pts, vs, src = images(pos, vel, planes, reach)
    grid = {}
    for k, p in enumerate(pts):
        grid.setdefault(tuple(math.floor(c / reach) for c in p), []).append(k)
    out = {}
    for i in which:
        xi_, vi = pos[i], vel[i]
        c = tuple(math.floor(x / reach) for x in xi_)
        pairs = []
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for k in grid.get((c[0] + dx, c[1] + dy, c[2] + dz), ()):
                        if k == i:
                            continue
                        x = [pts[k][m] - xi_[m] for m in range(3)]
                        r = math.sqrt(x[0] ** 2 + x[1] ** 2 + x[2] ** 2)
                        hij = 0.5 * (h[i] + h[src[k]])
                        if r >= 2 * hij:
                            continue
                        w, f = kernel(r, hij)
                        pairs.append((x, [vs[k][m] - vi[m] for m in range(3)], w, f, vol[src[k]]))
        lmat = [[0.0] * 3 for _ in range(3)]
        gsum = [[0.0] * 3 for _ in range(3)]
        for x, v, w, f, vj in pairs:
            grad = [-f * x[m] for m in range(3)]  # grad_i W_ij = F (x_i - x_j) = -F x_ji
            for a in range(3):
                for b in range(3):
                    lmat[a][b] += vj * x[a] * grad[b]
                    gsum[a][b] += vj * v[a] * grad[b]
        inv = inverse3(lmat)
        if inv is None:
            continue
        g = [[sum(gsum[a][k] * inv[k][b] for k in range(3)) for b in range(3)] for a in range(3)]
        num = den = 0.0
        for x, v, w, f, vj in pairs:
            rest = [v[a] - sum(g[a][b] * x[b] for b in range(3)) for a in range(3)]
            num += w * sum(c * c for c in rest)
            den += w * sum(c * c for c in v)
        if den > 0:
            out[i] = num / den
    return out


def median(values):
    s = sorted(values)
    if not s:
        return math.nan
    n = len(s)
    return s[n // 2] if n % 2 else 0.5 * (s[n // 2 - 1] + s[n // 2])


def frames_of(run):
    pvd_path = os.path.join(run, 'particles.pvd')
    if not os.path.exists(pvd_path):
        sys.exit('foot.py: no %s; run the case without --set output.vtu=false' % pvd_path)
    frames = []
    for t, name in re.findall(r'timestep="([^"]+)" group="" part="0" file="([^"]+)"', open(pvd_path).read()):
        if not frames or float(t) > frames[-1][0]:  # the end time may be listed twice (it is also a frame time)
            frames.append((float(t), name))
    return frames


def measure(run):
    info = json.load(open(os.path.join(run, 'run.json')))
    summary = json.load(open(os.path.join(run, 'summary.json')))
    case = tomllib.load(open(info['case_file'], 'rb'))
    kernel_name = case.get('numerics', {}).get('kernel', 'wendland-c2')
    for s in info.get('set', []):
        if s.startswith('numerics.kernel='):
            kernel_name = s.split('=', 1)[1].strip('"')
    kernel = wendland_c2 if kernel_name == 'wendland-c2' else cubic_spline
    planes = []
    boundaries = case.get('boundaries', {})
    for p in boundaries.get('symmetry', []) + boundaries.get('wall', []):
        position = p.get('position', '0 mm')
        if position.split()[0] not in ('0', '0.0'):
            sys.exit('foot.py: symmetry plane off the origin (%s); the Taylor cases put theirs at 0' % position)
        planes.append(('xyz'.index(p['axis']), 0.0))
    dx = summary['spacing_m']
    frames = frames_of(run)
    first = read_vtu(os.path.join(run, frames[0][1]))
    rows = []
    last = None
    for t, name in frames[1:]:
        a = read_vtu(os.path.join(run, name))
        last = a
        pos, vel = a['Points'], a['velocity']
        foot = [i for i, p in enumerate(pos) if p[2] < FOOT_HEIGHT]
        neck = [i for i, p in enumerate(pos) if NECK_BAND[0] <= p[2] < NECK_BAND[1]]
        xi = non_affinity(a, planes, kernel, foot + neck)
        radial = []
        for i in foot:
            r = math.hypot(pos[i][0], pos[i][1])
            if r > 0:
                radial.append((pos[i][0] * vel[i][0] + pos[i][1] * vel[i][1]) / r)
        rows.append({'time_us': t * 1e6, 'foot_xi': median([xi[i] for i in foot if i in xi]),
                     'neck_xi': median([xi[i] for i in neck if i in xi]),
                     'foot_radial_speed': sum(radial) / len(radial) if radial else math.nan,
                     'foot_particles': len(foot)})
    p0 = first['Points']
    r0 = [math.hypot(p[0], p[1]) for p in p0]
    bottom = [i for i, p in enumerate(p0) if p[2] < dx]
    r_out = max(r0[i] for i in bottom)
    rim = [i for i in bottom if r0[i] > r_out - dx]
    eps = sum(last['plastic_strain'][i] for i in rim)
    hoop = sum(math.log(math.hypot(last['Points'][i][0], last['Points'][i][1]) / r0[i]) for i in rim)
    return {'run': run, 'spacing_mm': dx * 1e3, 'frames': rows,
            'rim': {'particles': len(rim), 'plastic_strain': eps / len(rim), 'hoop_log_strain': hoop / len(rim),
                    'consistency': eps / hoop if hoop > 0 else math.nan, 'time_us': frames[-1][0] * 1e6}}


def main():
    args = [a for a in sys.argv[1:] if a != '--json']
    if len(args) != 1:
        sys.exit(__doc__)
    m = measure(args[0])
    if '--json' in sys.argv:
        print(json.dumps(m))
        return
    print('%s (spacing %.3g mm)' % (m['run'], m['spacing_mm']))
    print('%8s %12s %12s %16s %8s' % ('t [us]', 'foot xi', 'neck xi', 'foot v_r [m/s]', 'foot n'))
    for r in m['frames']:
        print('%8.1f %12.3f %12.3f %16.2f %8d' % (r['time_us'], r['foot_xi'], r['neck_xi'], r['foot_radial_speed'],
                                                 r['foot_particles']))
    rim = m['rim']
    print('rim at %.1f us (%d particles of the bottom layer\'s outer ring): plastic strain %.3f, '
          'hoop log-strain ln(r/r0) %.3f, consistency %.3f (a continuum: >= 1)'
          % (rim['time_us'], rim['particles'], rim['plastic_strain'], rim['hoop_log_strain'], rim['consistency']))


if __name__ == '__main__':
    main()
