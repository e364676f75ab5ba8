"""The public names of every module, pinned: a refactor may add names, never lose one.

``tests/data/public_api.json`` is the register of public names as of the architecture refactor (issue
10). A name that moved keeps working from its old module (re-exported, or as a deprecation alias), so
each pinned name must still be reachable there. New modules and packages must define ``__all__``.
"""

import importlib
import json
import pkgutil
import warnings
from pathlib import Path

import pytest

import bearinglab

PINNED = json.loads((Path(__file__).parent / "data" / "public_api.json").read_text(encoding="utf-8"))


def _public_modules():
    names = ["bearinglab"]
    for info in pkgutil.walk_packages(bearinglab.__path__, "bearinglab."):
        if not any(part.startswith("_") for part in info.name.split(".")[1:]):
            names.append(info.name)
    return names


@pytest.mark.parametrize("module", sorted(PINNED))
def test_pinned_public_names_still_reachable(module):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        try:
            mod = importlib.import_module(module)
        except ModuleNotFoundError:  # a module that moved answers as an attribute of its old package
            parent, _, last = module.rpartition(".")
            mod = getattr(importlib.import_module(parent), last)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)  # a renamed name may answer through an alias
        missing = [name for name in PINNED[module] if not hasattr(mod, name)]
    assert not missing, f"{module} lost public names {missing}"


@pytest.mark.parametrize("module", _public_modules())
def test_every_public_module_declares_all(module):
    mod = importlib.import_module(module)
    assert isinstance(getattr(mod, "__all__", None), (list, tuple)), f"{module} has no __all__"
    for name in mod.__all__:
        assert hasattr(mod, name), f"{module}.__all__ names {name!r}, which it does not define"


def test_private_names_stay_out_of_all():
    for module in _public_modules():
        mod = importlib.import_module(module)
        leaked = [n for n in mod.__all__ if n.startswith("_") and n != "__version__"]
        assert not leaked, f"{module}.__all__ exports private names {leaked}"


def test_every_public_module_is_registered():
    # a new public module joins the register, so that its names are pinned from then on
    unregistered = sorted(set(_public_modules()) - set(PINNED))
    assert not unregistered, (f"public modules missing from tests/data/public_api.json: {unregistered}; "
                              "run `python tests/test_public_api.py --update` and review the diff")


def _update():
    """Add every public module's current ``__all__`` to the register (names are only ever added)."""
    register = {m: list(names) for m, names in PINNED.items()}
    for module in _public_modules():
        names = set(register.get(module, [])) | set(importlib.import_module(module).__all__)
        register[module] = sorted(names)
    path = Path(__file__).parent / "data" / "public_api.json"
    path.write_text(json.dumps(dict(sorted(register.items())), indent=1) + "\n", encoding="utf-8")


if __name__ == "__main__":
    import sys

    if sys.argv[1:] == ["--update"]:
        _update()
