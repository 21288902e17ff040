"""The build's own steps: write the generated pages before Sphinx reads the sources, and run
every hand-written page's code examples (a failing one is a warning, an error under ``-W``)."""
from __future__ import annotations

import tempfile
from pathlib import Path

from sphinx.util import logging

import campbell
import doc_examples
import generated_pages

logger = logging.getLogger(__name__)

#: Pages whose examples run first, since later pages use what they make.
FIRST = ["getting-started.md"]


def hand_written_pages(docs: Path) -> list[str]:
    pages = sorted(str(path.relative_to(docs)) for path in docs.rglob("*.md")
                   if not {"generated", "_build", "_ext"} & set(path.relative_to(docs).parts))
    return FIRST + [page for page in pages if page not in FIRST]


def _generate(app) -> None:
    generated = Path(app.srcdir) / "generated"
    generated_pages.write_all(generated)
    campbell.campbell_figure(generated / "campbell.png")


def _run_examples(app) -> None:
    docs = Path(app.srcdir)
    with tempfile.TemporaryDirectory(prefix="bearing-sweep-docs-") as folder:
        for page in hand_written_pages(docs):
            try:
                doc_examples.run_page(page, (docs / page).read_text(), Path(folder))
            except doc_examples.ExampleFailed as failure:
                logger.warning(f"example does not run: {failure}", location=page)


def setup(app):
    app.connect("builder-inited", _generate)
    app.connect("builder-inited", _run_examples)
    return {"parallel_read_safe": True}
