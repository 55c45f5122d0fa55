#!/usr/bin/python3
"""Reads a run folder's particles.pvd and its VTU frames with VTK's own readers and checks them against
summary.json. Run it with a Python that has VTK (Debian: `sudo apt-get install python3-vtk9`, then
/usr/bin/python3):

    /usr/bin/python3 verification/vtk_readback.py runs/plate-8mm [--rtol 1e-9]

Checks: the PVD parses and lists at least one frame; every frame it lists exists and loads without a
VTK error; its time (FieldData TIME) is the PVD's timestep; its point and cell counts (one vertex per
particle) are summary.json's particle count; every point field the writer documents is there with its
type and component count; every value is finite; cell i is the vertex of point i; mass, density and
smoothing length are positive, damage in [0, 1], fixed 0 or 1, speed |velocity|. Of the last frame, when summary.json says the run
completed: the particles, mass, mass-weighted velocity, kinetic and internal energy and damaged mass
fraction of each body, the total momentum and the simulated time agree with summary.json to --rtol
(relative; the VTU holds Float64, so only the order of the sums differs: 1e-9 is ample). Vector and
signed figures are compared relative to the sum of magnitudes (sum m |v|, sum m |e|), a fraction
absolutely. Exit status 0: all agree; 1: a check failed (each failure is printed); 2: bad arguments;
77: VTK is not importable (the CTest skips).
"""
import argparse
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

try:
    from vtkmodules.vtkCommonCore import vtkCommand, vtkLogger, vtkOutputWindow, vtkStringOutputWindow
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
except ImportError as e:
    print(f"vtk_readback: cannot import VTK ({e}); install it with `sudo apt-get install python3-vtk9` and run "
          f"this script with /usr/bin/python3", file=sys.stderr)
    sys.exit(77)

# The point fields of FrameSeriesWriter::write_frame (common/output.cpp): name -> (VTK type, components).
FIELDS = {
    "velocity": ("double", 3),
    "speed": ("double", 1),
    "density": ("double", 1),
    "pressure": ("double", 1),
    "von_mises": ("double", 1),
    "plastic_strain": ("double", 1),
    "plastic_work": ("double", 1),
    "damage": ("double", 1),
    "temperature": ("double", 1),
    "bulking_pressure": ("double", 1),
    "internal_energy": ("double", 1),
    "smoothing_length": ("double", 1),
    "mass": ("double", 1),
    "body_id": ("int", 1),
    "material_id": ("int", 1),
    "fixed": ("unsigned char", 1),
}
VTK_VERTEX = 1
# Ranges every frame must keep: name -> (lowest, highest), None for no bound.
BOUNDS = {"density": (0.0, None), "smoothing_length": (0.0, None), "mass": (0.0, None), "damage": (0.0, 1.0),
          "fixed": (0, 1), "speed": (0.0, None)}
POSITIVE = ("density", "smoothing_length", "mass")  # strictly
FAILED_DAMAGE = 0.99  # common/observables.hpp: damaged_mass_fraction counts D >= 0.99


class Checks:
    def __init__(self):
        self.failures = []

    def fail(self, message):
        self.failures.append(message)
        print(f"FAIL: {message}")

    def close(self, what, got, want, scale, rtol):
        """got and want agree to rtol relative to scale (max(|want|, scale))."""
        tol = rtol * max(abs(want), scale)
        if not (math.isfinite(got) and abs(got - want) <= tol):
            self.fail(f"{what}: {got!r} from the VTU, {want!r} in summary.json (difference {got - want:.3g}, "
                      f"tolerance {tol:.3g})")


def read_pvd(path, checks):
    """The (timestep, file) entries of a PVD collection, or None when it cannot be parsed."""
    if not os.path.isfile(path):
        checks.fail(f"{path} is missing (a run with output.vtu = false writes no frames)")
        return None
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, OSError) as e:
        checks.fail(f"{path}: not a readable XML file: {e}")
        return None
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        checks.fail(f"{path}: not a VTK collection (<VTKFile type=\"Collection\">), root <{root.tag}>")
        return None
    entries = []
    for ds in root.iter("DataSet"):
        try:
            entries.append((float(ds.get("timestep")), ds.get("file")))
        except (TypeError, ValueError):
            checks.fail(f"{path}: <DataSet> without a numeric timestep and a file: {ds.attrib}")
    if not entries:
        checks.fail(f"{path}: the collection lists no frame")
    return entries


def load_vtu(path, checks):
    """The vtkUnstructuredGrid of one frame, or None when VTK reports an error or reads nothing."""
    if not os.path.isfile(path):
        checks.fail(f"{path}: listed in the PVD but missing")
        return None
    log = vtkStringOutputWindow()
    previous = vtkOutputWindow.GetInstance()
    vtkOutputWindow.SetInstance(log)
    errors = []
    reader = vtkXMLUnstructuredGridReader()
    reader.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
    reader.SetFileName(path)
    try:
        reader.Update()
    finally:
        vtkOutputWindow.SetInstance(previous)
    text = log.GetOutput()
    if errors or "ERROR" in text or reader.GetErrorCode() != 0:
        first = " ".join(line.strip() for line in text.splitlines() if line.strip())[:400]
        checks.fail(f"{path}: VTK could not read it: {first or 'error event'}")
        return None
    return reader.GetOutput()


def field_time(grid):
    arr = grid.GetFieldData().GetArray("TIME")
    return arr.GetValue(0) if arr is not None and arr.GetNumberOfTuples() == 1 else None


def check_frame(path, grid, timestep, particles, checks):
    """Counts, fields and finiteness of one frame; returns {name: vtkDataArray} of the fields present."""
    name = os.path.basename(path)
    n = grid.GetNumberOfPoints()
    if particles is not None and n != particles:
        checks.fail(f"{name}: {n} points, summary.json has {particles} particles")
    if grid.GetNumberOfCells() != n:
        checks.fail(f"{name}: {grid.GetNumberOfCells()} cells for {n} points (one vertex per particle)")
    elif any(grid.GetCellType(i) != VTK_VERTEX for i in range(n)):
        checks.fail(f"{name}: a cell is not a VTK_VERTEX")
    else:
        ids = grid.GetCells().GetConnectivityArray()
        if ids.GetNumberOfTuples() != n or any(ids.GetValue(i) != i for i in range(n)):
            checks.fail(f"{name}: the connectivity is not one vertex per particle in order (cell i = point i)")
    t = field_time(grid)
    if t is None:
        checks.fail(f"{name}: no FieldData TIME")
    elif t != timestep:
        checks.fail(f"{name}: TIME {t!r}, the PVD lists it at {timestep!r}")
    points = grid.GetPoints()
    if points is None or points.GetData().GetDataTypeAsString() != "double":
        checks.fail(f"{name}: Points are not Float64")
    elif not all(math.isfinite(c) for i in range(n) for c in points.GetPoint(i)):
        checks.fail(f"{name}: a point position is not finite")
    pd = grid.GetPointData()
    arrays = {}
    for field, (vtk_type, components) in FIELDS.items():
        arr = pd.GetArray(field)
        if arr is None:
            checks.fail(f"{name}: point field '{field}' is missing")
            continue
        if arr.GetDataTypeAsString() != vtk_type or arr.GetNumberOfComponents() != components:
            checks.fail(f"{name}: '{field}' is {arr.GetDataTypeAsString()} x {arr.GetNumberOfComponents()}, "
                        f"expected {vtk_type} x {components}")
            continue
        if arr.GetNumberOfTuples() != n:
            checks.fail(f"{name}: '{field}' has {arr.GetNumberOfTuples()} tuples for {n} points")
            continue
        bad = next((i for i in range(n * components) if not math.isfinite(arr.GetValue(i))), None)
        if bad is not None:
            checks.fail(f"{name}: '{field}' of particle {bad // components} is {arr.GetValue(bad)}")
        lo, hi = BOUNDS.get(field, (None, None))
        for i in range(n if bad is None and (lo is not None or hi is not None) else 0):
            v = arr.GetValue(i)
            if (lo is not None and (v < lo or (field in POSITIVE and v == lo))) or (hi is not None and v > hi):
                checks.fail(f"{name}: '{field}' of particle {i} is {v!r}, outside "
                            f"{'(' if field in POSITIVE else '['}{lo}, {hi if hi is not None else 'inf'}]")
                break
        arrays[field] = arr
    if "speed" in arrays and "velocity" in arrays:
        for i in range(n):
            v = arrays["velocity"].GetTuple3(i)
            s, want = arrays["speed"].GetValue(i), math.sqrt(sum(c * c for c in v))
            if abs(s - want) > 1e-12 * want + 1e-300:
                checks.fail(f"{name}: 'speed' of particle {i} is {s!r}, |velocity| is {want!r}")
                break
    extra = sorted(pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays()) if pd.GetArrayName(i) not in FIELDS)
    if extra:
        checks.fail(f"{name}: point fields the checker does not know: {', '.join(extra)} (add them to FIELDS)")
    return arrays


def check_against_summary(name, arrays, summary, rtol, checks):
    """The last frame's sums per body and in total against summary.json."""
    if any(f not in arrays for f in ("velocity", "mass", "internal_energy", "damage", "body_id")):
        checks.fail(f"{name}: fields missing, the sums against summary.json were not checked")
        return
    bodies = summary.get("bodies", [])
    n = arrays["mass"].GetNumberOfTuples()
    k_count = len(bodies)
    count = [0] * k_count
    mass, ke, ie, ie_scale, damaged, mv_scale = ([[] for _ in range(k_count)] for _ in range(6))
    mv = [[[], [], []] for _ in range(k_count)]
    total_p = [[], [], []]
    vel, m_arr, e_arr = arrays["velocity"], arrays["mass"], arrays["internal_energy"]
    d_arr, b_arr = arrays["damage"], arrays["body_id"]
    for i in range(n):
        b = b_arr.GetValue(i)
        if not 0 <= b < k_count:
            checks.fail(f"{name}: particle {i} has body_id {b}, summary.json has {k_count} bodies")
            return
        m, e = m_arr.GetValue(i), e_arr.GetValue(i)
        v = vel.GetTuple3(i)
        speed = math.sqrt(sum(c * c for c in v))
        count[b] += 1
        mass[b].append(m)
        ke[b].append(0.5 * m * speed * speed)
        ie[b].append(m * e)
        ie_scale[b].append(abs(m * e))
        mv_scale[b].append(m * speed)
        if d_arr.GetValue(i) >= FAILED_DAMAGE:
            damaged[b].append(m)
        for c in range(3):
            mv[b][c].append(m * v[c])
            total_p[c].append(m * v[c])
    for b, body in enumerate(bodies):
        label = f"{name}: body {body.get('name', b)!r}"
        if body.get("particles") != count[b]:
            checks.fail(f"{label}: {count[b]} particles, summary.json has {body.get('particles')}")
        m_sum = math.fsum(mass[b])
        checks.close(f"{label} mass_kg", m_sum, body["mass_kg"], 0.0, rtol)
        v_scale = math.fsum(mv_scale[b]) / m_sum if m_sum > 0 else 0.0
        for c in range(3):
            v = math.fsum(mv[b][c]) / m_sum if m_sum > 0 else 0.0
            checks.close(f"{label} velocity_m_s[{c}]", v, body["velocity_m_s"][c], v_scale, rtol)
        checks.close(f"{label} kinetic_energy_J", math.fsum(ke[b]), body["kinetic_energy_J"], 0.0, rtol)
        checks.close(f"{label} internal_energy_J", math.fsum(ie[b]), body["internal_energy_J"],
                     math.fsum(ie_scale[b]), rtol)
        fraction = math.fsum(damaged[b]) / m_sum if m_sum > 0 else 0.0
        checks.close(f"{label} damaged_mass_fraction", fraction, body["damaged_mass_fraction"], 1.0, rtol)
    p_scale = math.fsum(s for body in mv_scale for s in body)
    final_p = summary.get("totals", {}).get("final_momentum_kg_m_s")
    if final_p is None:
        checks.fail("summary.json has no totals.final_momentum_kg_m_s")
    else:
        for c in range(3):
            checks.close(f"{name}: total momentum[{c}]", math.fsum(total_p[c]), final_p[c], p_scale, rtol)


def main():
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)  # load_vtu reports VTK's errors itself
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run_dir", help="the output folder of `impactsph run` (holds particles.pvd and summary.json)")
    ap.add_argument("--rtol", type=float, default=1e-9, help="relative tolerance of the sums (default 1e-9)")
    args = ap.parse_args()
    if not (args.rtol > 0):
        ap.error("--rtol must be greater than zero")
    checks = Checks()
    summary_path = os.path.join(args.run_dir, "summary.json")
    summary = None
    try:
        with open(summary_path) as f:
            summary = json.load(f)
    except (OSError, ValueError) as e:
        checks.fail(f"{summary_path}: cannot read it: {e}")
    particles = summary.get("particles") if summary else None

    pvd_path = os.path.join(args.run_dir, "particles.pvd")
    entries = read_pvd(pvd_path, checks) or []
    last = None
    for timestep, file in entries:
        path = os.path.join(args.run_dir, file)
        grid = load_vtu(path, checks)
        if grid is None:
            last = None
            continue
        arrays = check_frame(path, grid, timestep, particles, checks)
        last = (file, timestep, arrays)

    if summary and entries:
        if last is None or last[0] != entries[-1][1]:
            checks.fail("the last frame could not be read, so it was not compared with summary.json")
        elif not summary.get("completed", False):
            print(f"note: summary.json says the run did not complete; the last frame was not compared with it")
        else:
            file, timestep, arrays = last
            if timestep != summary.get("simulated_time_s"):
                checks.fail(f"{file}: the last frame is at t = {timestep!r} s, summary.json's final state at "
                            f"{summary.get('simulated_time_s')!r} s")
            else:
                check_against_summary(file, arrays, summary, args.rtol, checks)

    if checks.failures:
        print(f"vtk_readback: {len(checks.failures)} check(s) failed in {args.run_dir}", file=sys.stderr)
        return 1
    print(f"vtk_readback: {len(entries)} frame(s) of {args.run_dir} read by vtkXMLUnstructuredGridReader: "
          f"{particles} particles, {len(FIELDS)} fields, all finite; the last frame agrees with summary.json "
          f"to a relative {args.rtol:g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
