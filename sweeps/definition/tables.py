"""Reading a definition's tables and keys: a mistake is one line naming the file, the key
(its dotted path from the top of the definition), what is wrong and what is accepted."""
from __future__ import annotations

import difflib

import numpy as np

#: The largest magnitude of an integer in a definition: what 64 bits hold.
MAX_INTEGER = 2**63 - 1


class SpecError(Exception):
    """A mistake in a sweep definition; ``str(error)`` is the line shown to the user."""


class MissingExtra(RuntimeError):
    """What was asked needs an optional extra that is not installed; ``str(error)`` says
    which, and how to install it."""


def suggestion(name: str, options) -> str:
    """'; did you mean ...?' for the option closest to ``name``, or nothing."""
    close = difflib.get_close_matches(name, list(options), n=1, cutoff=0.6)
    return f"; did you mean {close[0]!r}?" if close else ""


class Reader:
    """Reads the tables of one definition (``where``: its file, or ``<definition>``) below
    the dotted ``path`` of a table in it ("" at the top, ``supports.A`` further down)."""

    def __init__(self, where: str, path: str = ""):
        self.where = where
        self.path = path

    def key(self, name: str) -> str:
        """``name``'s dotted path from the top of the definition."""
        return f"{self.path}.{name}" if self.path else name

    def within(self, name: str) -> Reader:
        """A reader of the table ``name`` below this one."""
        return Reader(self.where, self.key(name))

    def fail(self, key: str, message: str):
        raise SpecError(f"{self.where}: {self.key(key)}: {message}")

    def table(self, document: dict, key: str, allowed) -> dict:
        """The table ``key`` of ``document`` ({} if absent), its keys among ``allowed``
        (None: any)."""
        table = document.get(key, {})
        if not isinstance(table, dict):
            self.fail(key, f"expected a table [{self.key(key)}]")
        for name in table:
            if allowed is not None and name not in allowed:
                self.fail(f"{key}.{name}", "unknown key" + suggestion(name, allowed)
                          + f" (accepted: {', '.join(sorted(allowed))})")
        return table

    def fits(self, number: int, key: str):
        """Refuse an integer beyond what 64 bits hold (TOML's integers have no limit)."""
        if abs(number) > MAX_INTEGER:
            self.fail(key, f"{short(str(number))} is too large: an integer of a definition is "
                      f"at most {MAX_INTEGER} in magnitude")


def written(raw) -> str:
    """A value as the definition wrote it, for a message: TOML's nan and inf by name."""
    if isinstance(raw, float) and not np.isfinite(raw):
        return "nan" if np.isnan(raw) else ("-inf" if raw < 0 else "inf")
    return repr(raw) if isinstance(raw, (str, float, int)) else str(raw)


def integers(raw):
    """The integers in a value as TOML gives it (a number, or a list or table of them)."""
    if isinstance(raw, int) and not isinstance(raw, bool):
        yield raw
    elif isinstance(raw, (list, dict)):
        for item in (raw.values() if isinstance(raw, dict) else raw):
            yield from integers(item)


def short(text: str) -> str:
    """``text`` cut to 40 characters, for a message."""
    return text if len(text) <= 40 else text[:37] + "..."


def plain(number) -> str:
    """A number as a message shows it (``%g``); anything else as it is."""
    return f"{number:g}" if isinstance(number, (int, float)) else str(number)
