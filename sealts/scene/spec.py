"""A small declarative checker: dataclass fields carry their unit, range and choices.

``option(default, unit=..., gt=..., ge=..., le=..., choices=..., doc=...)`` declares a field;
:func:`build` turns a TOML table into the dataclass, rejecting unknown keys, wrong types and
out-of-range values with a :class:`SceneError` that names the dotted key.
"""
import dataclasses
import difflib
import math
import typing

from .errors import SceneError


def option(default, *, unit="", gt=None, ge=None, lt=None, le=None, choices=None, doc=""):
    meta = dict(unit=unit, gt=gt, ge=ge, lt=lt, le=le, choices=choices, doc=doc)
    if isinstance(default, (list, dict)):
        return dataclasses.field(default_factory=lambda: type(default)(default), metadata=meta)
    return dataclasses.field(default=default, metadata=meta)


def _type_name(tp):
    return {float: "a number", int: "an integer", bool: "true or false", str: "a string"}.get(
        tp, getattr(tp, "__name__", str(tp)))


def _convert(value, tp, key):
    origin = typing.get_origin(tp)
    if origin is list:
        (item,) = typing.get_args(tp)
        if not isinstance(value, list):
            raise SceneError(f"{key} must be a list of {_type_name(item)}s (got {value!r})")
        return tuple(_convert(v, item, f"{key}[{i}]") for i, v in enumerate(value))
    if tp is float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise SceneError(f"{key} must be a number (got {value!r})")
        if not math.isfinite(value):
            raise SceneError(f"{key} must be a finite number (got {value!r})")
        return float(value)
    if tp is int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise SceneError(f"{key} must be an integer (got {value!r})")
        return value
    if tp is bool or tp is str:
        if not isinstance(value, tp):
            raise SceneError(f"{key} must be {_type_name(tp)} (got {value!r})")
        return value
    if dataclasses.is_dataclass(tp):
        return build(tp, value, key)
    return value


def _check_range(v, meta, key):
    unit = f" {meta['unit']}" if meta.get("unit") else ""
    for name, op, ok in (("gt", ">", lambda a, b: a > b), ("ge", ">=", lambda a, b: a >= b),
                         ("lt", "<", lambda a, b: a < b), ("le", "<=", lambda a, b: a <= b)):
        bound = meta.get(name)
        if bound is None:
            continue
        items = v if isinstance(v, tuple) else (v,)
        for x in items:
            if not ok(x, bound):
                raise SceneError(f"{key} must be {op} {bound:g}{unit} (got {x:g})")
    choices = meta.get("choices")
    if choices and v not in choices:
        raise SceneError(f"{key} must be one of {', '.join(map(repr, choices))} (got {v!r})")


def build(cls, table, prefix=""):
    """Instantiate dataclass ``cls`` from a TOML table, validating every key."""
    where = prefix or "scene"
    if not isinstance(table, dict):
        raise SceneError(f"{where} must be a table (got {table!r})")
    hints = typing.get_type_hints(cls)
    fields = {f.name: f for f in dataclasses.fields(cls)}
    for k in table:
        if k not in fields:
            near = difflib.get_close_matches(k, fields, n=1)
            hint = f"; did you mean {near[0]!r}?" if near else ""
            key = f"{prefix}.{k}" if prefix else k
            raise SceneError(f"unknown key {key}{hint}")
    values = {}
    for name, f in fields.items():
        if name not in table:
            continue
        key = f"{prefix}.{name}" if prefix else name
        v = _convert(table[name], hints[name], key)
        _check_range(v, f.metadata, key)
        values[name] = v
    return cls(**values)


def describe(cls, prefix=""):
    """Lines documenting every key of ``cls``: name, default, unit, range and meaning."""
    lines = []
    hints = typing.get_type_hints(cls)
    for f in dataclasses.fields(cls):
        key = f"{prefix}.{f.name}" if prefix else f.name
        tp = hints[f.name]
        if dataclasses.is_dataclass(tp):
            lines.append(f"[{key}]  {f.metadata.get('doc', '')}".rstrip())
            lines += describe(tp, key)
            continue
        m = f.metadata
        default = f.default if f.default is not dataclasses.MISSING else f.default_factory()
        extra = [m.get("unit") or ""]
        for name, op in (("gt", ">"), ("ge", ">="), ("lt", "<"), ("le", "<=")):
            if m.get(name) is not None:
                extra.append(f"{op} {m[name]:g}")
        if m.get("choices"):
            extra.append("|".join(m["choices"]))
        extra = ", ".join(e for e in extra if e)
        lines.append(f"  {key} = {default!r}  ({extra})  {m.get('doc', '')}".rstrip())
    return lines
