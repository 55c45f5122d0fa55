#!/usr/bin/env python3
"""Writes projectile.stl: the blunt 20 mm x 80 mm Arne projectile of plate-8mm with its axis along a path
30 degrees from the plate normal (in the x-z plane), its impact face's lowest point 0.5 mm above the
plate's top face z = 0. Coordinates in mm; 64 segments around. Run from this folder:
    python3 make_projectile.py
"""
import math

RADIUS, LENGTH, SEGMENTS, ANGLE_DEG, GAP = 10.0, 80.0, 64, 30.0, 0.5

a = math.radians(ANGLE_DEG)
axis = (math.sin(a), 0.0, -math.cos(a))  # the direction of flight, from the rear face to the impact face
u = (math.cos(a), 0.0, math.sin(a))      # two unit vectors normal to the axis
v = (0.0, 1.0, 0.0)
# The impact face's centre: its rim point with the smallest z (at -u) sits GAP above z = 0.
front = (0.0, 0.0, GAP + RADIUS * math.sin(a))
rear = tuple(front[i] - LENGTH * axis[i] for i in range(3))


def ring(centre):
    return [tuple(centre[i] + RADIUS * (math.cos(t) * u[i] + math.sin(t) * v[i]) for i in range(3))
            for t in (2 * math.pi * s / SEGMENTS for s in range(SEGMENTS))]


f_ring, r_ring = ring(front), ring(rear)
triangles = []
for s in range(SEGMENTS):
    n = (s + 1) % SEGMENTS
    triangles.append((front, f_ring[n], f_ring[s]))   # impact face, normal along +axis
    triangles.append((rear, r_ring[s], r_ring[n]))    # rear face, normal along -axis
    triangles.append((r_ring[s], f_ring[s], f_ring[n]))
    triangles.append((r_ring[s], f_ring[n], r_ring[n]))

with open("projectile.stl", "w") as out:
    out.write("solid projectile\n")
    for t in triangles:
        out.write(" facet normal 0 0 0\n  outer loop\n")
        for p in t:
            out.write("   vertex %.9g %.9g %.9g\n" % p)
        out.write("  endloop\n endfacet\n")
    out.write("endsolid projectile\n")
print("wrote projectile.stl: %d triangles" % len(triangles))
