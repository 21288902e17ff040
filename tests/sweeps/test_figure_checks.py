"""The figure checks find each thing a reader would stumble on, and nothing in a clean figure."""
import numpy as np
import pytest

from bearing_sweep.figure_checks import figure_problems
from bearing_sweep.plotting import subplots


def _clean():
    figure, axis = subplots(figsize=(5, 3.5))
    load = np.linspace(1, 10, 20)
    axis.plot(load, 2 * load, label="bearing D")
    axis.set(xlabel="radial load [kN]", ylabel="radial stiffness [1e5 N/mm]",
             title="$e_r$ = 2 mm")  # a paper's symbol in mathtext is no internal name
    axis.legend(loc="lower right")
    return figure, axis


def test_a_clean_figure_has_no_problem():
    figure = _clean()[0]
    figure.tight_layout()  # as plotting.save lays a figure out
    assert figure_problems(figure) == []


def _problem(case):
    figure, axis = _clean()
    if case == "blank":
        figure, axis = subplots()
        axis.set(xlabel="load [N]", ylabel="force [N]")
    elif case == "one_colour_map":
        figure, axis = subplots()
        axis.pcolormesh(np.zeros((3, 4)))
        axis.set(xlabel="arc element number", ylabel="axial element number")
    elif case == "no_label":
        axis.set_ylabel("")
    elif case == "no_unit":
        axis.set_xlabel("radial load")
    elif case == "si":
        axis.set_ylabel("contact constant K [SI]")
    elif case == "internal_name":
        axis.set_title("crown_consistent: paper 4.1 %")
    elif case == "legend_over_data":
        axis.plot([1, 10], [2, 2], label="flat")
        axis.legend(loc="lower right")
    elif case == "ticks":
        axis.set_xticks(np.linspace(1, 10, 40), [f"{v:.3f} mm" for v in np.linspace(1, 10, 40)])
    elif case == "off_the_figure":
        figure.text(0.9, 0.5, "a note that runs far beyond the right edge of the figure")
    figure.tight_layout()
    return figure


@pytest.mark.parametrize("case, found", [
    ("blank", "a blank panel"), ("one_colour_map", "a blank panel"),
    ("no_label", "its y axis has no label"), ("no_unit", "names a quantity without its unit"),
    ("si", "shows no real unit"), ("internal_name", "an internal name in"),
    ("legend_over_data", "the legend lies over data"), ("ticks", "x tick labels overlap"),
    ("off_the_figure", "runs off the figure")])
def test_each_problem_is_found(case, found):
    problems = figure_problems(_problem(case))
    assert len(problems) == 1 and found in problems[0], problems


def test_a_panel_saying_why_it_is_empty_is_not_blank():
    figure, axis = subplots()
    axis.text(0.5, 0.5, "no dry contact", transform=axis.transAxes)
    axis.set(xticks=[], yticks=[])
    assert figure_problems(figure) == []
