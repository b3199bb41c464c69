"""Every parameter of the public API is documented in a numpydoc "Parameters" section.

The walk, after python-control's ``docstrings_test.py``: every module of the packages
``sailmujoco``, ``sailmujoco.controllers`` and ``sailmujoco.studies`` is imported; a module whose
name, or the name of any package above it, starts with ``_`` is private, and ``__main__`` modules
are skipped. In each module the public (no leading underscore) functions and classes defined there
(``obj.__module__ == module.__name__``) are checked, and so are the public methods (plus
``__init__`` and ``__call__``) that a public class defines itself.

Rules:

- every parameter except ``self``/``cls`` appears in "Parameters" (or "Other Parameters") of the
  docstring, ``*args`` as ``*args`` and ``**kwargs`` as ``**kwargs``, stars included;
- the parameters of ``__init__`` may be documented in the class docstring or in ``__init__``'s own;
- a method without a docstring of its own is judged by the one it overrides (``inspect.getdoc``);
- a dataclass's generated ``__init__`` is not checked as a method, its fields are: each one under
  "Parameters" or "Attributes" of the class docstring;
- a numba-compiled function is checked through its Python source (``py_func``);
- properties, methods a class inherits from a third-party base (dm_control, gymnasium) and
  members a base or decorator puts on the class (``typing.Protocol``'s ``__init__``) are not
  checked; a method a project class overrides is;
- a ``**kwargs``-style parameter says what it accepts: its description is not empty.

Each failure reads ``module.qualname: parameter 'x' not documented``; all are collected and
listed in one assertion.
"""

from __future__ import annotations

import dataclasses
import functools
import importlib
import inspect
import pkgutil
import warnings

from numpydoc.docscrape import NumpyDocString

PACKAGES = ("sailmujoco", "sailmujoco.controllers", "sailmujoco.studies")
PUBLIC_DUNDERS = ("__init__", "__call__")  # the constructor and a controller's step
PARAMETER_SECTIONS = ("Parameters", "Other Parameters")


def _public_modules():
    """The imported public modules of the three packages, by dotted name."""
    names = set()
    for package_name in PACKAGES:
        package = importlib.import_module(package_name)
        names.add(package_name)
        for info in pkgutil.walk_packages(package.__path__, package_name + "."):
            names.add(info.name)
    for name in sorted(names):
        parts = name.split(".")
        if any(p.startswith("_") for p in parts):  # private, and __main__
            continue
        yield importlib.import_module(name)


def _sections(doc: str | None, where: str, failures: list[str]) -> NumpyDocString | None:
    if not doc:
        return None
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # unknown section names are not our concern here
            return NumpyDocString(inspect.cleandoc(doc))
    except Exception as error:  # noqa: BLE001 - any parse error is a documentation failure
        failures.append(f"{where}: docstring does not parse as numpydoc ({error})")
        return None


def _documented(parsed: NumpyDocString | None, sections=PARAMETER_SECTIONS) -> dict[str, str]:
    """Documented name (stars kept, escapes dropped) -> its description, over ``sections``."""
    out = {}
    if parsed is None:
        return out
    for section in sections:
        for entry in parsed[section]:
            for name in entry.name.replace("\\", "").split(","):
                out[name.strip()] = "\n".join(entry.desc).strip()
    return out


def _signature_names(func) -> list[tuple[str, inspect.Parameter]]:
    """(name as it must be documented, parameter) for each parameter but self/cls."""
    try:
        signature = inspect.signature(func)
    except (TypeError, ValueError):
        return []
    out = []
    for name, parameter in signature.parameters.items():
        if name in ("self", "cls"):
            continue
        if parameter.kind is inspect.Parameter.VAR_POSITIONAL:
            name = "*" + name
        elif parameter.kind is inspect.Parameter.VAR_KEYWORD:
            name = "**" + name
        out.append((name, parameter))
    return out


def _check(func, where: str, documented: dict[str, str], failures: list[str]) -> None:
    for name, parameter in _signature_names(func):
        if name not in documented:
            failures.append(f"{where}: parameter '{name}' not documented")
        elif parameter.kind is inspect.Parameter.VAR_KEYWORD and not documented[name]:
            failures.append(f"{where}: parameter '{name}' does not say what it accepts")


def _python_function(obj):
    """The plain Python function behind ``obj`` (a numba dispatcher's ``py_func``), or None."""
    if inspect.isfunction(obj):
        return obj
    py_func = getattr(obj, "py_func", None)
    return py_func if inspect.isfunction(py_func) else None


def _generated_init(cls) -> bool:
    init = cls.__dict__.get("__init__")
    return dataclasses.is_dataclass(cls) and init is not None and init.__code__.co_filename == "<string>"


def _check_class(cls, where: str, failures: list[str]) -> None:
    class_doc = _sections(cls.__dict__.get("__doc__"), where, failures)
    if dataclasses.is_dataclass(cls) and _generated_init(cls):
        documented = _documented(class_doc, PARAMETER_SECTIONS + ("Attributes",))
        for field in dataclasses.fields(cls):
            if field.init and field.name not in documented:
                failures.append(f"{where}: parameter '{field.name}' not documented")
    for name, member in cls.__dict__.items():
        if name.startswith("_") and name not in PUBLIC_DUNDERS:
            continue
        if isinstance(member, property):
            continue
        if isinstance(member, staticmethod | classmethod):
            member = member.__func__
        func = _python_function(member)
        if func is None or (name == "__init__" and _generated_init(cls)):
            continue
        if func.__module__ != cls.__module__:  # put there by a base or decorator (typing.Protocol)
            continue
        method_where = f"{where}.{name}"
        documented = _documented(_sections(inspect.getdoc(func), method_where, failures))
        if name == "__init__":
            documented = {**_documented(class_doc), **documented}
        _check(func, method_where, documented, failures)


@functools.cache
def _failures() -> list[str]:
    failures: list[str] = []
    for module in _public_modules():
        for name, obj in vars(module).items():
            if name.startswith("_"):
                continue
            where = f"{module.__name__}.{name}"
            if inspect.isclass(obj):
                if obj.__module__ == module.__name__:
                    _check_class(obj, where, failures)
                continue
            func = _python_function(obj)
            if func is None or func.__module__ != module.__name__:
                continue
            _check(func, where, _documented(_sections(func.__doc__, where, failures)), failures)
    return sorted(set(failures))


def _listing(failures: list[str]) -> str:
    return f"{len(failures)} documentation failures:\n" + "\n".join(failures)


def test_every_public_parameter_is_documented():
    failures = [f for f in _failures() if "does not say what it accepts" not in f]
    assert not failures, _listing(failures)


def test_every_keyword_catch_all_says_what_it_accepts():
    failures = [f for f in _failures() if "does not say what it accepts" in f]
    assert not failures, _listing(failures)
