"""Opens every .xdmf of the given run folders with the XDMF readers this machine has and compares
what they read with the HDF5 files: meshio's xdmf.TimeSeriesReader (the triangle-mesh series) and
ParaView's pvbatch (every file; one pvbatch process for all). Fails on a reader's error line, a
wrong count of points, cells or time steps, or a frame's values that differ from the HDF5; for a 3D
grid of fields also on its bounds and on a value placed in another cell than the HDF5's.

usage: /usr/bin/python3 xdmf_readers.py PVBATCH|- FOLDER...   (- : no pvbatch)
Under pvbatch (called by this script): xdmf_readers.py --paraview FILE...: one JSON line per reader
and file."""
import glob
import json
import os
import subprocess
import sys

# The readers ParaView 5.11 offers for .xdmf; the legacy XDMF 2 reader cannot select a slab in
# XDMF 3's "file:/path|slab" form, so it is asked only for files that name whole datasets.
XDMF3_READERS = ("Xdmf3ReaderS", "Xdmf3ReaderT")


def paraview_side(files):
    import paraview.simple as pv

    for path in files:
        slabs = "|" in open(path).read()
        default = pv.OpenDataFile(path)
        print(json.dumps({"file": path, "default_reader": default.GetXMLName()}), flush=True)
        pv.Delete(default)
        for name in XDMF3_READERS + (() if slabs else ("XDMFReader",)):
            key = "FileNames" if name == "XDMFReader" else "FileName"
            reader = getattr(pv, name)(**{key: [path]})
            times = list(reader.TimestepValues)
            frames = []
            for t in times:
                reader.UpdatePipeline(t)
                info = reader.GetDataInformation()
                frames.append({
                    "time": t, "points": info.GetNumberOfPoints(), "cells": info.GetNumberOfCells(),
                    "bounds": list(info.GetBounds()),
                    "point_ranges": {a.GetName(): list(a.GetRange(-1)) for a in reader.PointData},
                    "cell_ranges": {a.GetName(): list(a.GetRange(0)) for a in reader.CellData},
                    "cell_moments": cell_moments(reader),
                })
            print(json.dumps({"file": path, "reader": name, "frames": frames}), flush=True)
            pv.Delete(reader)


def cell_moments(reader):
    """For each cell array of a 3D grid, sum over cells of value x cell centre (x, y, z), the centres
    from ParaView's own geometry: the HDF5's only when ParaView placed every value in its own cell
    and the cells where the grid's attributes put them. {} for other data."""
    import numpy as np
    from paraview import servermanager
    from vtk.numpy_interface import dataset_adapter as dsa
    from vtkmodules.vtkFiltersCore import vtkCellCenters

    data = servermanager.Fetch(reader)
    if data.IsA("vtkCompositeDataSet") or not data.IsA("vtkImageData") or min(data.GetDimensions()) < 2:
        return {}
    centres = vtkCellCenters()
    centres.SetInputData(data)
    centres.Update()
    where = dsa.WrapDataObject(centres.GetOutput()).Points
    cells = dsa.WrapDataObject(data).CellData
    return {name: [float(v) for v in (np.asarray(cells[name])[:, None] * where).sum(axis=0)] for name in cells.keys()}


def h5_of(xdmf):
    import xml.etree.ElementTree as ET

    item = next(i for i in ET.parse(xdmf).getroot().iter("DataItem") if i.get("Format") == "HDF")
    return os.path.join(os.path.dirname(xdmf), item.text.strip().split(":")[0])


def expected(xdmf):
    """What a reader must see, per frame, from the HDF5 file."""
    import h5py
    import numpy as np

    with h5py.File(h5_of(xdmf), "r") as f:
        if "render" in f:
            r = f["render"]
            pos, nrm = r["positions_m"][()], r["normals"][()]
            return {"kind": "mesh", "times": list(r["time_s"][()]), "points": pos.shape[1],
                    "cells": r["triangles"].shape[0],
                    "frames": [{"bounds": [v for d in range(3) for v in (pos[k, :, d].min(), pos[k, :, d].max())],
                                "point_ranges": {"normals": [np.linalg.norm(nrm[k], axis=1).min(),
                                                             np.linalg.norm(nrm[k], axis=1).max()],
                                                 "part": [r["part"][()].min(), r["part"][()].max()]},
                                "cell_ranges": {}} for k in range(len(pos))]}
        names = [n for n in f["fields"] if n != "time_s"]
        if f["fields"][names[0]].ndim == 4:
            return expected_volume(f["fields"], names)
        nt, ny, nx = f["fields"][names[0]].shape
        return {"kind": "fields", "times": list(f["fields/time_s"][()]), "points": (ny + 1) * (nx + 1),
                "cells": ny * nx,
                "frames": [{"cell_ranges": {n: [f["fields"][n][k].min(), f["fields"][n][k].max()] for n in names},
                            "point_ranges": {}} for k in range(nt)]}


def expected_volume(fields, names):
    """A (frames, nz, ny, nx) field series: counts, the box's bounds from the grid's attributes, each
    frame's ranges and sums of value x cell centre (cell_moments) with their scale for the tolerance."""
    import numpy as np

    nt, nz, ny, nx = fields[names[0]].shape
    a = fields.attrs
    bounds = []
    for axis, n in (("x", nx), ("y", ny), ("z", nz)):
        origin = float(a["origin_%s_m" % axis])
        bounds += [origin, origin + n * float(a["d%s_m" % axis])]
    centre = [bounds[2 * a] + (np.arange(n) + 0.5) * float(a_d) for a, (n, a_d) in
              enumerate(((nx, a["dx_m"]), (ny, a["dy_m"]), (nz, a["dz_m"])))]
    z, y, x = np.meshgrid(centre[2], centre[1], centre[0], indexing="ij")
    where = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    frames = []
    for k in range(nt):
        values = {n: fields[n][k].ravel() for n in names}
        frames.append({"bounds": bounds,
                       "cell_ranges": {n: [v.min(), v.max()] for n, v in values.items()},
                       "cell_moments": {n: [list((v[:, None] * where).sum(axis=0)), (abs(v) * abs(where).sum(axis=1)).sum()]
                                        for n, v in values.items()},
                       "point_ranges": {}})
    return {"kind": "volume", "times": list(fields["time_s"][()]), "points": (nz + 1) * (ny + 1) * (nx + 1),
            "cells": nz * ny * nx, "frames": frames}


def close(a, b):
    return abs(a - b) <= 1e-12 * max(1.0, abs(a), abs(b))


def check_paraview(pvbatch, files, expect, failures):
    out = subprocess.run([pvbatch, os.path.abspath(__file__), "--paraview"] + files, capture_output=True, text=True,
                         timeout=120)
    lines = (out.stdout + out.stderr).splitlines()
    records = []
    for line in lines:
        try:
            records.append(json.loads(line))
        except ValueError:
            if line.strip():
                failures.append("pvbatch printed: " + line.strip()[:300])
    if out.returncode:
        failures.append("pvbatch exit code %d" % out.returncode)
    for path in files:
        want = expect[path]
        mine = [r for r in records if r["file"] == path]
        default = [r["default_reader"] for r in mine if "default_reader" in r]
        if default != [default[0]] or default[0] not in XDMF3_READERS:
            failures.append("%s: ParaView opens it with %s, not an Xdmf3 reader" % (path, default))
        read = [r for r in mine if "reader" in r]
        if len(read) != (3 if want["kind"] == "mesh" else 2):
            failures.append("%s: %d ParaView readers reported" % (path, len(read)))
        for r in read:
            where = "%s, ParaView %s" % (path, r["reader"])
            if len(r["frames"]) != len(want["times"]):
                failures.append("%s: %d time steps, HDF5 has %d" % (where, len(r["frames"]), len(want["times"])))
                continue
            for k, (got, frame) in enumerate(zip(r["frames"], want["frames"])):
                if not close(got["time"], want["times"][k]):
                    failures.append("%s frame %d: time %r, HDF5 %r" % (where, k, got["time"], want["times"][k]))
                if got["points"] != want["points"] or got["cells"] != want["cells"]:
                    failures.append("%s frame %d: %d points, %d cells; HDF5 %d, %d" % (
                        where, k, got["points"], got["cells"], want["points"], want["cells"]))
                if "bounds" in frame and not all(map(close, got["bounds"], frame["bounds"])):
                    failures.append("%s frame %d: bounds %s, HDF5 %s" % (where, k, got["bounds"], frame["bounds"]))
                for name, (moment, scale) in frame.get("cell_moments", {}).items():
                    have = got["cell_moments"].get(name)
                    if have is None or max(abs(h - m) for h, m in zip(have, moment)) > 1e-9 * scale:
                        failures.append("%s frame %d: %s's cells hold other values or sit elsewhere (moment %r, "
                                        "HDF5 %r)" % (where, k, name, have, moment))
                for group in ("point_ranges", "cell_ranges"):
                    for name, span in frame[group].items():
                        have = got[group].get(name)
                        if have is None or not (close(have[0], span[0]) and close(have[1], span[1])):
                            failures.append("%s frame %d: %s range %s, HDF5 %s" % (where, k, name, have, span))
    return len(files)


def check_meshio(files, expect, failures):
    count = 0
    for path in files:
        if expect[path]["kind"] != "mesh":
            continue  # meshio reads no co-rectilinear grids (2D or 3D)
        count += 1
        try:
            read_with_meshio(path, failures)
        except Exception as e:  # a reader's error is a finding, not a crash of this check
            failures.append("%s, meshio: %s: %s" % (path, type(e).__name__, e))
    return count


def read_with_meshio(path, failures):
    import h5py
    import meshio
    import numpy as np

    with h5py.File(h5_of(path), "r") as f, meshio.xdmf.TimeSeriesReader(path) as reader:
        r = f["render"]
        points, cells = reader.read_points_cells()
        if not np.array_equal(points, r["positions_m"][0]):
            failures.append("%s, meshio: points %s differ from positions_m[0]" % (path, points.shape))
        if [c.type for c in cells] != ["triangle"] or not np.array_equal(cells[0].data, r["triangles"][()]):
            failures.append("%s, meshio: cells %s differ from triangles" % (path, [c.type for c in cells]))
        if reader.num_steps != len(r["time_s"]):
            failures.append("%s, meshio: %d time steps, HDF5 %d" % (path, reader.num_steps, len(r["time_s"])))
        for k in range(min(reader.num_steps, len(r["time_s"]))):
            t, point_data, _ = reader.read_data(k)
            if t != r["time_s"][k]:
                failures.append("%s, meshio frame %d: time %r, HDF5 %r" % (path, k, t, r["time_s"][k]))
            for name, want in (("positions_m", r["positions_m"][k]), ("normals", r["normals"][k]),
                               ("part", r["part"][()])):
                if name not in point_data or not np.array_equal(point_data[name], want):
                    failures.append("%s, meshio frame %d: point data %s differs" % (path, k, name))


def main():
    if sys.argv[1] == "--paraview":
        paraview_side(sys.argv[2:])
        return 0
    pvbatch, folders = sys.argv[1], sys.argv[2:]
    files = sorted(os.path.abspath(p) for d in folders for p in glob.glob(os.path.join(d, "*.xdmf")))
    if not files:
        print("FAIL: no .xdmf in %s" % folders)
        return 1
    expect = {p: expected(p) for p in files}
    failures, done = [], []
    try:
        import meshio  # noqa: F401
    except ImportError as e:
        print("meshio: not installed (%s)" % e)
    else:
        done.append("meshio read %d triangle-mesh series" % check_meshio(files, expect, failures))
    if pvbatch != "-":
        done.append("pvbatch read %d files" % check_paraview(pvbatch, files, expect, failures))
    for f in failures:
        print("FAIL: " + f)
    print("; ".join(done) + (": ok" if not failures else ": %d failure(s)" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
