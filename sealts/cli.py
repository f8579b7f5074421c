"""Command line: ``sealts run [SCENE.toml] [-o OUTDIR] [--restart OUTDIR] [PETSc options ...]``.

Also ``python -m sealts``. Subcommands:

  run    run a scene (the embedded default scene without one); every option that sealts does
         not know goes to PETSc (-ts_type, -snes_monitor, -pc_type, -log_view, -help, ...);
         --restart OUTDIR goes on with the stroke or the hold of the run in OUTDIR
         (interrupted, failed or finished) from its last checkpoint (the step's start or a
         stop: output times, reversals, decades of the hold), with the same scene (its
         steering keys may change: sealts/steps/run_checkpoint.py)
  ihl    inverse-hydrodynamic estimate of a seal scene's film and leakage per stroke, from
         its dry mounted (and pressurised) contact pressure at rod.velocity
  check  validate a scene file and print nothing else
  keys   list every scene key with its unit, range and default

Exit codes: 0 success, 2 bad input (scene, files, usage, PETSc option names and values),
3 a solve that failed or a physical stop (extrusion, blow-by, a fold, a crease: printed
"physical stop (cause): ...", summary.json "stopped"), 130 / 143 stopped by SIGINT /
SIGTERM (the files written so far are closed and readable, summary.json says
"interrupted" and where).
"""
import sys
from pathlib import Path

from . import interrupt
from .scene import SceneError, default_scene, load_scene

USAGE = """usage: sealts run [SCENE.toml] [-o OUTDIR | --restart OUTDIR] [PETSc options ...]
       sealts ihl SCENE.toml [-o OUTDIR] [PETSc options ...]
       sealts check SCENE.toml
       sealts keys"""


def _split_run_args(args):
    """(scene, outdir, restart dir, PETSc args). The scene is the first argument, or the one
    ending in .toml wherever it stands; other tokens that are not options are values of the
    PETSc option before them."""
    scene, outdir, restart, petsc = None, None, None, []
    i = 0
    while i < len(args):
        a = args[i]
        if a in ("-o", "--output", "--restart"):
            if i + 1 >= len(args) or args[i + 1].startswith("-"):
                raise SceneError(f"{a} needs a directory")
            if a == "--restart":
                restart = args[i + 1]
            else:
                outdir = args[i + 1]
            i += 2
            continue
        if a.startswith("--output="):
            outdir = a.split("=", 1)[1]
        elif a.startswith("--restart="):
            restart = a.split("=", 1)[1]
        elif a.startswith("--"):
            # PETSc reads "--ts_rtol" as no option at all: the run would go on without it
            raise SceneError(f"unknown option {a.split('=', 1)[0]}: sealts run takes -o "
                             "OUTDIR and --restart OUTDIR; PETSc options take one dash "
                             f"(-{a.lstrip('-').split('=', 1)[0]})")
        elif (a.endswith(".toml") or i == 0) and not a.startswith("-"):
            if scene is not None:
                raise SceneError(f"two scene files given: {scene} and {a}")
            scene = a
        elif not a.startswith("-") and (not petsc or not petsc[-1].startswith("-")):
            raise SceneError(f"unexpected argument {a!r} (a scene file ends in .toml)")
        else:
            petsc.append(a)
        i += 1
    if restart is not None and outdir is not None and Path(outdir).resolve() != Path(
            restart).resolve():
        raise SceneError(f"--restart {restart} continues the run in {restart}; -o {outdir} "
                         "names another directory")
    return scene, restart or outdir, restart, petsc


def _prepare_outdir(out):
    """Create the output directory (every rank checks, so all fail alike under MPI)."""
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise SceneError(f"output directory {out} cannot be created ({e.strerror})") from None
    if not out.is_dir():
        raise SceneError(f"output directory {out} is not a directory")


def _init_petsc(argv, scene):
    import petsc4py
    petsc4py.init(["sealts"] + argv)
    from petsc4py import PETSc
    opts = PETSc.Options()
    for key, value in scene.petsc_options.items():
        if not opts.hasName(key):  # the command line wins
            opts[key] = value
    return PETSc


# the option prefixes of sealts' solvers (sealts.problem.Problem's ``prefix``)
SOLVER_PREFIXES = ("", "static_", "transfer_", "hold_", "stroke_", "stroke_film_",
                   "stroke_start_",
                   # the viscoelastic hold's and stroke's S (sealts.problem.condensed)
                   "hold_condensed_", "stroke_condensed_")


# sealts' own solver options (read by sealts, not by a PETSc object): name -> meaning
SEALTS_OPTIONS = {"stroke_ts_pressure_atol": "the film pressures' absolute error tolerance "
                                             "in MPa (sealts.problem.stroke_problem)"}


# the solver objects whose options sealts' solvers read when they are set up
FAMILIES = ("ts", "snes", "ksp", "pc")
# ... and options of theirs read only while solving (viewers, reports, checks) or by
# sub-solvers the check does not build
READ_LATER = ("_view", "converged_reason", "_test_", "fieldsplit", "_sub_", "redundant_")


def _check_petsc_options(PETSc, given=()):
    """Read the given options once through a TS (BDF, Newton, LU as sealts sets them up) per
    solver prefix, before the output directory is touched: an invalid value stops the run
    here, with the last run's results still in place. Then every option in ``given`` that
    names a sealts solver's TS, SNES, KSP or PC option (``-ts_...``, ``-stroke_snes_...``)
    and was not read is a misspelt name: a SceneError names it."""
    from .problem.condensed import PREFIX as CONDENSED
    opts = PETSc.Options()
    if opts.hasName("help"):
        return
    for prefix in SOLVER_PREFIXES:
        if prefix.endswith(CONDENSED):      # S's solver is a KSP alone: no TS, no SNES
            ksp = PETSc.KSP().create(comm=PETSc.COMM_SELF)
            try:
                ksp.setOptionsPrefix(prefix)
                ksp.setType(PETSc.KSP.Type.PREONLY)
                ksp.getPC().setType(PETSc.PC.Type.LU)
                ksp.setFromOptions()
            finally:
                ksp.destroy()
            continue
        ts = PETSc.TS().create(comm=PETSc.COMM_SELF)
        try:
            ts.setOptionsPrefix(prefix)
            ts.setType(PETSc.TS.Type.BDF)
            snes = ts.getSNES()
            snes.setType(PETSc.SNES.Type.NEWTONLS)
            snes.getLineSearch()
            ksp = snes.getKSP()
            ksp.setType(PETSc.KSP.Type.PREONLY)
            ksp.getPC().setType(PETSc.PC.Type.LU)
            ts.setFromOptions()
            # the event options (-ts_event_tol, -ts_event_monitor, ...) are read where a
            # problem's terms set events (sealts.problem.Problem._set_events)
            ts.setEventHandler([1], [False], lambda ts, t, U, f: None)
        finally:
            ts.destroy()
    for name, meaning in SEALTS_OPTIONS.items():
        if opts.hasName(name):
            try:
                value = opts.getReal(name)
            except PETSc.Error:
                value = None
            if value is None or not value > 0.0:
                raise SceneError(f"-{name} {opts.getString(name)!r}: {meaning} must be a "
                                 "positive number")
    for name in given:
        # read, or a deprecated name PETSc replaced by its new one (-ts_dt: -ts_time_step)
        if opts.used(name) or not opts.hasName(name):
            continue
        if any(k in name for k in READ_LATER) or name.startswith("sub_"):
            continue
        words = name.split("_")
        at = next((i for i, w in enumerate(words) if w in FAMILIES), None)
        if at is None:
            continue
        prefix = "_".join(words[:at]) + "_" if at else ""
        if prefix not in SOLVER_PREFIXES:
            raise SceneError(f"unknown PETSc option -{name}: no sealts solver has the prefix "
                             f"{prefix!r} (" + ", ".join(repr(p) for p in SOLVER_PREFIXES
                                                         if p) + ")")
        raise SceneError(f"unknown PETSc option -{name}: no sealts solver reads it "
                         "(sealts run SCENE -help lists the options)")


def run(args, command="run"):
    scene_path, outdir, restart, petsc_args = _split_run_args(args)
    if command == "ihl" and (scene_path is None or restart):
        raise SceneError("ihl needs a seal scene file" if scene_path is None
                         else "ihl has no --restart")
    scene = load_scene(scene_path) if scene_path else default_scene()
    # PETSc first: anything that imports petsc4py before (the restart's check does)
    # initialises it without the command line's options
    PETSc = _init_petsc(petsc_args, scene)
    resume = None
    if restart is not None:
        from .steps.run_checkpoint import check_restart
        resume = check_restart(restart, scene)
    out = Path(outdir) if outdir else Path("results") / (
        scene.name + ("_ihl" if command == "ihl" else ""))
    _prepare_outdir(out)
    comm = PETSc.COMM_WORLD
    if command == "ihl" and scene.model != "seal":
        raise SceneError("ihl needs a seal scene (model = \"seal\")")
    if command == "ihl" and scene.rod.velocity == 0.0:
        raise SceneError("ihl needs the stroke speed: set rod.velocity (mm/s)")
    options = PETSc.Options().getAll()
    _check_petsc_options(PETSc, given=options)
    from .io import Writer
    from .steps import run_scene
    # the files the scene reads stay, whatever an earlier run in ``out`` wrote
    inputs = [f for f in (scene.start.state, scene.stroke.table, scene.film.table,
                          scene.seal.mesh_file) if f]
    writer = Writer(out, comm, plots=scene.output.plot, keep=inputs, resume=resume is not None)
    interrupt.install()
    try:
        summary = run_scene(scene, writer, comm, command, options, resume=resume)
    finally:
        writer.close()
    if command == "ihl":
        return 0
    if comm.getRank() == 0 and scene.output.progress and "stroke" in summary:
        st = summary["stroke"]
        leak = (f"leakage {st['leakage_out']:.4g} mm^3 out at the atmosphere side (outstroke "
                f"{st['outstroke_transport']:.4g}, instroke {st['instroke_transport']:.4g})"
                if st["film"] else "dry stroke (no film)")
        print(f"{scene.name}: {leak}; peak friction {st['peak_friction_outstroke']:.4g}"
              f" N out, {st['peak_friction_instroke']:.4g} N in; min h "
              f"{st['h_min'] * 1e3:.4g} um  ({summary['wall_time_s']:.1f} s wall)")
        print(f"written: {out}/summary.json, series.csv, stroke_profiles.csv, "
              "stroke_fields.xdmf/.h5 (time series), fields.xdmf/.h5, state.h5, "
              "stroke_checkpoint.h5 (for --restart), PNG plots")
    elif comm.getRank() == 0 and scene.output.progress and scene.model == "seal":
        r = summary["results"]
        print(f"{scene.name}: contact force {r['contact_force_total']:.6g} N "
              f"({r['contact_force_per_length']:.6g} N/mm), width {r['contact_width']:.4g} mm, "
              f"peak {r['p_contact_max']:.4g} MPa  ({summary['wall_time_s']:.1f} s wall)")
        print(f"written: {out}/summary.json, profiles.csv, fields.xdmf/.h5, PNG plots")
    elif comm.getRank() == 0 and scene.output.progress:
        r = summary["results"]
        print(f"{scene.name} at t = {r['t']:.6g} s: p_max = {r['p_max']:.6g} MPa at y = {r['y_at_p_max']:.4g} mm, "
              f"load = {r['load']:.6g} N, Q_out = {r['Q_out']:.6g} mm^3/s, "
              f"friction = {r['friction_fluid']:.6g} N  "
              f"({summary['wall_time_s']:.2f} s wall)")
        print(f"written: {out}/summary.json, profiles.csv" +
              (", series.csv" if summary["analysis"] == "transient" else "") +
              (", PNG plots" if scene.output.plot else ""))
    return 0


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    if not argv or argv[0] in ("-h", "--help"):
        print(USAGE)
        return 0 if argv else 2
    cmd, rest = argv[0], argv[1:]
    if cmd in ("run", "ihl") and ("-h" in rest or "--help" in rest):
        print(f"{USAGE}\n(PETSc's own options: sealts {cmd} SCENE.toml -help)")
        return 0
    try:
        if cmd in ("run", "ihl"):
            return run(rest, cmd)
        if cmd == "check":
            if len(rest) != 1:
                raise SceneError("check takes one scene file")
            load_scene(rest[0])
            return 0
        if cmd == "keys":
            from .scene.schema import Scene
            from .scene.spec import describe
            print("\n".join(describe(Scene)))
            return 0
        raise SceneError(f"unknown command {cmd!r}\n{USAGE}")
    except SceneError as e:
        print(f"scene error: {e}", file=sys.stderr)
        return 2
    except interrupt.Interrupted as e:
        _quiet_petsc()
        print(f"stopped: {e}; what was written so far is closed and readable "
              "(summary.json: status \"interrupted\")", file=sys.stderr)
        return interrupt.EXIT_CODES.get(e.signal, 130)
    except Exception as e:  # solver failures are reported, not dumped
        from .core import PhysicalStop, SolveError
        if isinstance(e, SolveError):
            _quiet_petsc()
            # a physical stop is a result (summary.json: "stopped" and its cause), a solve
            # error a failure; both end the run with exit 3
            what = f"physical stop ({e.cause})" if isinstance(e, PhysicalStop) else "solve error"
            print(f"{what}: {e}", file=sys.stderr)
            return 3
        if type(e).__module__.startswith("petsc4py"):   # a bad option value, mostly
            _quiet_petsc()
            print(f"PETSc error: {petsc_message(e)}", file=sys.stderr)
            return 2
        raise


def _quiet_petsc():
    """A run that stopped has options it never read: PETSc need not warn about them."""
    from petsc4py import PETSc
    PETSc.Options()["options_left"] = "no"


def petsc_message(error):
    """One line from a petsc4py Error: PETSc's own last message ("Unknown TSAdapt type
    "foo" given"), without the call stack's "Function() at file:line" lines."""
    lines = [ln.split("]", 1)[-1].strip() for ln in str(error).splitlines()[1:]]
    said = [ln for ln in lines if ln and "() at " not in ln and not ln.startswith("See ")]
    return (said[-1] if said else "") + f" ({str(error).splitlines()[0]})"


if __name__ == "__main__":
    sys.exit(main())
