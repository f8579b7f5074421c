"""The scene: what to simulate, in mm, N, s, MPa.

Every key, its unit, range and meaning is listed by ``sealts keys`` (generated from the
declarations below); ``configs/*.toml`` are worked examples. A scene may carry PETSc options
in a ``[petsc]`` table (``ts_type = "bdf"`` for ``-ts_type bdf``); options given on the
command line win over it.
"""
import tomllib
from dataclasses import dataclass, field, replace
from importlib import resources
from pathlib import Path

import numpy as np

from ..film.floor import mean_gap_at_contact, roughness
from ..film.flow_factor_tables import PATIR_CHENG_GAMMAS, read_table, tabulated_gamma
from ..mesh.seal_mesh import REFINE_GROWTH
from .errors import SceneError
from .spec import build, option


@dataclass(frozen=True)
class Analysis:
    type: str = option("steady", choices=("steady", "transient"),
                       doc="steady: one Reynolds solution at `time`; transient: TS from 0 to t_end")
    time: float = option(0.0, unit="s", ge=0.0, doc="time of the steady snapshot")
    t_end: float = option(1.0, unit="s", gt=0.0, doc="end time of a transient run")
    dt: float = option(1e-3, unit="s", gt=0.0, doc="initial time step (TS adapts it)")
    output_times: list[float] = option([], unit="s", gt=0.0,
                                       doc="times of profile output; t_end is always written")


@dataclass(frozen=True)
class Gap:
    length: float = option(10.0, unit="mm", gt=0.0, doc="film length l along y")
    h_min: float = option(1e-3, unit="mm", gt=0.0, doc="gap at the thin end y = l, t = 0")
    s_h: float = option(0.0, unit="mm", ge=0.0, doc="taper: gap at y = 0 is h_min + s_h")
    squeeze_velocity: float = option(0.0, unit="mm/s", doc="dh/dt of the whole gap (du/dt)")
    tilt_rate: float = option(0.0, unit="mm/s",
                              doc="squeeze rate varies by this much from y = 0 to y = l")
    symmetry: str = option("planar", choices=("planar", "axisymmetric"),
                           doc="area factor of Eq. 31: width (planar) or 2 pi rod.radius")
    width: float = option(1.0, unit="mm", gt=0.0, doc="film depth of a planar scene")


@dataclass(frozen=True)
class Fluid:
    viscosity: float = option(1e-8, unit="MPa s", gt=0.0, doc="dynamic viscosity eta")
    p_in: float = option(0.0, unit="MPa", doc="gauge pressure at y = 0 (sealed, pressurised side)")
    p_out: float = option(0.0, unit="MPa", doc="gauge pressure at y = l (atmosphere side); on "
                                                "a seal a back pressure (double-acting)")
    p_crit: float = option(0.1, unit="MPa", ge=0.0,
                           doc="model = seal: pressure penetration stops where the seal "
                               "presses on a wall by more than the fluid pressure + p_crit")


@dataclass(frozen=True)
class Rod:
    velocity: float = option(0.0, unit="mm/s", doc="rod velocity v, +y from p_in to p_out side")
    radius: float = option(25.0, unit="mm", gt=0.0, doc="rod radius r (axisymmetric area)")


@dataclass(frozen=True)
class Film:
    scheme: str = option("fv", choices=("fv", "paper"),
                         doc="fv: mass-conserving control volumes; paper: Eq. 15-28 with c0, y0")
    elements: int = option(1000, ge=2, doc="film elements along y")
    alpha: float = option(0.5, ge=0.0, le=1.0, doc="paper scheme: gradient weight (Eq. 27)")
    beta: float = option(0.5, ge=0.0, le=1.0, doc="weight of the squeeze-rate gradient (Eq. 33)")
    squeeze: bool = option(True, doc="carry the squeeze term dh/dt of Eq. 13")
    upwind: bool = option(True, doc="fv scheme on a seal: upwind the Couette flow where the "
                          "gap's node-to-node mode is advection-dominated (element Peclet "
                          "number with the seal's modulus, sealts.film.reynolds_fv)")
    flow_factors: str = option("none", choices=("none", "patir-cheng", "table"),
                               doc="pressure/shear flow factors")
    rq: float = option(0.0, unit="mm", ge=0.0, doc="composite RMS roughness Rq (Eq. 14)")
    gamma: float = option(1.0, gt=0.0,
                          doc="Peklenik number for patir-cheng: 1/9, 1/6, 1/3, 1, 3, 6 or 9")
    table: str = option("", doc="CSV with columns h [mm], phi_p, phi_s (flow_factors = table)")
    rough_surface: str = option("seal", choices=("seal", "rod"),
                                doc="which surface carries Rq: sign of the Phi_s term")
    h_floor: float = option(0.0, unit="mm", ge=0.0,
                            doc="gap regularisation: the film conducts as if h >= h_floor; "
                                "0: Rq / sqrt(2 pi), the mean gap of rough surfaces in "
                                "contact, Rq of the asperity law "
                                "(0.086 um for the paper's O-ring; sealts.film.floor)")


@dataclass(frozen=True)
class Asperity:
    enabled: bool = option(False, doc="report asperity pressure and solid friction")
    law: str = option("exponential", choices=("exponential", "greenwood-williamson"),
                      doc="exponential: the paper's Eq. 44 (h_mix, p_mix); "
                          "greenwood-williamson: Gaussian summits, Greenwood and Williamson "
                          "1966 (summit_density, summit_radius, summit_sigma, modulus)")
    h_mix: float = option(7e-4, unit="mm", gt=0.0, doc="onset of asperity contact (Eq. 44)")
    p_mix: float = option(15.0, unit="MPa", gt=0.0, doc="asperity pressure at h = 0 (Eq. 44)")
    summit_density: float = option(1e4, unit="1/mm^2", gt=0.0,
                                   doc="greenwood-williamson: summits per area eta_s; "
                                       "typically 1e3-1e5 /mm^2, with eta_s beta sigma_s "
                                       "0.03-0.05 (Greenwood and Tripp 1970)")
    summit_radius: float = option(0.02, unit="mm", gt=0.0,
                                  doc="greenwood-williamson: summit radius beta; typically "
                                      "0.01-0.1 mm for ground and honed steel")
    summit_sigma: float = option(2.15e-4, unit="mm", gt=0.0,
                                 doc="greenwood-williamson: deviation of the summit heights "
                                     "sigma_s; about Rq (the paper's 0.215 um, Table 3)")
    modulus: float = option(0.0, unit="MPa", ge=0.0,
                            doc="greenwood-williamson: composite modulus E'; 0 takes the "
                                "seal's E/(1 - nu^2) against a rigid rod (4 G for rubber)")
    mu_s: float = option(0.1, ge=0.0, doc="solid friction coefficient (Eq. 46)")


@dataclass(frozen=True)
class Seal:
    shape: str = option("oring", choices=("oring", "rectangle", "file"),
                        doc="seal cross-section (file: seal.mesh_file)")
    mesh_file: str = option("", doc="shape = 'file': gmsh .msh or .geo, quads, physical curves "
                                    "rod_side, pressure_side, groove, atmosphere_side")
    d1: float = option(50.17, unit="mm", gt=0.0, doc="O-ring inner diameter")
    d2: float = option(5.33, unit="mm", gt=0.0, doc="O-ring cord diameter")
    width: float = option(2.0, unit="mm", gt=0.0, doc="rectangle: axial width")
    height: float = option(2.0, unit="mm", gt=0.0, doc="rectangle: radial height")
    inner_diameter: float = option(50.0, unit="mm", gt=0.0, doc="rectangle: inner diameter")
    corner_radius: float = option(0.0, unit="mm", ge=0.0,
                                  doc="rectangle: radius of the two corners on the rod side, "
                                      "part of the rod side (0: sharp, the rod side then "
                                      "runs 0.1 mm up the side faces)")
    symmetry: str = option("axisymmetric", choices=("axisymmetric", "planar"),
                           doc="axisymmetric ring or plane strain (per mm of depth)")
    self_contact: str = option("auto", choices=("auto", "on", "off"),
                               doc="the surface against itself (a crease closing on itself); "
                                   "auto: on from 10 MPa sealed (p_in or hold.p_end) or back "
                                   "pressure")


@dataclass(frozen=True)
class Groove:
    diameter: float = option(59.4, unit="mm", gt=0.0, doc="groove (bottom) diameter dG")
    width: float = option(5.6, unit="mm", gt=0.0, doc="groove width b between side walls")
    corner_radius: float = option(0.0, unit="mm", ge=0.0,
                                  doc="radius of the two bottom corners (0: sharp)")
    mu: float = option(0.1, ge=0.0, doc="friction coefficient of the groove walls (stroke "
                                        "with friction; elastic slip stroke.gamma_crit)")
    clearance: float = option(0.0, unit="mm", ge=0.0,
                              doc="extrusion gap: radial clearance between the rod and the "
                                  "bore where the side walls end (0: walls down to the rod)")
    edge_radius: float = option(0.1, unit="mm", ge=0.0,
                                doc="radius of the side walls' edges at the extrusion gap "
                                    "(clearance > 0)")
    extrusion_limit: float = option(0.25, unit="mm", gt=0.0,
                                    doc="a run stops once the seal has flowed this far past "
                                        "a side wall into the extrusion gap (clearance > 0)")


@dataclass(frozen=True)
class Material:
    model: str = option("neo-hooke", choices=("neo-hooke", "mooney-rivlin"),
                        doc="hyperelastic law (Eq. 1; Mooney-Rivlin adds C01 (I2bar - 3))")
    c10: float = option(1.064, unit="MPa", gt=0.0, doc="C10 (G = 2 (C10 + C01))")
    c01: float = option(0.0, unit="MPa", ge=0.0, doc="Mooney-Rivlin C01 (mooney-rivlin only)")
    d1: float = option(0.001, unit="mm^2/N", gt=0.0, doc="compressibility D1 (K = 2/D1)")
    alpha_th: float = option(0.0, unit="1/K", ge=0.0, doc="thermal expansion (Eq. 3-5)")
    temperature_rise: float = option(0.0, unit="K", doc="temperature above the reference")


@dataclass(frozen=True)
class Mesh:
    h_contact: float = option(0.01, unit="mm", gt=0.0, doc="element size along the rod side")
    h_bulk: float = option(0.05, unit="mm", gt=0.0, doc="element size in the bulk")
    grading_distance: float = option(0.5, unit="mm", gt=0.0,
                                     doc="distance over which sizes grow to h_bulk")
    layer_depth: float = option(0.0, unit="mm", ge=0.0,
                                doc="depth beneath the rod side meshed at h_contact before "
                                    "the grading starts (resolves the solid under the "
                                    "contact's inlet and outlet; 0: grading from the surface)")
    h_edge: float = option(0.0, unit="mm", ge=0.0,
                           doc="element size at the pressurised contact's two edges, the "
                               "film's inlets: steps 1-2 run on the mesh above first to find "
                               "them and their end state is carried to the refined mesh (0: "
                               "off; README, 'Where gmsh puts the nodes')")
    edge_span: float = option(0.08, unit="mm", gt=0.0,
                              doc="how far along the rod side to either side of each edge "
                                  "the size is h_edge")
    cache: str = option("meshes", doc="mesh cache directory (relative to the working dir)")
    symmetric: bool = option(False, doc="mesh half the cross-section and mirror it about the "
                                        "groove's mid-plane, so the mesh is mirror-symmetric "
                                        "node for node (oring, rectangle)")


@dataclass(frozen=True)
class Mount:
    t_hold: float = option(2.0, gt=1.0, doc="pseudo-time of the hold after the ramp (ramp: 0..1)")
    dt: float = option(0.02, gt=0.0, doc="first pseudo-time step")
    stabilisation: float = option(1e-3, unit="MPa s/mm^2", ge=0.0,
                                  doc="viscous stabilisation c of rigid-body modes in steps "
                                      "1-2; the pressurised front is c's limit c -> 0 up to "
                                      "1e-3 (1e-4 gives the same), from 3e-3 on it settles "
                                      "elsewhere (+8 % net leakage on the default cycle: "
                                      "benchmarks/stroke_sensitivity.md)")
    penalty: float = option(1e4, unit="MPa/mm", gt=0.0, doc="groove wall penalty stiffness")


@dataclass(frozen=True)
class Viscoelastic:
    prony: str = option("none", choices=("none", "table2", "custom"),
                        doc="shear relaxation (Eq. 7-9): none (long-term only), the paper's "
                            "Table 2 (EPDM), or custom prony_g / prony_tau")
    prony_g: list[float] = option([], gt=0.0, doc="custom: Prony weights g_i (sum below 1)")
    prony_tau: list[float] = option([], unit="s", gt=0.0,
                                    doc="custom: relaxation times tau_i at theta_0")
    temperature: float = option(25.0, unit="C", doc="seal temperature theta (WLF shift)")
    temperature_times: list[float] = option([], unit="s", ge=0.0,
                                            doc="times of a temperature history in the hold "
                                                "(piecewise linear; replaces temperature)")
    temperature_values: list[float] = option([], unit="C",
                                             doc="temperatures at temperature_times")
    theta_0: float = option(25.0, unit="C", doc="reference temperature of the tau_i")
    wlf_c1: float = option(7.69, doc="WLF C1 (Eq. 12; Table 2 value)")
    wlf_c2: float = option(157.74, unit="K", gt=0.0, doc="WLF C2 (Eq. 12; Table 2 value)")
    t_min: float = option(1e-3, unit="s", gt=0.0,
                          doc="shortest time over which the loading changes: terms much "
                              "faster are folded in as relaxed")
    tol: float = option(1e-2, gt=0.0, le=1.0,
                        doc="relative error of the relaxation modulus that folding Prony "
                            "terms (relaxed / frozen) may cause over [t_min, hold.t_end]")


@dataclass(frozen=True)
class Hold:
    p_end: float = option(0.0, unit="MPa", doc="step 3: sealed pressure stepped to from "
                                                "fluid.p_in, then held (0: no hold step)")
    t_ramp: float = option(1e-3, unit="s", gt=0.0, doc="duration of the pressure step")
    t_end: float = option(1e6, unit="s", gt=0.0, doc="end of the hold")
    dt: float = option(1e-5, unit="s", gt=0.0, doc="first time step (TS adapts it)")
    rtol: float = option(1e-4, gt=0.0, doc="TS relative error tolerance of the hold")


@dataclass(frozen=True)
class Stroke:
    velocity: str = option("none", choices=("none", "constant", "ramp-hold", "sine", "table"),
                           doc="step 3: the rod's velocity law in the stroke (none: no stroke); "
                               "+ is the outstroke, from the pressurised side out")
    v_max: float = option(500.0, unit="mm/s",
                          doc="constant speed, ramp-hold end speed or sine amplitude")
    t_ramp: float = option(1.0, unit="s", gt=0.0, doc="ramp-hold: time to reach v_max")
    period: float = option(10.0, unit="s", gt=0.0, doc="sine: period of one cycle")
    table: str = option("", doc="velocity = 'table': CSV with columns t (s) and v (mm/s)")
    t_end: float = option(10.0, unit="s", gt=0.0, doc="end of the stroke step")
    dt: float = option(1e-4, unit="s", gt=0.0, doc="first time step (TS adapts it)")
    rtol: float = option(1e-2, gt=0.0, doc="TS relative error tolerance of the stroke (the "
                                          "time error at 1e-2 is some 100 times below the "
                                          "default mesh's: benchmarks/work_precision.md)")
    output_times: list[float] = option([], unit="s", gt=0.0,
                                       doc="times of profile output; t_end is always written")
    friction: bool = option(True, doc="solid friction: mu_s p_s on the rod (Eq. 46-48) "
                                      "and groove.mu on the groove walls")
    film: bool = option(True, doc="the Reynolds film on the rod side (false: dry contact, "
                                  "no film or leakage unknowns)")
    gamma_crit: float = option(1e-4, unit="mm", gt=0.0,
                               doc="elastic slip at which solid friction reaches mu_s p_s")
    friction_history: str = option(
        "state", choices=("state", "anchors"),
        doc="the solid friction's history on the rod and the groove walls: state, the "
            "rod's elastic slips and the walls' anchors as TS unknowns with a viscoplastic "
            "return past gamma_crit, under TS error control "
            "(sealts/contact/slip_state_friction.py, groove_slip_state.py); anchors, moved "
            "after each accepted step (the paper's return mapping, outside the error "
            "estimate)")
    stabilisation: float = option(0.0, unit="MPa s/mm^2", ge=0.0,
                                  doc="viscous force c V_i u_i' on the seal's nodes (0: none): "
                                      "gives a snap of the quasi-static seal (a fold of its "
                                      "equilibrium path) a finite speed; 1e-3 carries the "
                                      "10 MPa O-ring through its snap; its largest share of "
                                      "the normal load is the summary's stabilisation_share")
    snap_stabilisation: float = option(1e-3, unit="MPa s/mm^2", ge=0.0,
                                       doc="c from the first snap on (steps stuck at TS's "
                                           "minimum; the summary's snapped_at), for the rest "
                                           "of the run, if above stroke.stabilisation; 0: "
                                           "a snap stops the run")
    front: str = option("moving", choices=("moving", "kept"),
                        doc="the pressure-penetration front during the stroke: moving, set "
                            "to where the seal's traction puts it at located TS events "
                            "(sealts/solid/moving_front.py); kept, where steps 1-2 left it")
    front_tolerance: float = option(0.1, unit="edges", gt=0.0,
                                    doc="front = moving: the drift between a front and where "
                                        "the seal's traction puts it at which it follows "
                                        "(boundary edges)")


@dataclass(frozen=True)
class Start:
    state: str = option("", doc="model = seal: start from a state.h5 written by an earlier run "
                                "(its mounted and pressurised seal) instead of steps 1-2")
    cache: bool = option(True, doc="model = seal: keep the state of steps 1-2 under "
                                   "<mesh.cache>/states and reuse it in a later run with "
                                   "the same inputs and code (sealts/steps/state_cache.py)")


@dataclass(frozen=True)
class Output:
    plot: bool = option(True, doc="write PNG plots")
    progress: bool = option(True, doc="print t, dt and Newton iterations while running")


@dataclass(frozen=True)
class Scene:
    name: str = option("scene", doc="scene name, used in output")
    description: str = option("", doc="free text")
    model: str = option("film", choices=("film", "seal"),
                        doc="film: a film on a rigid gap; seal: the seal mounted in its groove")
    analysis: Analysis = option(Analysis(), doc="steady or transient, times")
    gap: Gap = option(Gap(), doc="rigid gap geometry of a film-only scene")
    fluid: Fluid = option(Fluid(), doc="fluid and boundary pressures")
    rod: Rod = option(Rod(), doc="rod motion and size")
    film: Film = option(Film(), doc="film discretisation and flow factors")
    asperity: Asperity = option(Asperity(), doc="asperity contact law")
    seal: Seal = option(Seal(), doc="seal cross-section (model = seal)")
    groove: Groove = option(Groove(), doc="rigid rod groove (model = seal)")
    material: Material = option(Material(), doc="seal material, long-term (model = seal)")
    mesh: Mesh = option(Mesh(), doc="seal mesh sizes (model = seal)")
    mount: Mount = option(Mount(), doc="mounting step (model = seal)")
    viscoelastic: Viscoelastic = option(Viscoelastic(),
                                        doc="Prony series and WLF shift (model = seal)")
    hold: Hold = option(Hold(), doc="viscoelastic pressure step and hold (model = seal)")
    stroke: Stroke = option(Stroke(), doc="transient stroke with the film (model = seal)")
    start: Start = option(Start(), doc="restart from a saved state (model = seal)")
    output: Output = option(Output(), doc="what to write")
    petsc: dict = field(default_factory=dict, metadata=dict(doc="default PETSc options"))
    source: str = field(default="<embedded>", metadata=dict(doc="where the scene came from"))

    @property
    def petsc_options(self):
        return dict(self.petsc)


def _check_petsc(table):
    if not isinstance(table, dict):
        raise SceneError(f"petsc must be a table of options (got {table!r})")
    out = {}
    for k, v in table.items():
        if isinstance(v, bool):
            v = "true" if v else "false"
        elif isinstance(v, (int, float)):
            v = repr(v)
        elif not isinstance(v, str):
            raise SceneError(f"petsc.{k} must be a string, number or boolean (got {v!r})")
        out[k.lstrip("-")] = v
    return out


MAX_MESH_NODES = 1_000_000     # 2e6 unknowns: a direct LU of that needs tens of GiB
MAX_FILM_ELEMENTS = 10_000_000


def _check_sizes(s):
    """Sizes that would not fit the machine, refused before anything is meshed: the seal
    mesh's node count estimated as its section over h_bulk^2 plus the graded band along
    the rod side over h_contact^2 (a tenth of the perimeter times grading_distance: the
    0.025 / 0.2 O-ring mesh gives 1,900 for its 1,411 nodes; plus a quarter of the perimeter
    times layer_depth; plus mesh.h_edge's refinement), and the film's element count; the
    key that contributes most is named."""
    if s.model == "film":
        if s.film.elements > MAX_FILM_ELEMENTS:
            raise SceneError(f"film.elements = {s.film.elements:,}: more than "
                             f"{MAX_FILM_ELEMENTS:,} film elements will not fit this machine")
        return
    sl, m = s.seal, s.mesh
    if sl.shape == "file":
        return
    if sl.shape == "oring":
        area, perimeter, size = np.pi * sl.d2 ** 2 / 4, np.pi * sl.d2, sl.d2
    else:
        area, perimeter = sl.width * sl.height, 2 * (sl.width + sl.height)
        size = min(sl.width, sl.height)
    bulk = area / m.h_bulk ** 2
    band = perimeter * (0.25 * min(m.layer_depth, size) + 0.1 * min(m.grading_distance, size)) \
        / m.h_contact ** 2
    # mesh.h_edge: two edges, each a refined span (size h_edge + g d at distance d, g the
    # mesh's REFINE_GROWTH) and the fan around its ends
    g = REFINE_GROWTH
    edges = (2 * (2 * m.edge_span / (g * m.h_edge)
                  + np.pi / g ** 2 * np.log(max(m.h_contact / m.h_edge, 1.0)))
             if m.h_edge > 0.0 else 0.0)
    nodes = bulk + band + edges
    if nodes > MAX_MESH_NODES:
        parts = {"mesh.h_bulk": (bulk, m.h_bulk), "mesh.h_contact": (band, m.h_contact),
                 "mesh.h_edge": (edges, m.h_edge)}
        key = max(parts, key=lambda k: parts[k][0])
        raise SceneError(f"{key} = {parts[key][1]:g} mm: about {nodes:.2g} mesh nodes, more "
                         f"than {MAX_MESH_NODES:,} will not fit this machine")


def _check_seal_geometry(s, base):
    """Impossible seal geometry: each key fine alone, not together."""
    sl, gr, rod = s.seal, s.groove, s.rod
    if 2 * rod.radius >= gr.diameter:
        raise SceneError(f"rod.radius = {rod.radius:g} mm: the rod diameter must be below "
                         f"groove.diameter = {gr.diameter:g} mm")
    space = 0.5 * gr.diameter - rod.radius
    if gr.corner_radius >= min(0.5 * gr.width, space):
        raise SceneError(f"groove.corner_radius = {gr.corner_radius:g} mm must be below half "
                         f"the groove width and the groove depth {space:g} mm")
    if gr.clearance > 0.0 and gr.clearance + gr.edge_radius + gr.corner_radius >= space:
        raise SceneError(f"groove.clearance = {gr.clearance:g} mm with edge_radius "
                         f"{gr.edge_radius:g} and corner_radius {gr.corner_radius:g} mm must "
                         f"leave room in the groove depth {space:g} mm")
    if sl.corner_radius and sl.shape != "rectangle":
        raise SceneError(f"seal.corner_radius is the rectangle's (seal.shape is {sl.shape!r})")
    if sl.shape == "file":
        if not sl.mesh_file:
            raise SceneError("seal.mesh_file must name a .msh or .geo file with "
                             "seal.shape = 'file'")
        _check_file("seal.mesh_file", sl.mesh_file, base)
        if Path(sl.mesh_file).suffix not in (".msh", ".geo"):
            raise SceneError(f"seal.mesh_file = {sl.mesh_file}: must be a .msh or .geo file")
        if s.mesh.symmetric:
            raise SceneError("mesh.symmetric = true needs a built-in seal.shape ('oring' or "
                             "'rectangle'); a mesh file is used as it is")
        if s.mesh.h_edge:
            raise SceneError("mesh.h_edge needs a built-in seal.shape ('oring' or "
                             "'rectangle'); a mesh file is used as it is")
        return   # the rest is checked on the mesh itself (sealts.problem.seal_model)
    if sl.mesh_file:
        raise SceneError(f"seal.mesh_file is only used with seal.shape = 'file' "
                         f"(shape is {sl.shape!r})")
    if sl.shape == "oring":
        if sl.d2 >= gr.width:
            raise SceneError(f"seal.d2 = {sl.d2:g} mm: the cord must be narrower than "
                             f"groove.width = {gr.width:g} mm")
        inner, radial = 0.5 * sl.d1, sl.d2
    else:
        if sl.corner_radius == 0.0 and s.film.scheme == "paper":
            raise SceneError("film.scheme = 'paper' integrates dp/dy over the rod side's axial "
                             "positions, which a sharp-cornered ring's rod side repeats up its "
                             "side faces: use film.scheme = 'fv' or seal.corner_radius > 0")
        if sl.corner_radius >= 0.5 * min(sl.width, sl.height):
            raise SceneError(f"seal.corner_radius = {sl.corner_radius:g} mm must be below half "
                             f"the rectangle's width and height")
        if sl.width >= gr.width:
            raise SceneError(f"seal.width = {sl.width:g} mm must be below "
                             f"groove.width = {gr.width:g} mm")
        inner, radial = 0.5 * sl.inner_diameter, sl.height
    if radial > 1.35 * space:
        raise SceneError(f"seal: radial size {radial:g} mm squeezed into {space:g} mm "
                         f"(over 35 % squeeze) cannot be mounted")
    if inner + radial <= rod.radius or inner >= 0.5 * gr.diameter:
        raise SceneError("seal: the cross-section does not lie between rod and groove bottom")
    m = s.mesh
    if m.h_contact > m.h_bulk:
        raise SceneError(f"mesh.h_contact = {m.h_contact:g} mm must not exceed "
                         f"mesh.h_bulk = {m.h_bulk:g} mm")
    if m.h_edge > 0.0 and m.h_edge >= m.h_contact:
        raise SceneError(f"mesh.h_edge = {m.h_edge:g} mm must be below "
                         f"mesh.h_contact = {m.h_contact:g} mm (0: no refinement)")
    if m.h_edge > 0.0 and m.symmetric:
        raise SceneError("mesh.h_edge refines at the contact's edges, which are not "
                         "mirror images: it needs mesh.symmetric = false")


def _check_viscoelastic(s):
    ve, hold = s.viscoelastic, s.hold
    if ve.prony == "custom":
        g, tau = ve.prony_g, ve.prony_tau
        if not g or len(g) != len(tau):
            raise SceneError("viscoelastic.prony_g and prony_tau must be lists of the same "
                             f"non-zero length with prony = 'custom' (got {len(g)} and "
                             f"{len(tau)})")
        if sum(g) >= 1.0:
            raise SceneError(f"viscoelastic.prony_g must sum to below 1 (got {sum(g):.6g})")
    elif ve.prony_g or ve.prony_tau:
        raise SceneError("viscoelastic.prony_g / prony_tau are only used with "
                         f"prony = 'custom' (prony is {ve.prony!r})")
    if len(ve.temperature_times) != len(ve.temperature_values):
        raise SceneError("viscoelastic.temperature_times and temperature_values must have "
                         f"the same length (got {len(ve.temperature_times)} and "
                         f"{len(ve.temperature_values)})")
    if any(b <= a for a, b in zip(ve.temperature_times, ve.temperature_times[1:])):
        raise SceneError("viscoelastic.temperature_times must increase")
    for theta in [ve.temperature] + list(ve.temperature_values):
        if ve.wlf_c2 + theta - ve.theta_0 <= 0.0:
            raise SceneError(f"viscoelastic.temperature {theta:g} C is below the WLF range "
                             f"(theta_0 - C2 = {ve.theta_0 - ve.wlf_c2:g} C)")
    if hold.p_end != 0.0:
        if ve.prony == "none":
            raise SceneError("hold.p_end needs a viscoelastic material: set "
                             "viscoelastic.prony")
        if s.fluid.p_in == 0.0:
            raise SceneError("hold.p_end needs the pressurised state: set fluid.p_in")
        if hold.t_ramp >= hold.t_end or ve.t_min > hold.t_end:
            raise SceneError(f"hold.t_ramp = {hold.t_ramp:g} s and viscoelastic.t_min = "
                             f"{ve.t_min:g} s must lie below hold.t_end = {hold.t_end:g} s")


def _check_file(key, name, base, reader=None):
    """A file named by a scene key (relative to the scene's directory) exists and, with a
    ``reader``, reads (its ValueError becomes the one-line error)."""
    path = Path(name) if Path(name).is_absolute() else base / name
    if not path.is_file():
        raise SceneError(f"{key}: no such file {path}")
    if reader is not None:
        try:
            reader(path)
        except ValueError as e:
            raise SceneError(f"{key}: {e}") from None


def _check_stroke(s, base):
    st = s.stroke
    if st.velocity == "none":
        return
    if s.hold.p_end != 0.0:
        raise SceneError("stroke.velocity and hold.p_end: a scene runs either the stroke or "
                         "the pressure hold as its step 3")
    late = [t for t in st.output_times if t > st.t_end]
    if late:
        raise SceneError(f"stroke.output_times has {late[0]:g} s after stroke.t_end = "
                         f"{st.t_end:g} s")
    if st.dt >= st.t_end:
        raise SceneError(f"stroke.dt = {st.dt:g} s must be below stroke.t_end = {st.t_end:g} s")
    if st.velocity == "table":
        from ..contact.rod_motion import read_velocity_table
        if not st.table:
            raise SceneError("stroke.table must name a CSV file with stroke.velocity = 'table'")
        _check_file("stroke.table", st.table, base, read_velocity_table)
    elif st.table:
        raise SceneError(f"stroke.table is only used with stroke.velocity = 'table' "
                         f"(velocity is {st.velocity!r})")


GW_KEYS = ("summit_density", "summit_radius", "summit_sigma", "modulus")


def _check_asperity(s):
    """Keys of the law that is not chosen are an error (they would be ignored)."""
    a, default = s.asperity, Asperity()
    if a.law != "greenwood-williamson":
        for key in GW_KEYS:
            if getattr(a, key) != getattr(default, key):
                raise SceneError(f"asperity.{key} is only used with asperity.law = "
                                 f"'greenwood-williamson' (law is {a.law!r})")
    elif s.model == "film" and a.modulus == 0.0:
        raise SceneError("asperity.modulus must be > 0 MPa with asperity.law = "
                         "'greenwood-williamson' in a film scene (no seal material to take "
                         "it from)")


def _check_consistency(s, base):
    """Cross-key checks: things each key allows alone but not together."""
    _check_asperity(s)
    _check_sizes(s)
    if s.model == "seal":
        _check_seal_geometry(s, base)
        mat = s.material
        if mat.model == "neo-hooke" and mat.c01 != 0.0:
            raise SceneError(f"material.c01 = {mat.c01:g} MPa needs material.model = "
                             "'mooney-rivlin' (Neo-Hooke has no C01)")
        if mat.model == "mooney-rivlin" and mat.c01 <= 0.0:
            raise SceneError("material.c01 must be > 0 MPa with material.model = "
                             "'mooney-rivlin'")
        _check_viscoelastic(s)
        _check_stroke(s, base)
        from ..units import P_VACUUM
        for key, p in (("fluid.p_in", s.fluid.p_in), ("fluid.p_out", s.fluid.p_out),
                       ("hold.p_end", s.hold.p_end)):
            if p < P_VACUUM:
                raise SceneError(f"{key} = {p:g} MPa is below vacuum ({P_VACUUM:g} MPa): "
                                 "pressures are gauge pressures, above the atmosphere's")
        if s.start.state:
            _check_file("start.state", s.start.state, base)
        return
    a, g, f = s.analysis, s.gap, s.film
    if a.type == "transient":
        late = [t for t in a.output_times if t > a.t_end]
        if late:
            raise SceneError(f"analysis.output_times has {late[0]:g} s after "
                             f"analysis.t_end = {a.t_end:g} s")
        if a.dt > a.t_end:
            raise SceneError(f"analysis.dt = {a.dt:g} s exceeds analysis.t_end = {a.t_end:g} s")
    t_last = a.t_end if a.type == "transient" else a.time
    # the gap is linear in y and t: its minimum is at an end, at t = 0 or t_last
    ends = (g.h_min + g.s_h + (g.squeeze_velocity - 0.5 * g.tilt_rate) * t_last,
            g.h_min + (g.squeeze_velocity + 0.5 * g.tilt_rate) * t_last)
    if min(ends) <= 0.0:
        raise SceneError(f"gap.squeeze_velocity = {g.squeeze_velocity:g} mm/s closes the gap "
                         f"(h_min = {g.h_min:g} mm) before t = {t_last:g} s")
    if f.flow_factors == "patir-cheng":
        if f.rq <= 0.0:
            raise SceneError("film.rq must be > 0 mm with film.flow_factors = 'patir-cheng'")
        if tabulated_gamma(f.gamma) is None:
            allowed = ", ".join(f"{x:.4g}" for x in PATIR_CHENG_GAMMAS)
            raise SceneError(f"film.gamma must be one of {allowed} (got {f.gamma:g})")
    if f.flow_factors == "table":
        if not f.table:
            raise SceneError("film.table must name a CSV file with film.flow_factors = 'table'")
        _check_file("film.table", f.table, base, read_table)


def parse_scene(text, source="<string>", base=None):
    """Parse and validate scene TOML text; raise SceneError naming the offending key."""
    try:
        table = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise SceneError(f"{source}: not valid TOML: {e}") from None
    return scene_from_table(table, source, base)


# the sections each model reads (the top-level keys name, description, model, petsc too)
SECTIONS = {
    "film": {"analysis", "gap", "fluid", "rod", "film", "asperity", "output"},
    "seal": {"fluid", "rod", "film", "asperity", "seal", "groove", "material", "mesh",
             "mount", "viscoelastic", "hold", "stroke", "start", "output"},
}


def _check_sections(scene, table):
    """A section the scene's model never reads is an error, not silently ignored."""
    tables = {k for k, v in table.items() if isinstance(v, dict)}
    for sec in sorted(tables - SECTIONS[scene.model]):
        other = next(m for m in SECTIONS if m != scene.model)
        hint = (f"; it belongs to model = '{other}'" if sec in SECTIONS[other] else "")
        raise SceneError(f"[{sec}] is not read by a model = '{scene.model}' scene{hint}")


def scene_from_table(table, source="<table>", base=None):
    """Validate an already parsed TOML table (a dict) into a Scene."""
    table = dict(table)
    petsc = _check_petsc(table.pop("petsc", {}))
    table.pop("source", None)
    scene = build(Scene, table)
    _check_sections(scene, table)
    base = Path(base) if base is not None else Path.cwd()
    _check_consistency(scene, base)

    def resolved(section, key):
        """The section with its file key made absolute (relative to the scene's dir)."""
        name = getattr(section, key)
        if not name or Path(name).is_absolute():
            return section
        return replace(section, **{key: str((base / name).resolve())})

    film, seal = resolved(scene.film, "table"), resolved(scene.seal, "mesh_file")
    if film.h_floor == 0.0:
        a = scene.asperity
        film = replace(film, h_floor=mean_gap_at_contact(
            roughness(a.law, a.h_mix, a.summit_sigma)))
    stroke, start = resolved(scene.stroke, "table"), resolved(scene.start, "state")
    return replace(scene, petsc=petsc, source=source, film=film, seal=seal, stroke=stroke,
                   start=start)


def load_scene(path):
    """Load a scene file; a missing file is a SceneError too."""
    path = Path(path)
    if path.is_dir():
        raise SceneError(f"scene file {path} is a directory")
    if not path.is_file():
        raise SceneError(f"scene file not found: {path}")
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise SceneError(f"scene file {path} cannot be read as UTF-8 text ({e})") from None
    return parse_scene(text, source=str(path), base=path.parent)


def default_scene():
    """The embedded default scene: the paper's O-ring cycle, a copy of
    ``configs/oring_stroke.toml`` (tests/test_scene.py keeps the two identical)."""
    text = resources.files("sealts.data").joinpath("oring_stroke.toml").read_text()
    return parse_scene(text, source="<embedded oring_stroke>")
