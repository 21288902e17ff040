"""Sphinx configuration of the bearing-sweep documentation (`make docs`)."""
import sys
from pathlib import Path

import matplotlib

sys.path.insert(0, str(Path(__file__).parent / "_ext"))

import bearing_sweep  # noqa: E402

matplotlib.use("Agg")  # this build's own process: the examples draw without a display

project = "bearing-sweep"
author = "The bearing-sweep authors"
copyright = "The bearing-sweep authors, MIT licence"
release = bearing_sweep.__version__
version = release

extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.mathjax", "numpydoc",
              "build_hooks"]
myst_enable_extensions = ["colon_fence", "dollarmath"]
myst_heading_anchors = 3
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
autodoc_typehints = "none"  # the numpydoc sections state types and units

html_theme = "pydata_sphinx_theme"
html_title = f"bearing-sweep {release}"
html_theme_options = {"navigation_with_keys": False, "show_toc_level": 2}
html_static_path = []
exclude_patterns = ["_build", "_ext", "Thumbs.db", ".DS_Store"]
