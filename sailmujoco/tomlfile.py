"""Reading the package's TOML files (wind files, sweep files) with one clear error."""

from __future__ import annotations

import tomllib
from pathlib import Path


def read_toml(path, what: str, error: type[Exception] = ValueError) -> dict:
    """The parsed TOML at ``path``; a missing or malformed file raises ``error`` naming ``what``.

    Parameters
    ----------
    path : str or Path
        The file.
    what : str
        What the file is, for the message (``"sweep file"``, ``"wind file"``).
    error : type
        The exception raised (a ``ValueError`` subclass the caller's users already catch).
    """
    path = Path(path)
    try:
        return tomllib.loads(path.read_text())
    except FileNotFoundError:
        raise error(f"{what} {str(path)!r} does not exist") from None
    except IsADirectoryError:
        raise error(f"{what} {str(path)!r} is a folder, not a TOML file") from None
    except UnicodeDecodeError:
        raise error(f"{what} {str(path)!r} is not a text (TOML) file") from None
    except OSError as err:
        raise error(f"{what} {str(path)!r} cannot be read: {err.strerror or err}") from None
    except tomllib.TOMLDecodeError as err:
        raise error(f"{what} {str(path)!r} does not parse as TOML: {err}") from None
