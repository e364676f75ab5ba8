"""Sphinx extension: resolve a reference to a re-exported name to the page that documents it.

Each object is documented once, on the page of the module that defines it
(``bearinglab.quasistatic.thrust.high_speed_analysis``), while users, docstrings and pages write the
name the package exports (``bearinglab.quasistatic.high_speed_analysis``). A Python reference that
finds no target is imported (a short name relative to the module whose docstring holds it); if it is
an object defined elsewhere, the reference goes to its definition.
"""

from __future__ import annotations

import importlib
import inspect


def _defining_name(target):
    parts = target.split(".")
    for i in range(len(parts) - 1, 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        try:
            for attr in parts[i:]:
                obj = getattr(obj, attr)
        except AttributeError:
            return None
        if inspect.ismodule(obj):
            return obj.__name__
        module, qualname = getattr(obj, "__module__", None), getattr(obj, "__qualname__", None)
        return f"{module}.{qualname}" if module and qualname else None
    return None


def _resolve(app, env, node, contnode):
    if node.get("refdomain") != "py":
        return None
    target = node.get("reftarget", "").lstrip(".~")
    if not target.startswith("bearinglab.") and node.get("py:module"):
        target = f"{node['py:module']}.{target}"  # a short name inside a module's docstring
    if not target.startswith("bearinglab."):
        return None
    name = _defining_name(target)
    if name is None or name == node["reftarget"]:
        return None
    found = env.get_domain("py").resolve_any_xref(env, node["refdoc"], app.builder, name, node, contnode)
    return found[0][1] if found else None


def setup(app):
    app.connect("missing-reference", _resolve)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
