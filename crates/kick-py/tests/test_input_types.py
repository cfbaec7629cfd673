"""Keyword values a numpy user might pass: real numbers and arrays of them
are taken; anything else is a TypeError (a masked value a ValueError) that
names the keyword and the type it got, never a silent conversion."""

import decimal
import fractions

import numpy as np
import pytest

import kick

# (value, the type named in the message) for a keyword that takes a number.
NOT_REAL = [
    ("3", "str"),
    ({}, "dict"),
    ([1.0], "list"),
    (np.complex128(3.0 + 1.0j), "complex128"),
    (np.array([3.0 + 0.5j]), "complex128"),
    (np.datetime64(3, "s"), "datetime64"),
    (np.timedelta64(3, "s"), "timedelta64"),
    (np.array(["3.0"]), "<U3"),
    (np.array([3.0, None]), "object"),
]


@pytest.mark.parametrize("value,named", NOT_REAL)
def test_simulate_refuses_what_is_not_a_real_number(value, named):
    with pytest.raises(TypeError, match=rf"`foot_mass` takes a number, got .*{named}") as error:
        kick.simulate(foot_mass=value)
    assert "three numbers" not in str(error.value)


@pytest.mark.parametrize("value,named", [v for v in NOT_REAL if v[1] != "list"])
def test_simulate_many_refuses_what_is_not_real_numbers(value, named):
    with pytest.raises(TypeError, match=rf"`foot_mass` takes .*numbers, got .*{named}"):
        kick.simulate_many(foot_mass=value)


def test_vectors_refuse_complex_and_strings():
    with pytest.raises(TypeError, match=r"`foot_inertia` takes three numbers \(x, y, z\), got .*complex128"):
        kick.simulate3d(foot_inertia=np.array([0.01, 0.02, 0.02j]))
    with pytest.raises(TypeError, match=r"`foot_inertia` takes three numbers \(x, y, z\), got str"):
        kick.simulate3d(foot_inertia="abc")
    with pytest.raises(TypeError, match=r"`foot_inertia` .*numbers.*, got .*complex128"):
        kick.simulate3d_many(foot_inertia=np.array([[0.01, 0.02, 0.02j]]))


def test_switches_take_bools_only():
    with pytest.raises(TypeError, match=r"`gravity` takes true or false, got .*str"):
        kick.simulate3d(gravity="yes")
    with pytest.raises(TypeError, match=r"`foot_mass` takes .*numbers, got .*bool"):
        kick.simulate_many(foot_mass=np.array([True, False]))
    with pytest.raises(TypeError, match=r"`gravity` takes true or false, got .*float64"):
        kick.simulate3d_many(gravity=np.array([0.0, 1.0]))
    # A bool array is a switch per row.
    rows = kick.simulate3d_many(offset=0.03, gravity=np.array([False, True]))
    assert rows["speed"][1] == kick.simulate3d(offset=0.03, gravity=True)["speed"]


def test_masked_values_are_refused_and_unmasked_arrays_taken():
    masked = np.ma.masked_array([3.0, 4.0], mask=[False, True])
    with pytest.raises(ValueError, match=r"`foot_mass` .*1 masked"):
        kick.simulate_many(foot_mass=masked)
    with pytest.raises(ValueError, match=r"`foot_mass` .*1 masked"):
        kick.simulate(foot_mass=np.ma.masked_array(3.0, mask=True))
    clear = np.ma.masked_array([3.0, 4.0], mask=[False, False])
    np.testing.assert_array_equal(kick.simulate_many(foot_mass=clear)["v_ball_out"], kick.simulate_many(foot_mass=[3.0, 4.0])["v_ball_out"])


def test_real_numbers_of_any_kind_are_taken():
    base = kick.simulate(foot_mass=3.0)["v_ball_out"]
    for value in (3, np.int8(3), np.uint16(3), np.float32(3.0), np.array(3.0), np.longdouble(3.0)):
        assert kick.simulate(foot_mass=value)["v_ball_out"] == base, value
    many = kick.simulate_many(foot_mass=np.array([3, 3], dtype=np.int32))["v_ball_out"]
    assert many.tolist() == [base, base]


def test_a_ragged_list_names_the_keyword():
    with pytest.raises(ValueError, match=r"`foot_mass`.*inhomogeneous"):
        kick.simulate_many(foot_mass=[[1.0], [1.0, 2.0]])


def test_fit_refuses_a_string_for_free_and_complex_data():
    t = np.linspace(0.0, 9e-3, 10)
    force = 1000.0 * np.sin(np.pi * t / 9e-3)
    with pytest.raises(TypeError, match=r"`free` takes a list of names, got str 'foot_mass'"):
        kick.fit(t, force, sigma=1.0, free="foot_mass")
    with pytest.raises(TypeError, match=r"`force` takes .*numbers, got .*complex128"):
        kick.fit(t, force + 1.0j, sigma=1.0, free=["foot_mass"])
    with pytest.raises(TypeError, match=r"`time` takes .*numbers, got str"):
        kick.fit("0.001", force, sigma=1.0, free=["foot_mass"])
    with pytest.raises(TypeError, match=r"`sigma` takes a number or a dict .*, got str"):
        kick.fit(t, force, sigma="1", free=["foot_mass"])


def test_options_refuse_complex_numbers():
    with pytest.raises(TypeError, match=r"`dt` takes a number, got .*complex128"):
        kick.simulate(solver="seed-rk4", dt=np.complex128(5e-6 + 1.0j))
    with pytest.raises(TypeError, match=r"`interval` takes a number, got .*complex128"):
        kick.history(interval=np.complex128(1e-4 + 1.0j))


# Every count keyword, as a call taking it: `samples` of the histories,
# `threads` of the `_many` functions.
COUNTS = {
    "history.samples": ("samples", lambda n: kick.history(samples=n)),
    "history3d.samples": ("samples", lambda n: kick.history3d(samples=n)),
    "simulate_many.threads": ("threads", lambda n: kick.simulate_many(foot_mass=[3.0, 4.0], threads=n)),
    "simulate3d_many.threads": ("threads", lambda n: kick.simulate3d_many(offset=[0.0, 0.02], threads=n)),
    "flight_many.threads": ("threads", lambda n: kick.flight_many(speed=[20.0, 25.0], launch_angle=20.0, threads=n)),
}

# (value, the type named in the message): what is not an int is a TypeError,
# a whole float included (as `range(3.0)` refuses it).
NOT_INT = [(3.0, "float 3.0"), (2.5, "float 2.5"), (np.float64(3.0), "float64"), (True, "bool"), (np.bool_(True), "bool"), ("3", "str"), (3 + 0j, "complex")]


@pytest.mark.parametrize("call", COUNTS)
@pytest.mark.parametrize("value,named", NOT_INT)
def test_counts_refuse_what_is_not_an_int(call, value, named):
    keyword, f = COUNTS[call]
    with pytest.raises(TypeError, match=rf"`{keyword}` takes a whole number \(int\), got .*{named}"):
        f(value)


def test_a_whole_float_count_says_how_to_write_it():
    with pytest.raises(TypeError, match=r"got float 1000000.0: write samples=1000000"):
        kick.history(samples=1e6)


@pytest.mark.parametrize("call", COUNTS)
@pytest.mark.parametrize("value", [-1, 10**6 + 1, 2**64, 10**30, np.int64(-5), np.uint64(2**64 - 1)])
def test_counts_out_of_range_name_the_keyword_and_the_limit(call, value):
    keyword, f = COUNTS[call]
    low, high = (2, 1_000_000) if keyword == "samples" else (1, r"\d+")
    with pytest.raises(ValueError, match=rf"`{keyword}` = {int(value)}: must be between {low} and {high}"):
        f(value)


def test_numpy_integer_counts_are_taken():
    for n in (np.int8(40), np.uint16(40), np.int64(40), np.array(40)):
        h = kick.history(samples=n)
        assert len(h["time"]) == 40, n
        np.testing.assert_array_equal(h["time"], kick.history(samples=40)["time"])
    assert len(kick.history3d(samples=np.int32(25))["time"]) == 25
    one = kick.simulate_many(foot_mass=[3.0, 4.0], threads=np.uint8(2))["v_ball_out"]
    np.testing.assert_array_equal(one, kick.simulate_many(foot_mass=[3.0, 4.0])["v_ball_out"])
    np.testing.assert_array_equal(
        kick.flight_many(speed=[20.0, 25.0], launch_angle=20.0, threads=np.int64(1))["flight_time"],
        kick.flight_many(speed=[20.0, 25.0], launch_angle=20.0)["flight_time"],
    )


# Issue 33, fault 7 and its kind: every entry point takes its values through
# one guard. (What the user gave, as the message names its type.)
NOT_A_NUMBER = [
    (np.complex128(20.0 + 1.0j), "complex128"),
    (np.datetime64("2020-01-01"), "datetime64"),
    ("20", "str"),
    (True, "bool"),
    (decimal.Decimal("20"), "Decimal"),
    (fractions.Fraction(20, 1), "Fraction"),
    ([20.0, True], "bool"),
]
ENTRY_POINTS = {
    "simulate": ("foot_speed", lambda v: kick.simulate(foot_speed=v)),
    "simulate_many": ("foot_speed", lambda v: kick.simulate_many(foot_speed=v)),
    "simulate3d": ("foot_speed", lambda v: kick.simulate3d(foot_speed=v)),
    "simulate3d_many": ("foot_speed", lambda v: kick.simulate3d_many(foot_speed=v)),
    "history": ("foot_speed", lambda v: kick.history(foot_speed=v, samples=10)),
    "history3d": ("foot_speed", lambda v: kick.history3d(foot_speed=v, samples=10)),
    "flight": ("speed", lambda v: kick.flight(speed=v, launch_angle=20.0)),
    "flight_many": ("speed", lambda v: kick.flight_many(speed=v, launch_angle=20.0)),
    "bounce": ("speed", lambda v: kick.bounce(speed=v)),
    "bounce_many": ("speed", lambda v: kick.bounce_many(speed=v)),
    "aim": ("speed", lambda v: kick.aim((25.0, 0.0, 1.5), speed=v)),
    "aim.target": ("target", lambda v: kick.aim((25.0, v, 1.5))),
}


@pytest.mark.parametrize("entry", sorted(ENTRY_POINTS))
@pytest.mark.parametrize("value,named", NOT_A_NUMBER, ids=[n for _, n in NOT_A_NUMBER])
def test_every_entry_point_refuses_what_is_not_a_real_number(entry, value, named):
    keyword, call = ENTRY_POINTS[entry]
    if entry.endswith("_many") or entry == "aim.target" or not isinstance(value, list):
        # A single call's keyword takes one number: a list is a shape error of its own.
        with pytest.raises((TypeError, ValueError), match=rf"`{keyword}`") as error:
            call(value)
        if entry != "aim.target" and not isinstance(value, list):
            assert named in str(error.value) or "switch" in str(error.value), str(error.value)


@pytest.mark.parametrize("entry", ["simulate_many", "flight_many", "bounce_many"])
def test_masked_rows_are_refused_in_every_many_function(entry):
    keyword, call = ENTRY_POINTS[entry]
    with pytest.raises(ValueError, match=rf"`{keyword}` has 1 masked value"):
        call(np.ma.masked_array([20.0, 25.0], mask=[False, True]))


def test_flight_many_rows_are_single_flights():
    """flight_many through the *_many runner: every row the single call's."""
    speeds = np.array([[20.0, 25.0], [30.0, 1e-9]])
    out = kick.flight_many(speed=speeds, launch_angle=45.0, spin=[0.0, 0.0, 20.0], distance=9.15)
    assert out["landing_point"].shape == (2, 2, 2) and out["crossing_velocity"].shape == (2, 2, 3)
    for index in np.ndindex(2, 2):
        one = kick.flight(speed=speeds[index], launch_angle=45.0, spin=(0.0, 0.0, 20.0), distance=9.15)
        assert out["flight_time"][index] == one["flight_time"]
        assert np.array_equal(out["landing_velocity"][index], one["landing_velocity"])
        assert out["evaluations"][index] == one["evaluations"]
    # Fault 6: 1e-9 m/s takes 2 v sin(45 deg) / g, not half of it.
    assert abs(out["flight_time"][1, 1] / (2e-9 * np.sin(np.pi / 4) / 9.81) - 1.0) < 1e-6
