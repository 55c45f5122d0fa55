#!/usr/bin/env python3
"""Checks a run's observables against its case's expected answers (cases/NAME/expected.toml).

    check_expected.py EXPECTED.toml SUMMARY.json FIGURE [FIGURE ...]

Each FIGURE names a table of the expected file and the same key of summary.json's observables (SI).
Prints every comparison; exits 1 when one is outside its tolerance, 2 when the files do not allow the check.
The units are those expected.toml files use for these observables; another unit is an error, not a guess.
"""
import json
import sys
import tomllib

UNITS = {"m/s": 1.0, "km/s": 1e3, "g": 1e-3, "kg": 1.0, "mm": 1e-3, "m": 1.0}


def cannot_check(message):
    print(f"check_expected.py: {message}", file=sys.stderr)
    sys.exit(2)


def si(text, where):
    number, _, unit = text.strip().partition(" ")
    if unit not in UNITS:
        cannot_check(f"{where}: unit '{unit}' is not one of {', '.join(UNITS)}")
    return float(number) * UNITS[unit]


def main(argv):
    if len(argv) < 4:
        cannot_check(__doc__)
    with open(argv[1], "rb") as f:
        expected = tomllib.load(f)
    with open(argv[2]) as f:
        observables = json.load(f)["observables"]
    failed = False
    for name in argv[3:]:
        where = f"{argv[1]}: {name}"
        if name not in expected or "tolerance" not in expected[name]:
            cannot_check(f"{where}: needs a table [{name}] with value and tolerance")
        if name not in observables:
            cannot_check(f"{argv[2]}: observables has no {name}")
        want = si(expected[name]["value"], where)
        tol = float(expected[name]["tolerance"])
        got = float(observables[name])
        gap = got / want - 1
        ok = abs(gap) <= tol
        failed |= not ok
        print(f"{name}: {got:.6g} against {want:.6g} ({expected[name]['source']}): {100 * gap:+.2f} %, "
              f"target {100 * tol:.0f} %: {'ok' if ok else 'OUTSIDE'}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
