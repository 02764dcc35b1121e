"""Every public function, class and method documents its parameters (numpydoc),
and every public function and class carries a runnable example.

python-control has the same kind of check (control/tests/docstrings_test.py);
the examples themselves run as doctests (pytest --doctest-modules).
"""

import importlib
import inspect
import pkgutil

import pytest

numpydoc_docscrape = pytest.importorskip("numpydoc.docscrape")

import hystcomp

# modules whose __all__ is the public API (private modules start with "_")
MODULES = sorted(
    m.name for m in pkgutil.iter_modules(hystcomp.__path__, "hystcomp.")
    if not m.name.rsplit(".", 1)[1].startswith("_") and m.name not in ("hystcomp.cli",)
)


def _public_objects():
    for modname in MODULES:
        mod = importlib.import_module(modname)
        for name in getattr(mod, "__all__", []):
            obj = getattr(mod, name)
            home = getattr(obj, "__module__", modname) or modname
            if inspect.ismodule(obj) or (home != modname and not home.rsplit(".", 1)[1].startswith("_")):
                continue  # re-exports of a public module are checked there; a private module's here
            if inspect.isfunction(obj) or inspect.isclass(obj):
                yield f"{modname}.{name}", obj


def _documented_params(doc):
    names = set()
    for section in ("Parameters", "Other Parameters"):
        for p in doc[section]:
            for n in p.name.replace("*", "").split(","):
                names.add(n.strip())
    return names


def _signature_params(func, skip_first=False):
    try:
        sig = inspect.signature(func)
    except (TypeError, ValueError):
        return []
    params = [p for p in sig.parameters.values()
              if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD) and not p.name.startswith("_")]
    if skip_first and params and params[0].name in ("self", "cls"):
        params = params[1:]
    return [p.name for p in params]


def _undocumented(func, docstring, skip_first=False):
    doc = numpydoc_docscrape.NumpyDocString(docstring or "")
    have = _documented_params(doc)
    return [p for p in _signature_params(func, skip_first) if p not in have]


PUBLIC = list(_public_objects())


@pytest.mark.parametrize("qualname,obj", PUBLIC, ids=[q for q, _ in PUBLIC])
def test_parameters_documented(qualname, obj):
    missing = {}
    if inspect.isclass(obj):
        init = obj.__dict__.get("__init__")
        if init is not None:
            miss = _undocumented(init, obj.__doc__, skip_first=True)
            if miss:
                missing["__init__"] = miss
        for name, member in vars(obj).items():
            if name.startswith("_") or not inspect.isfunction(member):
                continue
            miss = _undocumented(member, member.__doc__, skip_first=True)
            if miss:
                missing[name] = miss
    else:
        miss = _undocumented(obj, obj.__doc__)
        if miss:
            missing[qualname] = miss
    assert not missing, f"{qualname}: undocumented parameters {missing}"


@pytest.mark.parametrize("qualname,obj", PUBLIC, ids=[q for q, _ in PUBLIC])
def test_has_example(qualname, obj):
    doc = numpydoc_docscrape.NumpyDocString(obj.__doc__ or "")
    assert doc["Examples"], f"{qualname} has no Examples section"
    assert ">>>" in "\n".join(doc["Examples"]), f"{qualname}'s Examples run nothing"
