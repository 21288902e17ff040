"""A Ctrl-C stops a run, whatever exception the code it lands in turns it into."""
import os
import random
import signal
import threading
import time

import pytest

import bearing_sweep.models.registry as registry
from bearing_sweep import cli, spec, stores
from bearing_sweep.compute import Executor, Interrupts, run_sweep
from bearing_sweep.evaluate import evaluate_chunk
from bearing_sweep.grid import Grid
from bearing_sweep.interrupts import interruption

#: 8 points; in chunks of 2 points, one model call each.
DEFINITION = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[axes]
radial_load = ["1 kN", "2 kN", "3 kN", "4 kN"]
clearance = ["0 mm", "0.02 mm"]
"""
#: What numba's dispatcher raises when a Ctrl-C lands in its compiled function (seen from
#: crb_radial's roller_balances, the KeyboardInterrupt its cause's cause).
NUMBA = "CPUDispatcher(<function roller_balances at 0x7f0e1eef8a40>) returned a result with " \
        "an exception set"


def as_numba_does(original, inputs):
    try:
        signal.raise_signal(signal.SIGINT)  # the handler runs, and raises, before it returns
    except KeyboardInterrupt as interrupt:
        try:
            raise SystemError("<function _numba_unpickle> returned a result with an exception "
                              "set") from interrupt
        except SystemError as inner:
            raise SystemError(NUMBA) from inner


def raised_while_handling_it(original, inputs):
    try:
        signal.raise_signal(signal.SIGINT)
    except KeyboardInterrupt:
        raise RuntimeError("the solver's cleanup failed")  # its context: the interrupt


def dropped(original, inputs):
    """A ctypes callback's way: the interrupt printed ("Exception ignored") and lost."""
    try:
        signal.raise_signal(signal.SIGINT)
    except KeyboardInterrupt:
        pass


def dropped_then_failed(original, inputs):
    dropped(original, inputs)
    raise ValueError("a failure that says nothing of the interrupt")


def dropped_then_returned(original, inputs):
    dropped(original, inputs)
    return original(**inputs)


FORMS = {"numba's SystemError": as_numba_does,
         "an exception raised while handling it": raised_while_handling_it,
         "dropped, then another exception": dropped_then_failed,
         "dropped, then values": dropped_then_returned}


def interrupted_at_call(monkeypatch, form, call: int):
    """crb_radial, interrupted by a Ctrl-C in its ``call``-th call, which ``form`` turns into
    what it does."""
    model = registry.get_model("crb_radial")
    calls = []

    def function(**inputs):
        calls.append(1)
        if len(calls) == call:
            return form(model.function, inputs)
        return model.function(**inputs)

    monkeypatch.setitem(registry._MODELS, "crb_radial",
                        registry.Model(**{**model.__dict__, "function": function}))


@pytest.mark.parametrize("form", FORMS)
def test_a_ctrl_c_in_any_form_stops_the_run_and_keeps_the_chunks(tmp_path, capsys, monkeypatch,
                                                                 form):
    definition = tmp_path / "d.toml"
    definition.write_text(DEFINITION)
    output = tmp_path / "k.nc"
    arguments = ["run", str(definition), "-o", str(output), "--workers", "0", "--chunk-size",
                 "2", "--quiet"]
    with monkeypatch.context() as patched:
        interrupted_at_call(patched, FORMS[form], 3)
        assert cli.main(arguments) == 130
    out, err = capsys.readouterr()
    assert out == "" and err == ("interrupted: the finished chunks are kept; run the same "
                                 "command again to resume\n")
    assert len(list((tmp_path / "k.nc.parts").glob("chunk-*.npz"))) == 2
    assert not output.exists()
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    assert cli.main(arguments) == 0
    out, err = capsys.readouterr()
    assert "8 points (8 converged)" in out and "model errors" not in out
    assert err == f"resuming: 2 chunks already computed in {tmp_path / 'k.nc.parts'}\n"
    assert (stores.open_result(output).status == 0).all()


@pytest.mark.parametrize("form", FORMS)
def test_the_api_raises_it(monkeypatch, form):
    import bearing_sweep

    interrupted_at_call(monkeypatch, FORMS[form], 1)
    with pytest.raises(KeyboardInterrupt):
        bearing_sweep.run(DEFINITION, workers=0, progress=False)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_a_failure_that_is_no_interrupt_is_still_a_model_error(monkeypatch):
    # Raised while handling an error, not an interrupt: the points' status says it.
    def failing(original, inputs):
        try:
            raise ZeroDivisionError("inner")
        except ZeroDivisionError:
            raise RuntimeError("outer")

    interrupted_at_call(monkeypatch, failing, 1)
    summary = run_sweep(spec.parse(DEFINITION), None, Executor(workers=0), chunk_size=2,
                        progress=False)
    assert summary.status_counts["model_error"] == 2
    assert summary.errors == ["RuntimeError: outer"]


def chained(*errors):
    """``errors[0]``, raised from ``errors[1]``, raised from ..."""
    for inner, outer in zip(errors[::-1], errors[-2::-1]):
        outer.__cause__ = inner
    return errors[0]


def test_the_interruption_is_found_however_deep():
    interrupt, exit_ = KeyboardInterrupt(), SystemExit(143)  # SystemExit: a SIGTERM handler's
    assert interruption(chained(SystemError("a"), SystemError("b"), interrupt)) is interrupt
    assert interruption(chained(RuntimeError("a"), exit_)) is exit_
    context = RuntimeError("while handling")
    context.__context__ = interrupt
    assert interruption(chained(ValueError("a"), context)) is interrupt
    group = ExceptionGroup("tasks", [ValueError("one"), chained(OSError("two"), interrupt)])
    assert interruption(group) is interrupt
    looped = ValueError("a")
    looped.__context__ = chained(TypeError("b"), looped)
    assert interruption(looped) is None
    assert interruption(chained(RuntimeError("a"), ZeroDivisionError("b"))) is None


@pytest.mark.slow
def test_a_real_ctrl_c_in_compiled_code_is_never_a_model_error():
    # The reproduction: SIGINT at a random moment of a chunk of crb_radial, whose roller
    # balances numba compiled; about one in twenty landed where numba made it a SystemError.
    grid = Grid.from_sweep(spec.parse(DEFINITION.replace(
        'clearance = ["0 mm", "0.02 mm"]', 'clearance = { start = "0 mm", stop = "0.04 mm", '
                                            'num = 125 }')))
    evaluate_chunk(grid, 0, 500)  # compiled and cached
    began = time.monotonic()
    evaluate_chunk(grid, 0, 500)
    duration = time.monotonic() - began
    draw = random.Random(23)
    swallowed = []
    with Interrupts():
        for _ in range(60):
            timer = threading.Timer(draw.uniform(0.0, duration), os.kill,
                                    (os.getpid(), signal.SIGINT))
            try:
                timer.start()
                result = evaluate_chunk(grid, 0, 500)
                timer.join()
                time.sleep(0.05)  # the handler runs here if the signal came after the chunk
            except KeyboardInterrupt:
                timer.join()
                continue
            swallowed.append(result["errors"])
    assert swallowed == []
