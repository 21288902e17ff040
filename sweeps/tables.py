"""What :func:`bearing_sweep.list_models` and :func:`bearing_sweep.describe` return: the plain
list and dict they always were, shown as tables in a notebook (``_repr_html_``) and turned
into pandas DataFrames on request."""
from __future__ import annotations

from html import escape


def _html_table(rows: list[dict], columns: list[str]) -> str:
    head = "".join(f"<th style='text-align:left'>{escape(column)}</th>" for column in columns)
    body = "".join(
        "<tr>" + "".join(f"<td style='text-align:left'>{escape(_text(row.get(column)))}</td>"
                         for column in columns) + "</tr>"
        for row in rows)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _text(value) -> str:
    if value is None:
        return ""
    if isinstance(value, (tuple, list)):
        return ", ".join(str(item) for item in value)
    return str(value)


class ModelList(list):
    """The registered models, a dict per model (``name``, ``summary``, ``reference``,
    ``version``), shown as a table in a notebook."""

    COLUMNS = ["name", "summary", "reference", "version"]

    def _repr_html_(self) -> str:
        return _html_table(self, self.COLUMNS)

    def to_dataframe(self):
        """A :class:`pandas.DataFrame` of the models, indexed by name."""
        import pandas as pd

        return pd.DataFrame(list(self), columns=self.COLUMNS).set_index("name")


class ModelDescription(dict):
    """One model's declaration (see :func:`bearing_sweep.describe`), shown in a notebook as
    its summary and the tables of its inputs and outputs."""

    INPUT_COLUMNS = ["name", "unit", "default", "range", "meaning", "dims"]
    OUTPUT_COLUMNS = ["name", "unit", "dims", "meaning"]

    def _repr_html_(self) -> str:
        inputs = [{**entry, "default": "required" if entry["required"] else entry["default"],
                   "range": entry["range"] or _text(entry["choices"])}
                  for entry in self["inputs"]]
        conditions = "".join(f"<li>{escape(text)}</li>" for text in self["conditions"])
        return (f"<h4>{escape(self['name'])} (version {escape(str(self['version']))})</h4>"
                f"<p>{escape(self['summary'])}<br><i>{escape(self['reference'])}</i></p>"
                f"<p><b>Inputs</b></p>{_html_table(inputs, self.INPUT_COLUMNS)}"
                f"<p><b>Outputs</b></p>{_html_table(self['outputs'], self.OUTPUT_COLUMNS)}"
                f"<p><b>Flagged out of validity:</b> {escape(self['validity'] or 'nothing')}</p>"
                + (f"<p><b>Refused:</b></p><ul>{conditions}</ul>" if conditions else ""))

    def to_dataframe(self, part: str = "inputs"):
        """The model's ``"inputs"`` or ``"outputs"`` as a :class:`pandas.DataFrame`, indexed
        by name."""
        import pandas as pd

        if part not in ("inputs", "outputs"):
            raise ValueError(f"part={part!r}: 'inputs' or 'outputs'")
        return pd.DataFrame(self[part]).set_index("name")
