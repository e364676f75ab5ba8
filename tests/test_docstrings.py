"""STYLE.md section 7: every public docstring documents exactly the parameters in its function's signature.

Walks every public module of the package, takes the functions (and the classes with a ``Parameters``
section) listed in its ``__all__`` and defined there, parses the numpydoc ``Parameters`` section
(``a, b : type`` lines included) and compares the names with the signature (``self``/``cls`` and
``*args``/``**kwargs`` excluded).
"""

import importlib
import inspect
import pkgutil
import re

import pytest

import bearinglab

_HEADER = re.compile(r"^(\s*)([A-Z][A-Za-z ]+)\n\1(-{3,})\s*$", re.MULTILINE)
_PARAM_LINE = re.compile(r"^([*\w][\w*]*(?:\s*,\s*[*\w][\w*]*)*)\s*(?::.*)?$")


def documented_parameters(doc):
    """Names in the numpydoc Parameters section of ``doc``, or None if it has no such section."""
    doc = inspect.cleandoc(doc or "")
    headers = list(_HEADER.finditer(doc))
    for i, h in enumerate(headers):
        if h.group(2).strip() != "Parameters":
            continue
        end = headers[i + 1].start() if i + 1 < len(headers) else len(doc)
        names = []
        for line in doc[h.end() : end].splitlines():
            if not line.strip() or line[:1].isspace():  # descriptions are indented
                continue
            m = _PARAM_LINE.match(line.strip())
            if m:
                names += [n.strip() for n in m.group(1).split(",")]
        return names
    return None


def signature_parameters(obj):
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):
        return None
    return [
        p.name
        for p in sig.parameters.values()
        if p.name not in ("self", "cls") and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)
    ]


def variadic_parameters(obj):
    """``*args`` and ``**kwargs`` of the signature, written as numpydoc documents them."""
    sig = inspect.signature(obj)
    star = {inspect.Parameter.VAR_POSITIONAL: "*", inspect.Parameter.VAR_KEYWORD: "**"}
    return {star[p.kind] + p.name for p in sig.parameters.values() if p.kind in star}


def _public_modules():
    mods = [bearinglab.__name__]
    for info in pkgutil.walk_packages(bearinglab.__path__, prefix="bearinglab."):
        if not any(part.startswith("_") for part in info.name.split(".")):
            mods.append(info.name)
    return sorted(mods)


def _cases():
    cases = []
    for name in _public_modules():
        try:
            module = importlib.import_module(name)
        except Exception as exc:  # noqa: BLE001 - a module mid-work must not hide the others
            cases.append(pytest.param(name, None, exc, id=f"{name}:<import>"))
            continue
        for attr in getattr(module, "__all__", []):
            obj = getattr(module, attr, None)
            if getattr(obj, "__module__", None) != name:
                continue  # re-exported or a constant: checked where it is defined
            if inspect.isfunction(obj) or (
                inspect.isclass(obj) and documented_parameters(obj.__doc__) is not None
            ):
                cases.append(pytest.param(name, attr, None, id=f"{name}.{attr}"))
    return cases


CASES = _cases()


def test_every_public_module_has_all():
    missing = [m for m in _public_modules() if not hasattr(importlib.import_module(m), "__all__")]
    assert not missing, f"modules without __all__: {missing}"


@pytest.mark.parametrize("module_name, attr, import_error", CASES)
def test_docstring_documents_exactly_the_signature(module_name, attr, import_error):
    if import_error is not None:
        pytest.fail(f"{module_name} does not import: {import_error!r}")
    obj = getattr(importlib.import_module(module_name), attr)
    expected = signature_parameters(obj)
    documented = documented_parameters(obj.__doc__)
    assert obj.__doc__, f"{module_name}.{attr} has no docstring"
    if not expected and documented is None:
        return  # no parameters, none documented
    assert documented is not None, (
        f"{module_name}.{attr}: no Parameters section; signature has {expected}"
    )
    missing = [n for n in expected if n not in documented]
    # *args / **kwargs need not be documented, but one that is documented must exist
    extra = [n for n in documented if n not in expected and n not in variadic_parameters(obj)]
    assert not missing and not extra, (
        f"{module_name}.{attr}: undocumented {missing}, documented but absent {extra}"
    )
    assert len(documented) == len(set(documented)), (
        f"{module_name}.{attr}: a parameter is documented twice"
    )


# --------------------------------------------------------------------------- the parser itself
def test_parser_reads_numpydoc():
    doc = """Summary.

    Parameters
    ----------
    load : array_like
        Load. [N]
    rx, ry : array_like
        Radii. [m]
    flag
        A bare name.
    *args : tuple
        Ignored.

    Returns
    -------
    out : float
        Not a parameter.
    """
    assert documented_parameters(doc) == ["load", "rx", "ry", "flag", "*args"]
    assert documented_parameters("No sections.") is None


def test_a_mismatch_is_detected():
    def f(a, b, *, c=1):
        """Doc.

        Parameters
        ----------
        a, b : float
            Things.
        """

    assert signature_parameters(f) == ["a", "b", "c"]
    assert set(signature_parameters(f)) != set(documented_parameters(f.__doc__))

    def g(a, *rest, **options):
        """Doc."""

    assert signature_parameters(g) == ["a"]
    assert variadic_parameters(g) == {"*rest", "**options"}


# reStructuredText reads |name| as a substitution: in a rendered docstring it fails the -W docs build
_SUBSTITUTION = re.compile(r"(?<![|`\w\\])\|[A-Za-z_][^|\n`]*\|(?![|`\w])")
_LITERALS = re.compile(r"``.*?``|:math:`[^`]*`|`[^`]*`", re.DOTALL)


def _rendered_docstrings():
    for name in _public_modules():
        module = importlib.import_module(name)
        yield name, module.__doc__
        for attr in getattr(module, "__all__", []):
            obj = getattr(module, attr, None)
            if getattr(obj, "__module__", None) != name:
                continue
            yield f"{name}.{attr}", getattr(obj, "__doc__", None)
            if inspect.isclass(obj):
                for member, value in vars(obj).items():
                    if not member.startswith("_") and callable(value):
                        yield f"{name}.{attr}.{member}", value.__doc__


def test_rendered_docstrings_have_no_stray_substitutions():
    found = [(where, m.group(0)) for where, doc in _rendered_docstrings() if doc
             for m in _SUBSTITUTION.finditer(_LITERALS.sub("", doc))]
    assert not found, f"|...| is a substitution in reST; write abs(...) or use :math: {found}"


def test_stray_substitution_is_found():
    assert _SUBSTITUTION.search(_LITERALS.sub("", "F_a = |F_z|; ``|x|`` and :math:`|y|` are fine"))
    assert not _SUBSTITUTION.search(_LITERALS.sub("", "``|x|`` and :math:`|y|` and | table | cell"))
