"""The [output] table, and the same options on the command line and in the Python API: how
a result stores its outputs (the encoding and compression of :class:`..storage.Storage`)."""
from __future__ import annotations

from dataclasses import replace

from ..storage import COMPRESSIONS, DEFAULT_LEVELS, ENCODINGS, Storage
from .tables import Reader, SpecError, suggestion

#: The keys of an [output] table.
OUTPUT_KEYS = ("encoding", "compression", "shuffle")


def output_table(reader: Reader, document: dict) -> Storage:
    """How the outputs are written, from the [output] table of ``document`` (defaults for
    what it omits)."""
    table = reader.table(document, "output", OUTPUT_KEYS)
    base = storage_options(Storage(), table.get("encoding"), table.get("compression"),
                           lambda key: f"{reader.where}: {reader.key('output.' + key)}")
    shuffle = table.get("shuffle", base.shuffle)
    if not isinstance(shuffle, bool):
        reader.fail("output.shuffle", f"{shuffle!r}: expected true or false")
    return replace(base, shuffle=shuffle)


def storage_options(base: Storage, encoding=None, compression=None,
                    named=lambda key: f"--{key}") -> Storage:
    """``base`` with the ``encoding`` and ``compression`` given (None: as in ``base``),
    written as on the command line and in an [output] table: ``"float32"``, ``"zlib:4"``;
    ``named(key)`` says where, in a :class:`SpecError` for a mistake."""
    if encoding is not None and encoding not in ENCODINGS:
        raise SpecError(f"{named('encoding')}: {encoding!r} is not accepted; the encoding is "
                        + " or ".join(repr(e) for e in ENCODINGS)
                        + suggestion(str(encoding), ENCODINGS))
    name, level = base.compression, base.level
    if compression is not None:
        name, level = _compression(compression, named("compression"))
    return replace(base, encoding=encoding or base.encoding, compression=name, level=level)


def _compression(text, where: str) -> tuple[str, int]:
    """``"none"``, ``"zlib"``, ``"zlib:4"``, ``"zstd:3"`` as (name, level)."""
    accepted = "'none', 'zlib' or 'zlib:LEVEL' (1-9), 'zstd' or 'zstd:LEVEL' (1-22)"
    if not isinstance(text, str):
        raise SpecError(f"{where}: {text!r}: expected a string, {accepted}")
    name, _, level_text = text.partition(":")
    if name not in COMPRESSIONS:
        raise SpecError(f"{where}: {text!r} is not accepted; the compression is {accepted}"
                        + suggestion(name, COMPRESSIONS))
    levels = COMPRESSIONS[name]
    if levels is None:
        if level_text:
            raise SpecError(f"{where}: {text!r}: 'none' takes no level")
        return name, 0
    if level_text and not (level_text.isdigit() and int(level_text) in levels):
        raise SpecError(f"{where}: {text!r}: the level of {name} is an integer from "
                        f"{levels.start} to {levels.stop - 1}")
    if name == "zstd":
        import netCDF4

        if not getattr(netCDF4, "__has_zstandard_support__", False):
            raise SpecError(f"{where}: {text!r}: the installed netCDF4 {netCDF4.__version__} "
                            f"(HDF5 {netCDF4.__hdf5libversion__}) cannot write zstd; use "
                            "'zlib'")
    return name, int(level_text) if level_text else DEFAULT_LEVELS[name]
