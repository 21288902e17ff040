"""A definition given as a dict written out as TOML text, so that it meets the checks and
messages of a file, and its text is stored in the result."""
from __future__ import annotations

import json

import numpy as np

from .tables import SpecError


def toml_text(document: dict, where: str = "<definition>") -> str:
    """``document`` as TOML text: each table under its header, its values inline (a nested
    table keeps its place among the others: the order of axes is the order of dimensions)."""
    lines = [f"{_toml_key(k, where)} = {_toml_value(v, k, where)}" for k, v in document.items()
             if not isinstance(v, dict)]
    for name, table in document.items():
        if isinstance(table, dict):
            lines += ["", f"[{_toml_key(name, where)}]"] + [
                f"{_toml_key(k, where)} = {_toml_value(v, f'{name}.{k}', where)}"
                for k, v in table.items()]
    return "\n".join(lines).lstrip("\n") + "\n"


def _toml_key(key, where: str) -> str:
    if not isinstance(key, str):
        raise SpecError(f"{where}: {key!r}: a key is a string")
    return key if key and all(c.isalnum() and c.isascii() or c in "_-" for c in key) \
        else json.dumps(key, ensure_ascii=False)


def _toml_value(value, key: str, where: str) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)  # its escapes are TOML's too
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v, f"{key}[{i}]", where)
                               for i, v in enumerate(value)) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{_toml_key(k, where)} = {_toml_value(v, f'{key}.{k}', where)}"
                                for k, v in value.items()) + " }"
    raise SpecError(f"{where}: {key}: {value!r} is not a value of a definition (a string with "
                    "units, a number, a boolean, a list or a table)")
