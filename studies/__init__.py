"""The papers' studies: one folder each, with its sweep definitions, figure script, claims
and notes (data for the engine, installed with the package)."""
