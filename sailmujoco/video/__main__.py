"""``python -m sailmujoco.video``: the ``video`` command on its own (:mod:`sailmujoco.cli.video`)."""

import sys

from ..cli.video import main

sys.exit(main())
