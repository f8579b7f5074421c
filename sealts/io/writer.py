"""Run output, written as the run goes so that an interrupted run keeps what it wrote.

OUTDIR/
  summary.json   scene, wall time, step and iteration counts, key results at the end
                 (``results``) and, for transient runs, at t = 0 (``results_t0``)
  profiles.csv   long format: t, y, h, p, tau [, p_asperity, tau_solid]  (mm, MPa, s)
  series.csv     transient runs: one row per accepted step
  series.h5      the same columns as HDF5 datasets (written when the run ends, also after
                 a failure; series.csv is the record while it runs)
  hold_profiles.csv  seal scenes with a viscoelastic hold: t (s of the hold), y, h, p_contact
  stroke_profiles.csv  seal scenes with a stroke: t (s of the stroke), y, h, p, p_asperity,
                 tau, tau_solid (film pressure and shear, asperity pressure and friction)
  *profiles.png  film thickness (um), pressures and shear along y at each output time
  state.h5       seal scenes: the mounted (and pressurised) state, for [start] state of a
                 later scene
  series.png     transient runs: flows, leakage and time step over time
  manifest.json  the files this run wrote (rewritten as each new one appears)
  stroke_checkpoint.h5  seal scenes with a stroke: the state at the stroke's last stop, for
                 ``sealts run SCENE --restart OUTDIR`` (sealts/steps/run_checkpoint.py)

A new run first deletes the files an earlier run's manifest lists (and, for directories of
runs older than the manifest, the names above), except those the new scene reads (a state
file in the same directory): a directory never holds a mix of two runs' files. Every file a
run writes is named through ``path(name)``, which enters it in the manifest.

Only rank 0 writes. Rows are flushed as they come.
"""
import csv
import json
import os
from pathlib import Path

import numpy as np


# what runs wrote before the manifest existed
LEGACY = ("profiles.csv", "series.csv", "series.h5", "hold_profiles.csv", "stroke_profiles.csv",
          "ihl_profile.csv", "summary.json", "state.h5", "fields.xdmf", "fields.h5",
          "stroke_fields.xdmf", "stroke_fields.h5", "profiles.png", "hold_profiles.png",
          "stroke_profiles.png", "ihl_profile.png", "series.png")
MANIFEST = "manifest.json"


def write_h5(target, arrays, attrs):
    """An HDF5 file of named arrays and scalar attributes at ``target``, whole: written to
    a temporary file beside it and renamed into place, so a reader never sees half of it."""
    import h5py
    target = Path(target)
    tmp = target.with_name(target.name + f".{os.getpid()}.tmp")
    try:
        with h5py.File(tmp, "w") as f:
            for k, v in arrays.items():
                f.create_dataset(k, data=np.asarray(v))
            for k, v in attrs.items():
                f.attrs[k] = v
        os.replace(tmp, target)
    finally:
        tmp.unlink(missing_ok=True)


class Writer:
    def __init__(self, outdir, comm, plots=True, keep=(), resume=False):
        """``keep``: paths the run reads (a ``[start] state`` file), never deleted.
        ``resume``: the run continues the one in OUTDIR (``--restart``): its files stay, in
        the manifest; the resumed step rewrites its series and profiles from a checkpoint
        (``restore_series``, ``restore_profiles``)."""
        self.dir = Path(outdir)
        self.root = comm.getRank() == 0
        self.plots = plots
        self._files = {}
        self._profiles = {}
        self._series = []
        self.written = []
        if self.root:
            self.dir.mkdir(parents=True, exist_ok=True)
            if resume:
                self.written = self._manifest()
            else:
                self._clear(keep)
            self._save_manifest()

    def _manifest(self):
        """The files the manifest in OUTDIR lists (bare names only)."""
        try:
            old = json.loads((self.dir / MANIFEST).read_text())["files"]
            return [n for n in old if isinstance(n, str) and Path(n).name == n]
        except (OSError, ValueError, KeyError, TypeError):
            return []

    def _clear(self, keep):
        """Delete an earlier run's files (its manifest's, else the legacy names)."""
        old = self._manifest()
        keep = {Path(k).resolve() for k in keep}
        for name in set(old) | set(LEGACY):
            f = self.dir / name
            if f.resolve() not in keep:
                f.unlink(missing_ok=True)

    def _save_manifest(self):
        tmp = self.dir / (MANIFEST + ".tmp")
        tmp.write_text(json.dumps({"files": self.written}, indent=1) + "\n")
        os.replace(tmp, self.dir / MANIFEST)

    def path(self, name):
        """OUTDIR/name, entered in the manifest (rank 0)."""
        if self.root and name not in self.written:
            self.written.append(name)
            self._save_manifest()
        return self.dir / name

    def _csv(self, name, fields):
        if name not in self._files:
            f = open(self.path(name), "w", newline="")
            w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
            w.writeheader()
            self._files[name] = (f, w)
        return self._files[name]

    def profile(self, t, prof, name="profiles.csv", label=None):
        """One profile at time t (a dict of arrays along y) into the long CSV file
        ``name``; ``label`` names it in the plot (default: its time)."""
        if not self.root:
            return
        self._profiles.setdefault(name, []).append((t, prof, label))
        keys = ["t"] + list(prof)
        f, w = self._csv(name, keys)
        cols = [np.asarray(prof[k]) for k in prof]
        for i in range(cols[0].size):
            w.writerow(dict(zip(keys, [f"{t:.9g}"] + [f"{c[i]:.10g}" for c in cols])))
        f.flush()

    def series(self, row):
        if not self.root:
            return
        self._series.append(row)
        f, w = self._csv("series.csv", list(row))
        w.writerow({k: (f"{v:.10g}" if isinstance(v, float) else v) for k, v in row.items()})
        f.flush()

    def restore_series(self, rows):
        """A resumed run's rows so far: series.csv written anew from them."""
        for row in rows:
            self.series(row)

    def restore_profiles(self, name, profiles):
        """A resumed run's profiles so far, (t, profile, label) each: ``name`` anew."""
        for t, prof, label in profiles:
            self.profile(t, prof, name=name, label=label)

    def profiles_written(self, name):
        """The profiles written to ``name`` so far, (t, profile, label) each (rank 0)."""
        return list(self._profiles.get(name, []))

    @property
    def last_row(self):
        """The last series row written (None before the first)."""
        return self._series[-1] if self._series else None

    def state(self, arrays, attrs, name="state.h5"):
        """An HDF5 file of named arrays and scalar attributes, written whole (a temporary
        file renamed into place, so a reader never sees half a state)."""
        if not self.root:
            return
        write_h5(self.path(name), arrays, attrs)

    def summary(self, data):
        if not self.root:
            return
        target = self.path("summary.json")
        tmp = self.dir / "summary.json.tmp"
        tmp.write_text(json.dumps(data, indent=2) + "\n")
        os.replace(tmp, target)

    def close(self):
        if not self.root:
            return
        for f, _ in self._files.values():
            f.close()
        self._files.clear()
        if self._series:
            keys = list(self._series[0])
            self.state({k: [r.get(k, np.nan) for r in self._series] for k in keys},
                       {"columns": ",".join(keys), "units": "mm, N, s, MPa (as series.csv)"},
                       name="series.h5")
        if self.plots:
            from .plots import plot_profiles, plot_series
            for name, profiles in self._profiles.items():
                labels = [lab for _, _, lab in profiles]
                plot_profiles([(t, prof) for t, prof, _ in profiles],
                              self.path(name.replace(".csv", ".png")),
                              time_labels=labels if None not in labels else None)
            if self._series:
                plot_series(self._series, self.path("series.png"))


class NullWriter(Writer):
    """A Writer that writes nothing (steps run from tests, benchmarks and scripts)."""

    def __init__(self):
        self.dir, self.root, self.plots = Path(os.devnull), False, False
        self._files, self._profiles, self._series, self.written = {}, {}, [], []


class ProfileRecorder(NullWriter):
    """A NullWriter that keeps the profiles it is given, to hand them to a real writer
    later (``replay``): steps 1-2 run on trial meshes (``mesh.h_edge``) before the run
    knows which one it keeps."""

    def __init__(self):
        super().__init__()
        self.calls = []

    def profile(self, t, prof, name="profiles.csv", label=None):
        self.calls.append((t, prof, name, label))

    def replay(self, writer):
        for t, prof, name, label in self.calls:
            writer.profile(t, prof, name=name, label=label)
