"""The rod's axial motion in a stroke: velocity v(t) (mm/s) and displacement s(t) (mm).

Sign: v > 0 is the **outstroke**, the rod moving from the pressurised side (small y) to the
atmosphere (large y), dragging the film out of the seal; v < 0 the instroke. Laws (scene
``[stroke] velocity``):

* ``constant``:   v = v_max;
* ``ramp-hold``:  v = v_max t / t_ramp up to t_ramp, then v_max;
* ``sine``:       v = v_max sin(2 pi t / period), outstroke first (the paper's cycle:
  500 mm/s, 10 s);
* ``table``:      piecewise linear through a CSV with columns t (s), v (mm/s); constant
  beyond its ends.

``kinks`` are the times where dv/dt jumps, which the time stepper should hit exactly
(TS stops); ``reversals`` where v changes sign (ends of the strokes).
"""
import csv

import numpy as np


class RodMotion:
    def __init__(self, law, v_max=0.0, t_ramp=1.0, period=10.0, times=None, values=None):
        self.law, self.v_max, self.t_ramp, self.period = law, float(v_max), t_ramp, period
        if law == "table":
            self.times = np.asarray(times, float)
            self.values = np.asarray(values, float)
            # s at the knots: trapezoids of the piecewise-linear v
            inc = 0.5 * (self.values[1:] + self.values[:-1]) * np.diff(self.times)
            self._s = np.concatenate([[0.0], np.cumsum(inc)])
        elif law not in ("constant", "ramp-hold", "sine"):
            raise ValueError(f"unknown rod motion {law!r}")

    def v(self, t):
        if self.law == "constant":
            return self.v_max
        if self.law == "ramp-hold":
            return self.v_max * min(max(t, 0.0) / self.t_ramp, 1.0)
        if self.law == "sine":
            return self.v_max * np.sin(2 * np.pi * t / self.period)
        return float(np.interp(t, self.times, self.values))

    def s(self, t):
        """Rod displacement since t = 0 (mm), the integral of v."""
        if self.law == "constant":
            return self.v_max * t
        if self.law == "ramp-hold":
            tr = self.t_ramp
            return self.v_max * (0.5 * t * t / tr if t <= tr else t - 0.5 * tr)
        if self.law == "sine":
            w = 2 * np.pi / self.period
            return self.v_max * (1.0 - np.cos(w * t)) / w
        ts, vs = self.times, self.values
        t0 = ts[0]
        if t <= t0:
            return vs[0] * (t - t0)
        if t >= ts[-1]:
            return self._s[-1] + vs[-1] * (t - ts[-1])
        k = int(np.searchsorted(ts, t, side="right")) - 1
        dt = t - ts[k]
        slope = (vs[k + 1] - vs[k]) / (ts[k + 1] - ts[k])
        return self._s[k] + vs[k] * dt + 0.5 * slope * dt * dt

    def peak_speed(self):
        """The largest |v| of the law (mm/s), whatever the stroke's end: the sine's, the
        ramp's and the constant's v_max, the table's largest |v|."""
        if self.law == "table":
            return float(np.abs(self.values).max())
        return abs(self.v_max)

    def kinks(self, t_end):
        if self.law == "ramp-hold":
            return [self.t_ramp] if self.t_ramp < t_end else []
        if self.law == "table":
            return [float(t) for t in self.times if 0.0 < t < t_end]
        return []

    def reversals(self, t_end):
        if self.law == "sine":
            half = 0.5 * self.period
            return [k * half for k in range(1, int(t_end / half) + 1) if k * half < t_end]
        if self.law == "table":
            v = self.values
            k = np.nonzero(v[:-1] * v[1:] < 0.0)[0]
            t = self.times
            return [float(t[i] - v[i] * (t[i + 1] - t[i]) / (v[i + 1] - v[i])) for i in k]
        return []


def read_velocity_table(path):
    """(t, v) from a CSV with a header naming columns t and v; t must increase. Raises
    ValueError naming the problem."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or not {"t", "v"} <= set(rows[0]):
        raise ValueError(f"{path}: needs a header with columns t (s) and v (mm/s)")
    try:
        t = np.array([float(r["t"]) for r in rows])
        v = np.array([float(r["v"]) for r in rows])
    except (TypeError, ValueError):
        raise ValueError(f"{path}: t and v must be numbers") from None
    if t.size < 2 or np.any(np.diff(t) <= 0.0):
        raise ValueError(f"{path}: t must increase, with at least two rows")
    return t, v


def motion_from_scene(stroke):
    """The RodMotion of a scene's ``[stroke]`` section (its table path already resolved)."""
    if stroke.velocity == "table":
        t, v = read_velocity_table(stroke.table)
        return RodMotion("table", times=t, values=v)
    return RodMotion(stroke.velocity, stroke.v_max, stroke.t_ramp, stroke.period)
