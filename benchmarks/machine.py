#!/usr/bin/env python3
"""Prints the machine's processor model and its widest SIMD set, for the speed reports' machine line."""
cpu, simd = 'unknown', ''
try:
    for line in open('/proc/cpuinfo'):
        if line.startswith('model name') and cpu == 'unknown':
            cpu = line.split(':', 1)[1].strip()
        if line.startswith('flags') and not simd:
            flags = line.split(':', 1)[1].split()
            simd = 'AVX-512' if 'avx512f' in flags else 'AVX2' if 'avx2' in flags else 'no AVX2'
except OSError:
    pass
print(cpu + (' (%s)' % simd if simd else ''))
