"""``sealts ihl SCENE``: the inverse-hydrodynamic film estimate of a seal scene.

Mounts the seal dry (and pressurises it when fluid.p_in is set) exactly as ``sealts run``
does, takes the normal traction along the rod side, the asperity contact pressure plus the
fluid pressure on the wetted share of each node, and applies :mod:`sealts.film.ihl` at the
rod speed |rod.velocity|: outstroke (+y, from the pressurised side to the atmosphere) and
instroke. Writes ``ihl_profile.csv`` (y, h, p_contact, p_fluid, p, dp/dy) and
``summary.json``; prints the films and the volumes carried per mm of stroke.
"""
import time

import numpy as np

from ..film.ihl import ihl_estimate, pressure_gradient
from ..scene import SceneError
from .seal_run import model_from_scene


def run_ihl(scene, writer, comm):
    from .film_run import Progress
    if scene.model != "seal":
        raise SceneError("ihl needs a seal scene (model = \"seal\")")
    speed = abs(scene.rod.velocity)
    if speed == 0.0:
        raise SceneError("ihl needs the stroke speed: set rod.velocity (mm/s)")
    t_wall = time.perf_counter()
    say = Progress(comm, scene.output.progress)
    model = model_from_scene(scene)
    mount = scene.mount
    say(f"mesh: {model.mesh.X.shape[0]} nodes; mounting dry", force=True)
    u = model.mount(t_hold=mount.t_hold, dt0=mount.dt, comm=comm)
    t = mount.t_hold
    chain = model.mesh.chain("rod_side")
    p_fluid = np.zeros(chain.size)
    if scene.fluid.p_in != 0.0:
        say(f"pressurising to {scene.fluid.p_in:g} MPa", force=True)
        u = model.pressurise(u, scene.fluid.p_in, t0=t, t_hold=2 * t, dt0=mount.dt,
                             comm=comm, p_crit=scene.fluid.p_crit)
        t = 2 * t
        p_fluid = model.load.wet_share()[chain] * model.load.pressure(t)
    y, h, p_contact = model.contact_profile(t, u)
    order = np.argsort(y)
    y, h, p_contact, p_fluid = y[order], h[order], p_contact[order], p_fluid[order]
    p = p_contact + p_fluid
    area = 2 * np.pi * model.r_rod_final if model.axisym else 1.0
    try:
        est = ihl_estimate(y, p, scene.fluid.viscosity, speed, area)
    except ValueError as e:
        raise SceneError(f"ihl: {e}") from None
    writer.profile(0.0, {"y": y, "h": h, "p_contact": p_contact, "p_fluid": p_fluid, "p": p,
                         "dp_dy": pressure_gradient(y, p)}, name="ihl_profile.csv")
    summary = {"scene": scene.name, "source": scene.source, "analysis": "ihl",
               "p_in": scene.fluid.p_in, "viscosity": scene.fluid.viscosity,
               "wall_time_s": time.perf_counter() - t_wall, "ihl": est,
               "units": {"length": "mm", "pressure": "MPa", "speed": "mm/s",
                         "volume_per_mm_stroke": "mm^3/mm"}}
    writer.summary(summary)
    o, i = est["outstroke"], est["instroke"]
    say(f"IHL at {speed:g} mm/s, eta = {scene.fluid.viscosity:g} MPa s:\n"
        f"  outstroke  h* = {o['h_star'] * 1e3:.4g} um  (inlet rise {o['w']:.4g} MPa/mm "
        f"at y = {o['y_w']:.4g} mm)\n"
        f"  instroke   h* = {i['h_star'] * 1e3:.4g} um  (inlet rise {i['w']:.4g} MPa/mm "
        f"at y = {i['y_w']:.4g} mm)\n"
        f"  per mm of stroke: {est['volume_out_per_mm_stroke']:.4g} mm^3 out, "
        f"{est['volume_in_per_mm_stroke']:.4g} mm^3 back, net "
        f"{est['net_leakage_per_mm_stroke']:.4g} mm^3", force=True)
    return summary
