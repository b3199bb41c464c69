"""``python -m sailmujoco.video``: the ``video`` command on its own."""

import sys

from .command import main

sys.exit(main())
