"""``python -m sailmujoco``: the ``sailmujoco`` command (:func:`sailmujoco.cli.main.main`)."""

import sys

from .cli.main import main

if __name__ == "__main__":
    sys.exit(main())
