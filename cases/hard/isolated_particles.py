#!/usr/bin/env python3
"""Single-particle fragments in the frames of a run (the measurements of single-particle-fragments.toml).

    python3 cases/hard/isolated_particles.py RUN_FOLDER [TARGET_BODY]

A particle is isolated in a frame when no other particle, and no mirror image of a particle across the
case's symmetry planes, lies within the kernel support 2 (h_i + h_j)/2 (Wendland C2 and cubic spline:
support 2h): its kernel-correction matrix L_i is then zero and the solver falls back to the
uncorrected gradient. For each frame it prints the isolated particles, and at the end how many
different particles were isolated in some frame and how many of those, not of TARGET_BODY, later came
within the support of a particle of TARGET_BODY (hit it): in all, and those still isolated in the frame
before. Frames are the VTU files of particles.pvd (run without output.vtu=false); particles keep their
order in every frame (the writer's order is the scene's). Standard library only.
"""
import math
import os
import re
import struct
import sys
import tomllib


def pvd_frames(run):
    """The frames of a run's particles.pvd: (time in s, path of the VTU file), in time order, each file once
    (the last frame may be listed twice: the end time is also a frame time)."""
    pvd = open(os.path.join(run, 'particles.pvd')).read()
    frames, seen = [], set()
    for t, name in re.findall(r'timestep="([^"]+)" group="" part="0" file="([^"]+)"', pvd):
        if name not in seen:
            seen.add(name)
            frames.append((float(t), os.path.join(run, name)))
    return frames


def read_vtu(path):
    data = open(path, 'rb').read()
    head, _, rest = data.partition(b'<AppendedData encoding="raw">')
    raw = rest[rest.index(b'_') + 1:]
    out = {}
    pattern = rb'<DataArray type="(\w+)" Name="(\w+)"(?: NumberOfComponents="(\d+)")? format="appended" offset="(\d+)"'
    for m in re.finditer(pattern, head):
        kind, name, nc, off = m.group(1).decode(), m.group(2).decode(), int(m.group(3) or 1), int(m.group(4))
        nbytes = struct.unpack_from('<Q', raw, off)[0]  # header_type UInt64
        fmt, size = {'Float64': ('d', 8), 'Float32': ('f', 4), 'Int32': ('i', 4), 'Int64': ('q', 8), 'UInt8': ('B', 1)}[kind]
        values = struct.unpack_from('<%d%s' % (nbytes // size, fmt), raw, off + 8)
        out[name] = [values[i:i + nc] for i in range(0, len(values), nc)] if nc > 1 else list(values)
    return out


def neighbours(pos, h, planes):
    """For each particle, the indices (of real particles) within the pair support, images included."""
    pts, src = [tuple(p) for p in pos], list(range(len(pos)))
    reach = 2 * max(h)
    for axis, at in planes:  # images across each plane in turn: also the corner images of two planes
        for k in range(len(pts)):
            if abs(pts[k][axis] - at) < reach:
                q = list(pts[k])
                q[axis] = 2 * at - q[axis]
                pts.append(tuple(q))
                src.append(src[k])
    grid = {}
    for k, q in enumerate(pts):
        grid.setdefault(tuple(math.floor(c / reach) for c in q), []).append(k)
    out = []
    for i, q in enumerate(pos):
        c = tuple(math.floor(x / reach) for x in q)
        found = set()
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for k in grid.get((c[0] + dx, c[1] + dy, c[2] + dz), ()):
                        if k == i:
                            continue
                        j = src[k]
                        support = h[i] + h[j]  # 2 (h_i + h_j) / 2
                        if sum((pts[k][m] - q[m]) ** 2 for m in range(3)) < support * support:
                            found.add(j)
        out.append(found)
    return out


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    run = sys.argv[1]
    info = json_load(os.path.join(run, 'run.json'))
    case = tomllib.load(open(info['case_file'], 'rb'))
    planes = [('xyz'.index(p['axis']), length(p.get('position', 0))) for p in case.get('boundaries', {}).get('symmetry', [])]
    names = [b['name'] for b in case['bodies']]
    target = names.index(sys.argv[2]) if len(sys.argv) == 3 else None
    frames = pvd_frames(run)
    ever, was_isolated, hits, hits_alone = set(), set(), {}, {}
    for t, path in frames:
        a = read_vtu(path)
        body = a['body_id']
        nb = neighbours(a['Points'], a['smoothing_length'], planes)
        if target is not None:
            for i in ever:
                if i in hits or body[i] == target:
                    continue
                if any(body[j] == target for j in nb[i]):
                    hits[i] = float(t)
                    if i in was_isolated:
                        hits_alone[i] = float(t)
        isolated = {i for i in range(len(nb)) if not nb[i]}
        ever |= isolated
        was_isolated = isolated
        by_body = {names[b]: sum(1 for i in isolated if body[i] == b) for b in sorted({body[i] for i in isolated})}
        print('%8.3f us  isolated %4d  %s' % (float(t) * 1e6, len(isolated), by_body))
    print('particles isolated in some frame: %d' % len(ever))
    if target is not None:
        print('of them (not of "%s") later within the support of a particle of "%s": %d; isolated in the frame '
              'before: %d' % (names[target], names[target], len(hits), len(hits_alone)))
        if hits:
            print('first such hit at %.3f us' % (min(hits.values()) * 1e6))


def json_load(path):
    import json
    return json.load(open(path))


def length(v):
    """A length of the case file in m: a bare number or "N mm" style (m, mm, cm, um)."""
    if isinstance(v, (int, float)):
        return float(v)
    number, unit = v.split()
    return float(number) * {'m': 1, 'cm': 1e-2, 'mm': 1e-3, 'um': 1e-6}[unit]


if __name__ == '__main__':
    main()
