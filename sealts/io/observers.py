"""Outputs as observers of a Problem's post-step (:class:`sealts.core.Observer`).

A step attaches the observers it wants to its problem's run: a series row per accepted
step built from column sources, a progress line, profiles and fields at the output times
(``Recorder``, in memory, is :class:`sealts.core.Recorder`). A new output is one observer; a
new series column is one source (a callable ``source(t, u, info, row) -> dict`` that sees
the columns before it) in a step's list.
"""
from ..core import Observer


def at_times(times, t, rtol=1e-9):
    """Whether t is one of ``times`` (None: every time), to round-off."""
    return times is None or any(abs(t - w) <= rtol * max(1.0, abs(w)) for w in times)


class Series(Observer):
    """One row per accepted step into series.csv / series.h5: "t", then each source's
    columns in turn. ``line(row, info)``: a progress line printed through ``say``."""

    def __init__(self, writer, sources, say=None, line=None):
        if (say is None) != (line is None):
            raise ValueError("a progress line needs both say and line")
        self.writer, self.sources = writer, list(sources)
        self.say, self.line = say, line
        self.rows = []

    def accepted(self, t, u, info):
        row = {"t": t}
        for source in self.sources:
            row.update(source(t, u, info, row))
        self.rows.append(row)
        self.writer.series(row)
        if self.line is not None and self.say.due():
            self.say(self.line(row, info))


class StepLine:
    """A series row's progress line: "<label> <step>  t = .. s  dt = .. s" and the
    ``columns`` as (name, key, scale, unit): ("min h", "h_min", 1e3, "um")."""

    def __init__(self, label, columns=()):
        self.label, self.columns = label, list(columns)

    def __call__(self, row, info):
        extra = "".join(f"  {name} = {row[key] * scale:.4g}{' ' + unit if unit else ''}"
                        for name, key, scale, unit in self.columns)
        return (f"{self.label} {info.step:5d}  t = {row['t']:.5g} s  dt = {info.dt:.3g} s"
                + extra)


def solver_columns(t, u, info, row):
    """The step size that comes next (s) and the Newton iterations so far in this run."""
    return {"dt": info.dt, "newton": info.newton}


class Profiles(Observer):
    """Profiles along y at the stop times (only those in ``times``, if given, and then at
    the start too if it is one of them) into the long CSV file ``name``:
    ``profile(t, u) -> dict of arrays``."""

    def __init__(self, writer, profile, name="profiles.csv", times=None, say=None):
        self.writer, self.profile, self.name, self.times = writer, profile, name, times
        self.say = say

    def start(self, t, u):
        if self.times is not None:
            self.stop(t, u)

    def stop(self, t, u):
        if at_times(self.times, t):
            self.writer.profile(t, self.profile(t, u), name=self.name)
            if self.say is not None:
                self.say(f"output at t = {t:.6g} s", force=True)


class Fields(Observer):
    """Fields on the seal's mesh at the start and the stop times in ``times`` into one XDMF
    + HDF5 time series (:class:`sealts.io.fields.FieldSeries`): ``fields(t, u) ->
    (point_data, cell_data)``."""

    def __init__(self, series, fields, times):
        self.series, self.fields, self.times = series, fields, times

    def start(self, t, u):
        self.stop(t, u)

    def stop(self, t, u):
        if at_times(self.times, t) and self.series.root:
            self.series.add(t, *self.fields(t, u))

    def close(self):
        self.series.close()
