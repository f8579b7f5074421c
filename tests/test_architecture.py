"""The package's layering (docs/design.md), checked on its source.

* No import cycle between sealts modules: a graph built from every module's syntax tree,
  imports inside functions included, has no strongly connected component of more than one
  module (Tarjan's algorithm) and no module importing itself.
* ``sealts check`` and ``sealts keys`` load neither petsc4py nor numba: the scene schema
  and the core (terms, constraints, counters) do not need them.
* The pseudo-time protocol of steps 1-2 is spelled out in sealts/steps alone: no other
  module, test or script names mount.t_hold (the scene key's declaration aside).
"""
import ast
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "sealts"


def modules(root=PACKAGE):
    """{dotted module name: path} of every .py file of the package."""
    out = {}
    for path in root.rglob("*.py"):
        parts = list(path.relative_to(root.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def import_graph(mods):
    """{module: set of sealts modules it imports}, from the syntax trees (every Import and
    ImportFrom node, at any depth). ``from P import name`` is an edge to the module P.name
    where that is a module, else to P."""
    graph = {}
    for name, path in mods.items():
        is_pkg = path.name == "__init__.py"
        package = name if is_pkg else name.rpartition(".")[0]
        edges = set()
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.split(".")
                    base = base[:len(base) - (node.level - 1)]
                    mod = ".".join(base + ([node.module] if node.module else []))
                else:
                    mod = node.module or ""
                targets = [f"{mod}.{a.name}" if f"{mod}.{a.name}" in mods else mod
                           for a in node.names]
            else:
                continue
            edges |= {t for t in targets if t in mods}
        if is_pkg:
            edges.discard(name)     # "from . import x" in a package: not a cycle
        graph[name] = edges
    return graph


def cycles(graph):
    """The strongly connected components of more than one module, and self-loops."""
    index, low, stack, on, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1 or v in graph.get(v, ()):
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in graph:
        if v not in index:
            visit(v)
    return out


def test_no_import_cycle_between_sealts_modules():
    graph = import_graph(modules())
    assert "sealts.steps" in graph["sealts.cli"]          # imported inside run()
    assert cycles(graph) == []


def test_the_cycle_finder_finds_a_cycle_through_a_function_level_import(tmp_path):
    """The checker itself: two modules importing each other, one of them inside a
    function, are one cycle; a package importing its own submodule is none."""
    pkg = tmp_path / "sealts"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text("from .a import f\n")
    (pkg / "a.py").write_text("from .sub import b\n\ndef f():\n    pass\n")
    (pkg / "sub" / "__init__.py").write_text("")
    (pkg / "sub" / "b.py").write_text("def g():\n    from ..a import f\n    return f\n")
    mods = modules(pkg)
    assert cycles(import_graph(mods)) == [["sealts.a", "sealts.sub.b"]]
    (pkg / "sub" / "b.py").write_text("def g():\n    from .. import core\n")
    (pkg / "core.py").write_text("import numpy\n")
    assert cycles(import_graph(modules(pkg))) == []


def test_check_and_keys_load_neither_petsc_nor_numba():
    code = ("import sys\nfrom sealts.cli import main\n"
            f"assert main(['check', {str(ROOT / 'configs' / 'oring_stroke.toml')!r}]) == 0\n"
            f"assert main(['check', {str(ROOT / 'configs' / 'paper_fig11_flowfactors.toml')!r}])"
            " == 0\n"
            "assert main(['keys']) == 0\n"
            "print(sorted({m.split('.')[0] for m in sys.modules} & {'petsc4py', 'numba'}))\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines()[-1] == "[]"


def test_the_pseudo_time_protocol_is_named_in_the_steps_alone():
    spelled = []
    for folder in ("sealts", "tests", "scripts"):
        for path in (ROOT / folder).rglob("*.py"):
            rel = path.relative_to(ROOT).as_posix()
            if rel.startswith("sealts/steps/") or rel == "sealts/scene/schema.py":
                continue
            if path.name == Path(__file__).name:
                continue
            if re.search(r"\bt_hold\b", path.read_text()):
                spelled.append(rel)
    assert spelled == []
