"""Reading a sweep definition, one job a module (the entry points are in :mod:`..spec`).

- :mod:`.tables`: the TOML tables and their keys, and the one-line :class:`SpecError`
  (file, dotted key, what is wrong, what is accepted, "did you mean").
- :mod:`.values`: one value of a model's input, written with units or in its declared unit,
  to SI; the one conversion of a written value to another unit (:func:`convert_written`).
- :mod:`.axes`: the [axes] table: lists, ranges and zipped axes.
- :mod:`.sampling`: the [sample] table: distributions and the drawn ``sample`` axis.
- :mod:`.inputs`: every input of one model from its [fixed], [axes] and [sample] tables,
  defaults and presets, and the conditions between them.
- :mod:`.system`: the tables that give a model's structure (a shaft's [shaft], [supports]
  and [loads]), read into the inputs of the model they build.
- :mod:`.output`: the [output] table and the ``--encoding``/``--compression`` options.
- :mod:`.writing`: a definition given as a dict written out as TOML text.

Each reader is told where its table sits (a dotted path), and :mod:`.inputs` reads one
model's inputs from any table: a definition holding several models (a shaft's supports, each
its own bearing) reads each of its sub-tables with its own path, ``supports.A``.
"""
