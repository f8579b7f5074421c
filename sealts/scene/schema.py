"""The scene: what to simulate, in mm, N, s, MPa.

Every key, its unit, range and meaning is listed by ``sealts keys`` (generated from the
declarations below); ``configs/*.toml`` are worked examples. A scene may carry PETSc options
in a ``[petsc]`` table (``ts_type = "bdf"`` for ``-ts_type bdf``); options given on the
command line win over it.
"""
import tomllib
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path

from ..film.flow_factors import PATIR_CHENG_GAMMAS, tabulated_gamma
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
    symmetry: str = option("planar", choices=("planar", "axisymmetric"),
                           doc="area factor of Eq. 31: width (planar) or 2 pi rod.radius")
    width: float = option(1.0, unit="mm", gt=0.0, doc="film depth of a planar scene")


@dataclass(frozen=True)
class Fluid:
    viscosity: float = option(1e-8, unit="MPa s", gt=0.0, doc="dynamic viscosity eta")
    p_in: float = option(0.0, unit="MPa", doc="pressure at y = 0 (sealed, pressurised side)")
    p_out: float = option(0.0, unit="MPa", doc="pressure at y = l (atmosphere side)")


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
    flow_factors: str = option("none", choices=("none", "patir-cheng", "table"),
                               doc="pressure/shear flow factors")
    rq: float = option(0.0, unit="mm", ge=0.0, doc="composite RMS roughness Rq (Eq. 14)")
    gamma: float = option(1.0, gt=0.0,
                          doc="Peklenik number for patir-cheng: 1/9, 1/6, 1/3, 1, 3, 6 or 9")
    table: str = option("", doc="CSV with columns h [mm], phi_p, phi_s (flow_factors = table)")
    h_floor: float = option(1e-5, unit="mm", ge=0.0,
                            doc="gap regularisation: the film conducts as if h >= h_floor")


@dataclass(frozen=True)
class Asperity:
    enabled: bool = option(False, doc="report asperity pressure and solid friction")
    h_mix: float = option(7e-4, unit="mm", gt=0.0, doc="onset of asperity contact (Eq. 44)")
    p_mix: float = option(15.0, unit="MPa", gt=0.0, doc="asperity pressure at h = 0 (Eq. 44)")
    mu_s: float = option(0.1, ge=0.0, doc="solid friction coefficient (Eq. 46)")


@dataclass(frozen=True)
class Output:
    plot: bool = option(True, doc="write PNG plots")
    progress: bool = option(True, doc="print t, dt and Newton iterations while running")


@dataclass(frozen=True)
class Scene:
    name: str = option("scene", doc="scene name, used in output")
    description: str = option("", doc="free text")
    model: str = option("film", choices=("film",), doc="film: a film on a rigid gap")
    analysis: Analysis = option(Analysis(), doc="steady or transient, times")
    gap: Gap = option(Gap(), doc="rigid gap geometry of a film-only scene")
    fluid: Fluid = option(Fluid(), doc="fluid and boundary pressures")
    rod: Rod = option(Rod(), doc="rod motion and size")
    film: Film = option(Film(), doc="film discretisation and flow factors")
    asperity: Asperity = option(Asperity(), doc="asperity contact law")
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


def _check_consistency(s, base):
    """Cross-key checks: things each key allows alone but not together."""
    a, g, f = s.analysis, s.gap, s.film
    if a.type == "transient":
        late = [t for t in a.output_times if t > a.t_end]
        if late:
            raise SceneError(f"analysis.output_times has {late[0]:g} s after "
                             f"analysis.t_end = {a.t_end:g} s")
        if a.dt > a.t_end:
            raise SceneError(f"analysis.dt = {a.dt:g} s exceeds analysis.t_end = {a.t_end:g} s")
    t_last = a.t_end if a.type == "transient" else a.time
    if g.h_min + g.squeeze_velocity * t_last <= 0.0:
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
        path = Path(f.table) if Path(f.table).is_absolute() else base / f.table
        if not path.is_file():
            raise SceneError(f"film.table: no such file {path}")


def parse_scene(text, source="<string>", base=None):
    """Parse and validate scene TOML text; raise SceneError naming the offending key."""
    try:
        table = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise SceneError(f"{source}: not valid TOML: {e}") from None
    return scene_from_table(table, source, base)


def scene_from_table(table, source="<table>", base=None):
    """Validate an already parsed TOML table (a dict) into a Scene."""
    table = dict(table)
    petsc = _check_petsc(table.pop("petsc", {}))
    table.pop("source", None)
    scene = build(Scene, table)
    base = Path(base) if base is not None else Path.cwd()
    _check_consistency(scene, base)
    film = scene.film
    if film.table and not Path(film.table).is_absolute():
        film = _replace(film, table=str((base / film.table).resolve()))
    return _replace(scene, petsc=petsc, source=source, film=film)


def _replace(obj, **kw):
    import dataclasses
    return dataclasses.replace(obj, **kw)


def load_scene(path):
    """Load a scene file; a missing file is a SceneError too."""
    path = Path(path)
    if not path.is_file():
        raise SceneError(f"scene file not found: {path}")
    return parse_scene(path.read_text(), source=str(path), base=path.parent)


def default_scene():
    """The embedded default scene (the paper's slider bearing until the O-ring exists)."""
    text = resources.files("sealts.data").joinpath("slider.toml").read_text()
    return parse_scene(text, source="<embedded slider>")
