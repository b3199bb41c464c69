"""Sphinx configuration of the API reference (``sphinx-build -W -b html docs docs/_build/html``).

The reference is built from the docstrings of the installed package (``pip install -e
'.[dev]'``), so this file puts nothing on ``sys.path``: ``sailmujoco.controllers`` and
``sailmujoco.studies`` exist only as installed. The Markdown pages of ``docs/`` are read as
they are (on the repository's web page or in an editor); Sphinx builds the reStructuredText
pages only. No network: no intersphinx, the plain alabaster theme.
"""

import re

import sailmujoco

project = "sailmujoco"
author = "the sailmujoco authors"
copyright = "the sailmujoco authors"
release = version = sailmujoco.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
]

root_doc = "index"
source_suffix = {".rst": "restructuredtext"}
exclude_patterns = ["_build", "**/*.md"]
templates_path = ["_templates"]

html_theme = "alabaster"
html_static_path: list[str] = []

autosummary_generate = True
autosummary_imported_members = False
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False}
autodoc_member_order = "bysource"
autodoc_typehints = "none"  # the numpydoc sections give every parameter's type

numpydoc_show_class_members = False  # autodoc lists the members; numpydoc's tables would repeat them
numpydoc_validation_checks: set[str] = set()  # tests/test_docstrings.py checks the parameters

# ``python -m`` entry modules run their command when imported; autosummary must not import them.
autosummary_mock_imports = ["sailmujoco.__main__", "sailmujoco.video.__main__"]

# The docstrings write formulas as plain text, where |x| is an absolute value (|V|, |phi|); in
# reStructuredText a bar starts a substitution reference. Outside literals (``code``, ``::``
# blocks, doctests) every bar is escaped, so the text shows as written.
_LITERAL = re.compile(r"(``.*?``)")


def _escape_bars(line: str) -> str:
    parts = _LITERAL.split(line)
    return "".join(part if i % 2 else part.replace("|", "\\|") for i, part in enumerate(parts))


def _plain_bars(app, what, name, obj, options, lines):
    """autodoc-process-docstring: escape the absolute-value bars of one docstring in place."""
    block_indent = None  # indent of the line that opened a literal block, while inside one
    for i, line in enumerate(lines):
        stripped = line.lstrip()
        indent = len(line) - len(stripped)
        if block_indent is not None:
            if not stripped or indent > block_indent:
                continue
            block_indent = None
        if stripped.startswith(">>>"):
            continue
        if "|" in line:
            lines[i] = _escape_bars(line)
        if stripped.endswith("::") or stripped.startswith(".. code"):
            block_indent = indent


def setup(app):
    """Sphinx hook: after numpydoc (priority 500) has turned the sections into reST."""
    app.connect("autodoc-process-docstring", _plain_bars, priority=600)
