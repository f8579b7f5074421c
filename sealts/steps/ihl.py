"""The inverse-hydrodynamic film estimate (``sealts ihl``) of a mounted (and pressurised)
seal, as a step after steps 1-2.

Takes the normal traction along the rod side, the asperity contact pressure plus the fluid
pressure on the wetted share of each node, and applies :mod:`sealts.film.ihl` at the rod
speed |rod.velocity|: outstroke (+y, from the pressurised side to the atmosphere) and
instroke. Writes ``ihl_profile.csv`` (y, h, p_contact, p_fluid, p, dp/dy); the estimate is
the summary's ``ihl`` block.
"""
import numpy as np

from ..film.ihl import ihl_estimate, pressure_gradient
from .base import Step


class Ihl(Step):
    name = "ihl"

    def run(self, state):
        from ..scene import SceneError
        model, scene, t, u = state.model, state.scene, state.t, state.u
        speed = abs(scene.rod.velocity)
        if scene.seal.shape == "rectangle" and scene.seal.corner_radius == 0.0:
            raise SceneError("ihl: the dry profile's dp/dy is taken over the rod side's axial "
                             "positions, which a sharp-cornered ring's rod side repeats up its "
                             "side faces: round its corners (seal.corner_radius > 0)")
        chain = model.mesh.chain("rod_side")
        p_fluid = np.zeros(chain.size)
        if state.load is not None:
            p_fluid = state.load.fluid_share(t)[chain]
        y, h, p_contact = model.contact_profile(t, u)
        order = np.argsort(y)
        y, h, p_contact, p_fluid = y[order], h[order], p_contact[order], p_fluid[order]
        p = p_contact + p_fluid
        area = 2 * np.pi * model.r_rod_final if model.axisym else 1.0
        try:
            est = ihl_estimate(y, p, scene.fluid.viscosity, speed, area)
        except ValueError as e:
            raise SceneError(f"ihl: {e}") from None
        state.writer.profile(0.0, {"y": y, "h": h, "p_contact": p_contact, "p_fluid": p_fluid,
                                   "p": p, "dp_dy": pressure_gradient(y, p)},
                             name="ihl_profile.csv")
        state.parts["ihl"] = est
        o, i = est["outstroke"], est["instroke"]
        state.say(f"IHL at {speed:g} mm/s, eta = {scene.fluid.viscosity:g} MPa s:\n"
                  f"  outstroke  h* = {o['h_star'] * 1e3:.4g} um  (inlet rise {o['w']:.4g} "
                  f"MPa/mm at y = {o['y_w']:.4g} mm)\n"
                  f"  instroke   h* = {i['h_star'] * 1e3:.4g} um  (inlet rise {i['w']:.4g} "
                  f"MPa/mm at y = {i['y_w']:.4g} mm)\n"
                  f"  per mm of stroke: {est['volume_out_per_mm_stroke']:.4g} mm^3 out, "
                  f"{est['volume_in_per_mm_stroke']:.4g} mm^3 back, net "
                  f"{est['net_leakage_per_mm_stroke']:.4g} mm^3", force=True)
