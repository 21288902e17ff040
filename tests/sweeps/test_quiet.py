"""A model's warnings stay off the screen, and nothing of the user's warnings changes."""
import threading
import warnings

import numpy as np
import pytest

import bearing_sweep.models.registry as registry
from bearing_sweep import spec
from bearing_sweep.compute import Executor, run_sweep
from bearing_sweep.quiet import silenced

#: An overflow in the centrifugal force, then invalid values in the solver: numpy's
#: RuntimeWarnings printed in the middle of a run, for points that do not converge.
HUGE_SPEED = """
[sweep]
model = "crb_radial"
bearing = "paper000-D"
[fixed]
speed = "1e300 rpm"
[axes]
radial_load = ["1 kN", "2 kN", "3 kN"]
"""


@pytest.mark.parametrize("workers", ["0", pytest.param("2", marks=pytest.mark.slow)])
def test_a_model_overflowing_prints_nothing_but_the_summary(tmp_path, workers, run_command):
    (tmp_path / "d.toml").write_text(HUGE_SPEED)
    done = run_command("run", "d.toml", "-o", "d.nc", "--workers", workers, "--chunk-size", "1",
                   "--quiet", cwd=tmp_path, timeout=300)
    assert done.returncode == 0 and done.stderr == "", done.stderr
    # Points no bearing runs at: not converged, and flagged outside validity (speed factor).
    assert "3 points (3 not_converged; 3 out_of_validity)" in done.stdout


def warning_model(monkeypatch):
    """crb_radial that also warns as libraries do (a warnings.warn) and overflows."""
    model = registry.get_model("crb_radial")

    def warning(**inputs):
        warnings.warn("the model's own warning", UserWarning)
        np.float64(1e300) * 1e300
        np.log(np.zeros(1))
        return model.function(**inputs)

    monkeypatch.setitem(registry._MODELS, "crb_radial",
                        registry.Model(**{**model.__dict__, "function": warning}))


def test_no_warning_of_the_model_reaches_the_user_and_nothing_of_theirs_changes(monkeypatch):
    warning_model(monkeypatch)
    sweep = spec.parse(HUGE_SPEED.replace("1e300 rpm", "3000 rpm"))
    run_sweep(sweep, None, Executor(workers=0), progress=False)  # what it imports, imported
    with warnings.catch_warnings(record=True) as shown:
        warnings.simplefilter("always")
        filters, show = list(warnings.filters), warnings._showwarnmsg
        errors = np.geterr()
        summary = run_sweep(sweep, None, Executor(workers=0), progress=False)
        assert summary.status_counts["converged"] == 3 and not summary.errors
        assert [str(w.message) for w in shown] == []
        assert warnings.filters == filters and warnings._showwarnmsg is show
        assert np.geterr() == errors
        warnings.warn("the user's own", UserWarning)  # and theirs are shown as before
        assert [str(w.message) for w in shown] == ["the user's own"]


def test_another_thread_warns_as_before_while_one_is_silenced():
    # Two threads in silenced blocks that overlap, and a third outside any: only the third's
    # warnings are shown, and the last one out leaves the warnings module as it was.
    inside = [threading.Event() for _ in range(4)]

    def silenced_thread(entered, leave, label):
        with silenced():
            entered.set()
            warnings.warn(f"{label} in its block")
            np.float64(1e300) * 1e300
            leave.wait(10)

    with warnings.catch_warnings(record=True) as shown:
        warnings.simplefilter("always")
        show = warnings._showwarnmsg
        first = threading.Thread(target=silenced_thread, args=(inside[0], inside[1], "first"))
        second = threading.Thread(target=silenced_thread, args=(inside[2], inside[3], "second"))
        first.start()
        inside[0].wait(10)
        second.start()
        inside[2].wait(10)
        warnings.warn("outside, both in their blocks")
        inside[1].set()  # the first leaves, the second is still in its block
        first.join()
        warnings.warn("outside, one in its block")
        with np.errstate(over="raise"), pytest.raises(FloatingPointError):
            np.float64(1e300) * 1e300  # numpy's state is this thread's own
        inside[3].set()
        second.join()
        assert warnings._showwarnmsg is show
        warnings.warn("outside, none in a block")
    assert [str(w.message) for w in shown] == ["outside, both in their blocks",
                                               "outside, one in its block",
                                               "outside, none in a block"]


def test_a_filter_that_makes_warnings_errors_is_the_models_error(monkeypatch):
    # -W error: the user asked for it; the points say why they have no values.
    warning_model(monkeypatch)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        summary = run_sweep(spec.parse(HUGE_SPEED.replace("1e300 rpm", "3000 rpm")), None,
                            Executor(workers=0), progress=False)
    assert summary.status_counts["model_error"] == 3
    assert summary.errors == ["UserWarning: the model's own warning"]
