"""A sealts output directory read back into numpy arrays.

The files are those of :mod:`sealts.io.writer` (``summary.json``, ``series.csv`` /
``series.h5``, the long-format profile CSVs) and the XDMF + HDF5 fields: ``fields.xdmf``
(meshio, the final state of a seal run) and ``stroke_fields.xdmf`` (:mod:`sealts.io.fields`,
a time series)::

    r = Results("results/oring_stroke")
    r.summary["stroke"]["leakage_out"]            # summary.json as written
    r.series["Q_out"]                             # one value per accepted step
    P = r.profiles("stroke_profiles", sort_by="y")  # {t: {"y": ..., "h": ..., "p": ...}}
    f = r.fields("stroke_fields")                 # f.times, f.point_data["displacement"][k]

A file that is not there raises :class:`MissingOutput`, which names it. Importing this module
loads numpy, csv, json and xml only; h5py is imported when an HDF5 file is read.
"""
import csv
import json
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import numpy as np


class MissingOutput(FileNotFoundError):
    """An output file (or directory) that is not there: the run did not write it, or not yet.
    ``path`` is the file."""

    def __init__(self, path, why="no such file"):
        self.path = Path(path)
        super().__init__(f"sealts output {self.path}: {why}")


def _need(path):
    path = Path(path)
    if not path.is_file():
        raise MissingOutput(path)
    return path


def read_summary(path):
    """``summary.json`` as a dict, as written (units in its ``units`` entries)."""
    return json.loads(_need(path).read_text())


def read_table(path):
    """(column names, values) of a CSV written by sealts: a header line, then rows of numbers;
    values is an n_rows x n_columns float array. A row of the wrong length or a value that is
    not a number raises ValueError naming the file and line."""
    path = _need(path)
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty, no header line")
    head, body = rows[0], rows[1:]
    values = np.empty((len(body), len(head)))
    for i, row in enumerate(body):
        if len(row) != len(head):
            raise ValueError(f"{path}, line {i + 2}: {len(row)} values for the "
                             f"{len(head)} columns {','.join(head)}")
        try:
            values[i] = [float(x) for x in row]
        except ValueError:
            raise ValueError(f"{path}, line {i + 2}: not all numbers: {','.join(row)}") from None
    return head, values


def read_series(path):
    """{column: array over the accepted steps} of ``series.csv`` or ``series.h5`` (by the
    suffix), columns in the order written."""
    path = Path(path)
    if path.suffix == ".h5":
        import h5py
        with h5py.File(_need(path), "r") as f:
            names = f.attrs["columns"].split(",")
            return {k: np.asarray(f[k][:], float) for k in names}
    head, values = read_table(path)
    return {k: values[:, j] for j, k in enumerate(head)}


def read_profiles(path, sort_by=None):
    """{t: {column: array}} of a long-format profile CSV (``profiles.csv``,
    ``stroke_profiles.csv``, ``hold_profiles.csv``, ``ihl_profile.csv``): one entry per
    block of rows with the same t, in the order written, the node order of the file (the
    rod-side chain) unless ``sort_by`` names a column to sort each block by (e.g. "y"). A
    time written in two blocks keeps the last (the writers write each output time once)."""
    head, values = read_table(path)
    if "t" not in head:
        raise ValueError(f"{path}: no t column, not a profile file")
    k = head.index("t")
    t = values[:, k]
    out = {}
    if t.size == 0:
        return out
    starts = np.flatnonzero(np.r_[True, t[1:] != t[:-1]])
    for rows in np.split(np.arange(t.size), starts[1:]):
        block = {name: values[rows, j] for j, name in enumerate(head) if j != k}
        if sort_by is not None:
            if sort_by not in block:
                raise ValueError(f"{path}: no column {sort_by!r} to sort by")
            order = np.argsort(block[sort_by], kind="stable")
            block = {name: v[order] for name, v in block.items()}
        out[float(t[rows[0]])] = block
    return out


@dataclass(frozen=True)
class Fields:
    """Fields on the seal mesh at one or more times.

    points: (n_nodes, 3) reference coordinates (r, z, 0), mm; cells: (n_cells, 4) node
    indices of the quadrilaterals; times: (n_steps,) s, NaN for a file without times (the
    single state of ``fields.xdmf``); point_data / cell_data: {name: array} stacked over
    the steps, (n_steps, n_nodes[, k]) and (n_steps, n_cells)."""
    points: np.ndarray
    cells: np.ndarray
    times: np.ndarray
    point_data: dict
    cell_data: dict

    def __len__(self):
        return self.times.size


def _data_item(item, base, files):
    """The array of an XDMF DataItem: HDF (``file.h5:/path`` beside the XDMF) or XML."""
    fmt = item.get("Format", "XML")
    text = (item.text or "").strip()
    if fmt == "HDF":
        name, _, inner = text.rpartition(":")
        if name not in files:
            import h5py
            files[name] = h5py.File(_need(base / name), "r")
        return np.asarray(files[name][inner][()])
    if fmt == "XML":
        dims = [int(d) for d in item.get("Dimensions", "").split()]
        return np.array(text.split(), float).reshape(dims or -1)
    raise ValueError(f"XDMF DataItem format {fmt!r} is not read (HDF or XML)")


def read_fields(path):
    """The :class:`Fields` of an XDMF file (``fields.xdmf``, ``stroke_fields.xdmf``): every
    uniform grid is one step, the mesh is the first grid's (both writers write one mesh)."""
    path = _need(path)
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        raise ValueError(f"{path}: not XDMF ({e})") from None
    grids = [g for g in root.iter("Grid") if g.get("GridType", "Uniform") == "Uniform"]
    if not grids:
        raise ValueError(f"{path}: no grid")
    files = {}
    try:
        points = _data_item(grids[0].find("Geometry/DataItem"), path.parent, files)
        cells = _data_item(grids[0].find("Topology/DataItem"), path.parent, files).astype(np.int64)
        times, steps = [], {"Node": [], "Cell": []}
        for g in grids:
            t = g.find("Time")
            times.append(float(t.get("Value")) if t is not None else np.nan)
            data = {"Node": {}, "Cell": {}}
            for a in g.findall("Attribute"):
                center = a.get("Center", "Node")
                if center not in data:
                    raise ValueError(f"{path}: {a.get('Name')} is on {center}s, not nodes or cells")
                data[center][a.get("Name")] = _data_item(a.find("DataItem"), path.parent, files)
            for center in steps:
                steps[center].append(data[center])
    finally:
        for f in files.values():
            f.close()

    def stacked(per_step):
        names = set().union(*per_step)
        if any(set(d) != names for d in per_step):
            raise ValueError(f"{path}: the steps carry different fields")
        return {n: np.stack([d[n] for d in per_step]) for n in per_step[0]}

    return Fields(points, cells, np.array(times), stacked(steps["Node"]), stacked(steps["Cell"]))


class Results:
    """One output directory: ``summary`` and ``series`` (read on first use), ``profiles(name)``
    and ``fields(name)``; names with or without the suffix ("stroke_profiles",
    "ihl_profile.csv", "stroke_fields")."""

    def __init__(self, outdir):
        self.dir = Path(outdir)
        if not self.dir.is_dir():
            raise MissingOutput(self.dir, "no such output directory")

    def path(self, name, suffix):
        """The file ``name`` in the directory, with ``suffix`` unless it has one."""
        return self.dir / (name if Path(name).suffix else name + suffix)

    @cached_property
    def summary(self):
        return read_summary(self.dir / "summary.json")

    @cached_property
    def series(self):
        """series.csv (the record while a run goes), or series.h5 where there is no CSV."""
        csv_path = self.dir / "series.csv"
        if csv_path.is_file() or not (self.dir / "series.h5").is_file():
            return read_series(csv_path)
        return read_series(self.dir / "series.h5")

    def profiles(self, name="profiles", sort_by=None):
        return read_profiles(self.path(name, ".csv"), sort_by)

    def fields(self, name="fields"):
        return read_fields(self.path(name, ".xdmf"))
