"""Exceptions by what became of the call (`kick_core::Status`), with the CLI's message."""

import pytest

import kick
from conftest import cli, flags


def test_a_numerical_failure_raises_numerical_error_with_the_cli_message(kick_bin):
    assert issubclass(kick.NumericalError, RuntimeError)
    assert not issubclass(kick.NumericalError, ValueError)
    # A fixed step beyond seed-rk4's stability limit on a stiff contact.
    with pytest.raises(kick.NumericalError) as stiff:
        kick.simulate(solver="seed-rk4", dt=1e-4, stiffness=1e12)
    assert str(stiff.value) == cli(kick_bin, "simulate", "--solver", "seed-rk4", "--dt", "1e-4", *flags(stiffness=1e12), ok=False)
    assert str(stiff.value).startswith("step too large")
    # seed-rk4's step budget runs out under a drive that keeps the ball pressed: not a proof of trapping.
    with pytest.raises(kick.NumericalError, match="not proven trapped"):
        kick.simulate(solver="seed-rk4", drive_force=1e5)
    with pytest.raises(kick.NumericalError, match="step too large"):
        kick.history(solver="seed-rk4", dt=1e-4, stiffness=1e12, samples=10)


def test_a_proven_trap_is_a_runtime_error_not_a_numerical_one(kick_bin):
    with pytest.raises(RuntimeError) as trapped:
        kick.simulate(drive_force=1e5)
    assert type(trapped.value) is RuntimeError
    assert str(trapped.value) == cli(kick_bin, "simulate", *flags(drive_force=1e5), ok=False)
    assert str(trapped.value).startswith("trapped")


def test_bad_input_is_still_a_value_error_naming_the_keyword():
    with pytest.raises(ValueError, match="`foot_mass` = -1: must be"):
        kick.simulate(foot_mass=-1.0)
    with pytest.raises(ValueError, match="`frobnicate`"):
        kick.simulate(frobnicate=1.0)
    with pytest.raises(ValueError, match="unknown solver `nope`"):
        kick.simulate(solver="nope")
    # dt with an adaptive solver: refused, not a numerical failure.
    with pytest.raises(ValueError, match="`dt` does not apply"):
        kick.simulate(solver="accurate", dt=1e-6)
