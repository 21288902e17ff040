"""Finished chunks kept on disk beside a sweep's output, so that an interrupted sweep resumes.

``<output>.parts/`` holds a manifest (what the parts belong to: the definition's sha256, the
model's version, the grid's size and the chunk size) and one ``.npz`` file per finished chunk,
each written atomically. Parts of another definition are discarded, with a message.
A lock file ``<output>.lock`` keeps two runs from writing the same output.
"""
from __future__ import annotations

import fcntl
import json
import os
import shutil
from pathlib import Path

import numpy as np


class OutputBusy(OSError):
    """Another run holds the output; the message is for the user."""


class Parts:
    """The part files of one output."""

    def __init__(self, output, key: dict):
        output = Path(output)
        self.folder = output.with_name(output.name + ".parts")
        self.key = key

    def open(self, chunk_size: int, fresh: bool, log) -> int:
        """Prepare the folder; return the chunk size to use (a resumed sweep keeps its own)."""
        manifest = self.folder / "manifest.json"
        if self.folder.exists():
            found = _read_json(manifest)
            count = len(list(self.folder.glob("chunk-*.npz")))
            same = found is not None and {k: found.get(k) for k in self.key} == self.key
            if fresh or not same:
                if count:
                    log(f"{'--fresh' if fresh else 'the definition or model changed'}: "
                        f"discarding {count} finished chunks in {self.folder}")
                shutil.rmtree(self.folder)
            else:
                if count:
                    log(f"resuming: {count} chunks already computed in {self.folder}")
                return int(found["chunk_size"])
        self.folder.mkdir(parents=True)
        _write_atomically(manifest, json.dumps({**self.key, "chunk_size": chunk_size}).encode())
        return chunk_size

    def finished(self) -> set:
        """``(start, stop)`` of every chunk on disk."""
        done = set()
        for path in self.folder.glob("chunk-*.npz"):
            _, start, stop = path.stem.split("-")
            done.add((int(start), int(stop)))
        return done

    def save(self, start: int, stop: int, result: dict):
        arrays = {f"output_{name}": values for name, values in result["outputs"].items()}
        arrays["status"] = result["status"]
        arrays["errors"] = np.array(result["errors"], dtype=str)
        temporary = self.folder / f".chunk-{start}-{stop}.{os.getpid()}.tmp"
        with open(temporary, "wb") as handle:
            np.savez(handle, **arrays)
        os.replace(temporary, self.folder / f"chunk-{start:012d}-{stop:012d}.npz")

    def load(self, start: int, stop: int) -> dict:
        with np.load(self.folder / f"chunk-{start:012d}-{stop:012d}.npz") as data:
            return {"outputs": {key[len("output_"):]: data[key] for key in data.files
                                if key.startswith("output_")},
                    "status": data["status"], "errors": data["errors"].tolist()}

    def remove(self):
        shutil.rmtree(self.folder, ignore_errors=True)


class OutputLock:
    """An exclusive lock on an output path, released when the process ends, however it ends."""

    def __init__(self, output):
        self.output = Path(output)
        self.path = self.output.with_name(f".{self.output.name}.lock")
        self.handle = None

    def __enter__(self):
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self.handle = open(self.path, "a+")
        try:
            fcntl.flock(self.handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            self.handle.close()
            raise OutputBusy(f"{self.output}: another bearing-sweep run is writing this output; "
                             "wait for it to finish or choose another -o") from None
        return self

    def __exit__(self, *exc):
        self.path.unlink(missing_ok=True)
        fcntl.flock(self.handle, fcntl.LOCK_UN)
        self.handle.close()


def _read_json(path: Path):
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return None


def _write_atomically(path: Path, data: bytes):
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    temporary.write_bytes(data)
    os.replace(temporary, path)
