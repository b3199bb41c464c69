"""``python -m sailmujoco``: the ``sailmujoco`` command (:func:`sailmujoco.cli.main`)."""

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
