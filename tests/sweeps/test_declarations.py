"""The docstring of a model's function describes the inputs it declares: the check every
model's declaration passes (``tests/test_registry.py``) finds each kind of disagreement."""
import pytest

from bearing_sweep.models.registry import Input, Model, Output
from bearing_sweep.testing import assert_valid_declaration, documented_parameters


def _springs(load, stiffness=1.0e5, springs=2):
    """Springs in series.

    Parameters
    ----------
    load, stiffness : array_like
        Axial load [N] and the stiffness of one spring [N/m].
    springs : int
        Number of springs.

    Returns
    -------
    dict
    """


def _springs_undocumented(load, stiffness=1.0e5, springs=2):
    """Springs in series.

    Parameters
    ----------
    load : array_like
        Axial load [N]; stiffness : of one spring [N/m].
    springs, spring_count : int
    springs : int
    """


def _springs_without_section(load, stiffness=1.0e5, springs=2):
    """Springs in series, of a given load, stiffness and number."""


def springs_model(function):
    return Model("springs", function, "s", "r", "1",
                 (Input("load", "N", "l"), Input("stiffness", "N/mm", "k", default=100.0),
                  Input("springs", "1", "n", default=2, kind="count")),
                 (Output("deflection", "mm", "d"),))


def test_a_docstring_naming_every_input_passes():
    assert documented_parameters(_springs) == ["load", "stiffness", "springs"]
    assert_valid_declaration(springs_model(_springs))


def test_an_input_left_out_named_twice_or_unknown_fails():
    with pytest.raises(AssertionError) as raised:
        assert_valid_declaration(springs_model(_springs_undocumented))
    assert str(raised.value) == (
        "model 'springs': the docstring's Parameters: spring_count documented but not "
        "declared; the docstring's Parameters: stiffness declared but not documented; the "
        "docstring's Parameters: springs documented twice")


def test_a_docstring_without_parameters_fails():
    with pytest.raises(AssertionError, match="no Parameters section"):
        assert_valid_declaration(springs_model(_springs_without_section))
