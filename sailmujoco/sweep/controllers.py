"""Controllers by name or by import path. A factory is ``factory(env, **options) -> controller``.

A controller is named in one of three ways, wherever one is accepted (Python, sweep files,
``polar``, ``video``, ``view``):

- a registered name: the ``sailmujoco.controllers`` entry points (the library never imports a
  controller), or a name given to :func:`register_controller` in this process;
- ``"package.module:factory"``: a module on the Python path;
- ``"path/to/file.py:factory"``: a file, loaded by its path (no package, no reinstall).

Sweep workers import a controller the same way. A name registered at run time lives in one
process only, so a sweep replaces it by its factory's import path before the runs go out. On a
Dask cluster of other machines a file is found by its path, so it must be reachable there at the
same path (a shared file system), or installed as a module and named ``"module:factory"``.
"""

from __future__ import annotations

import hashlib
import importlib
import importlib.util
import inspect
import sys
from importlib import metadata
from pathlib import Path

from ..errors import one_line
from ..names import check_known, unknown_message
from .errors import SweepError
from .kinds import check_kinds, signature_defaults

ENTRY_POINTS = "sailmujoco.controllers"
_REGISTERED: dict = {}  # name -> factory, registered in this process (register_controller)


class _Registered:
    """A factory registered at run time, with an entry point's ``load()``."""

    def __init__(self, factory):
        self.factory = factory

    def load(self):
        return self.factory


def controller_factories() -> dict:
    """name -> entry point (an object whose ``load()`` gives the factory) of every registered
    controller: the ``sailmujoco.controllers`` entry points and :func:`register_controller`'s."""
    found = {ep.name: ep for ep in metadata.entry_points(group=ENTRY_POINTS)}
    found.update({name: _Registered(factory) for name, factory in _REGISTERED.items()})
    return found


def register_controller(name: str, factory) -> None:
    """Register a controller factory under ``name`` in this process (no reinstall).

    Parameters
    ----------
    name : str
        A new name (an identifier; the entry points' names cannot be taken).
    factory : callable
        ``factory(env, **options)`` returning an object with ``reset(seed)`` and
        ``__call__(timestep) -> action``; its keyword defaults give its options and their kinds.
    """
    if not isinstance(name, str) or not name.isidentifier():
        raise SweepError(f"a controller's name must be an identifier, got {name!r}")
    if not callable(factory):
        raise SweepError(f"register_controller({name!r}, ...) needs a callable factory, got {factory!r}")
    if name in {ep.name for ep in metadata.entry_points(group=ENTRY_POINTS)}:
        raise SweepError(f"{name!r} is a built-in controller; register yours under another name")
    _REGISTERED[name] = factory


def factory_options(factory) -> tuple | None:
    """The option names ``factory`` takes by keyword (less ``env``, ``self`` and ``seed``), or
    None when it takes any (``**options``).

    Parameters
    ----------
    factory : callable
        A controller factory (or any function whose keywords are options).
    """
    parameters = inspect.signature(factory).parameters.values()
    if any(p.kind is p.VAR_KEYWORD for p in parameters):
        return None
    return tuple(p.name for p in parameters if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)
                 and p.name not in ("self", "seed", "env"))


def is_import_path(name: str) -> bool:
    """Whether ``name`` names a controller by import path (``"module:factory"``,
    ``"file.py:factory"``) rather than by a registered name.

    Parameters
    ----------
    name : str
        The controller's name as given.
    """
    return isinstance(name, str) and ":" in name


def controller_label(name: str) -> str:
    """A short name for files and titles: the factory's name of an import path, else ``name``.

    Parameters
    ----------
    name : str
        The controller.
    """
    return name.rpartition(":")[2] if is_import_path(name) else name


def _module_of_file(path: Path):
    """The module of the file ``path``, loaded once per process under a name of its own."""
    key = "sailmujoco_user_" + hashlib.sha256(str(path).encode()).hexdigest()[:12]
    if key in sys.modules:
        return sys.modules[key]
    spec = importlib.util.spec_from_file_location(key, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[key] = module
    try:
        spec.loader.exec_module(module)
    except BaseException:
        del sys.modules[key]
        raise
    return module


def _from_import_path(name: str):
    target, _, attribute = name.rpartition(":")
    if not target or not attribute:
        raise SweepError(f"controller {name!r}: an import path is 'package.module:factory' or "
                         "'path/to/file.py:factory'")
    try:
        if target.endswith(".py"):
            path = Path(target).expanduser().resolve()
            if not path.is_file():
                raise SweepError(f"controller {name!r}: no file {str(path)!r}")
            module = _module_of_file(path)
        else:
            module = importlib.import_module(target)
    except SweepError:
        raise
    except Exception as err:  # ImportError, SyntaxError, or whatever the module raised
        raise SweepError(f"controller {name!r}: cannot import {target!r} "
                         f"({type(err).__name__}: {err})") from None
    factory = getattr(module, attribute, None)
    if not callable(factory):
        public = [n for n, v in vars(module).items() if callable(v) and not n.startswith("_")]
        raise SweepError(unknown_message("factory", attribute, public, f"controller {name!r}"))
    return factory


def controller_factory(name: str):
    """The factory of controller ``name``: a registered name or an import path (module docstring);
    an unknown name refuses in one line with the nearest registered one.

    Parameters
    ----------
    name : str
        The controller.
    """
    if is_import_path(name):
        return _from_import_path(name)
    factories = controller_factories()
    check_known([name], factories, "the registered controllers (or give 'module:factory', "
                "'file.py:factory')", kind="controller", error=SweepError)
    return factories[name].load()


def portable_name(name: str) -> str:
    """``name`` as a worker process finds it: a file path made absolute, a name registered at
    run time replaced by its factory's import path; entry-point names and module paths as given.

    Parameters
    ----------
    name : str
        The controller.
    """
    if is_import_path(name):
        target, _, attribute = name.rpartition(":")
        if target.endswith(".py"):
            return f"{Path(target).expanduser().resolve()}:{attribute}"
        return name
    factory = _REGISTERED.get(name)
    if factory is None:
        return name
    qualname = getattr(factory, "__qualname__", "")
    if "<" in qualname or "." in qualname:
        raise SweepError(f"controller {name!r} was registered with a factory that is not a "
                         "module-level function; sweep workers can only import one of those")
    module = getattr(factory, "__module__", None)
    path = Path(inspect.getfile(factory)).resolve()
    installed = any(part in ("site-packages", "dist-packages") for part in path.parts)
    if module and module != "__main__" and installed:  # an installed module: by its name
        return f"{module}:{qualname}"
    return f"{path}:{qualname}"  # a script, a test or a file of one's own: by its path


def make_controller(name: str, env, **options):
    """Build controller ``name`` for ``env``, its options checked first (names and kinds).

    Parameters
    ----------
    name : str
        A registered controller or an import path (module docstring).
    env : SailEnvironment
        The environment it controls (its factory reads the boat and the action spec).
    **options
        The factory's options: a name it does not take refuses in one line with the nearest; a
        value of another kind than its default (``kp="two"``) in one line naming it.

    Raises
    ------
    ValueError
        A bad name or option, or a factory that raised (any exception, said in one line: the
        same controller and options raise it again, so a sweep does not retry it).
    """
    factory = check_controller_options(name, options)
    try:
        return factory(env, **options)
    except ValueError:
        raise
    except Exception as err:  # the user's factory: one line naming it, not its traceback
        raise ValueError(f"controller {name} could not be built: "
                         f"{one_line(f'{type(err).__name__}: {err}')}") from err


def check_controller_options(name: str, options: dict):
    """Check the options of controller ``name`` against its factory's keywords (names, and the
    kinds of their defaults) without building it; returns the factory.

    Parameters
    ----------
    name : str
        A registered controller or an import path (module docstring).
    options : dict
        The factory's options: a name it does not take refuses in one line with the nearest; a
        value of another kind than its default (``kp="two"``) in one line naming it.
    """
    factory = controller_factory(name)
    accepted = factory_options(factory)
    if accepted is not None:
        check_known(options, accepted, f"controller {name!r}", error=SweepError)
    check_kinds("controller", options, signature_defaults(factory))
    return factory
