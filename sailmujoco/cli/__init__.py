"""The ``sailmujoco`` command: each sub-command's parser and main (:mod:`sailmujoco.cli.main` dispatches)."""
