"""kick.simulate and kick.simulate3d against the command line's JSON."""

import math

import pytest

import kick
from conftest import cli, flags, same

CASES_1D = [
    {},
    {"foot_mass": 8.0, "stiffness": 1.8e6},
    {"damping": 0.0},
    {"ball_speed": -8.0, "drive_force": 500.0},
    {"exponent": 1.0, "damping": 450.0},
    {"solver": "seed-rk4", "dt": 1e-6},
    {"solver": "accurate", "foot_speed": 30.0},
    {"law": "hunt-crossley", "restitution": 0.6},
    {"law": "kelvin-voigt", "restitution": 0.8, "solver": "reduced"},
    # The pressurised ball by name, at its defaults and with a set pressure.
    {"law": "shell"},
    {"law": "shell", "inflation_pressure": 6.0e4, "shell_damping": 3000.0, "solver": "accurate"},
]


@pytest.mark.parametrize("case", CASES_1D)
def test_simulate_equals_the_cli(kick_bin, case):
    expected = cli(kick_bin, "simulate", "--format", "json", *flags(**case))
    same(kick.simulate(**case), expected)


CASES_3D = [
    {},
    {"offset": 0.05, "approach_angle": 10.0, "friction": 0.5},
    {"offset": 0.03, "friction": math.inf, "foot_inertia": (0.01, 0.02, 0.02)},
    {"offset": 0.04, "law": "hunt-crossley-exact", "restitution": 0.6, "foot_half_extents": (0.03, 0.1, 0.04)},
    # The shell ball's own keywords reach the 3D kick; rigid grip is a constraint.
    {"offset": 0.05, "law": "shell", "inflation_pressure": 6.0e4, "shell_damping": 3000.0},
    {"offset": 0.05, "friction": 0.8, "tangential_stiffness": float("inf")},
    # The instep's keywords: a face turned by yaw and pitch, a convex cap, the patch contact.
    {"offset": 0.03, "face_yaw": 5.0, "face_pitch": -3.0},
    {"offset": 0.05, "law": "shell", "face_yaw": 0.0, "instep_radius": 0.15, "patch_contact": True, "friction": 0.0},
    # The foot's line below and beside the centre on a rising path (offset, contact_depth: one definition).
    {"offset": 0.04, "contact_depth": 0.03, "approach_angle": 10.0},
]


@pytest.mark.parametrize("case", CASES_3D)
def test_simulate3d_equals_the_cli(kick_bin, case):
    expected = cli(kick_bin, "simulate3d", "--format", "json", *flags(**case))
    result = kick.simulate3d(**case)
    assert result["launch_velocity"].shape == (3,) and result["spin"].shape == (3,)
    same(result, expected)


def test_simulate3d_flies_its_kick_as_the_cli(kick_bin):
    """`flight=True` is `--flight`: the ball from the ground, a list of distances the planes."""
    case = {"offset": 0.04, "contact_depth": 0.03, "air_density": 1.1}
    expected = cli(kick_bin, "simulate3d", "--format", "json", *flags(**case), "--flight", "--distance", "9.15", "--distance", "25")
    result = kick.simulate3d(flight=True, distance=[9.15, 25.0], **case)
    same(result, expected)
    crossings = result["flight"]["crossings"]
    assert [c["distance"] for c in crossings] == [9.15, 25.0]
    # Each plane is the crossing a flight with that one distance gives.
    for c in crossings:
        one = kick.simulate3d(flight=True, distance=c["distance"], **case)["flight"]["crossing"]
        same(c, _plain(one))
    with pytest.raises(ValueError, match="give flight=True"):
        kick.simulate3d(air_density=1.1)


ERRORS = [
    ("simulate", {"foot_mass": -1.0}),
    ("simulate", {"foot_speed": 1.0, "ball_speed": 5.0}),
    ("simulate", {"law": "flores"}),
    ("simulate", {"restitution": 1.5, "law": "flores"}),
    ("simulate3d", {"offset": 0.2}),
    ("simulate3d", {"approach_angle": 95.0}),
    ("simulate3d", {"foot_inertia": (1.0, -1.0, 1.0)}),
    # Settings that do not apply are refused, never ignored.
    ("simulate", {"restitution": 0.5}),
    ("simulate", {"law": "flores", "restitution": 0.5, "damping": 100.0}),
    ("simulate", {"solver": "accurate", "dt": 1e-6}),
    ("simulate3d", {"solver": "accurate", "dt": 1e-6}),
    ("simulate3d", {"law": "hunt-crossley", "restitution": 0.5, "damping": 100.0}),
    ("simulate", {"inflation_pressure": 7.0e4}),
    ("simulate", {"law": "shell", "damping": 100.0}),
    ("simulate", {"law": "shell", "restitution": 0.6}),
    ("simulate3d", {"patch_contact": True}),
    ("simulate3d", {"law": "shell", "instep_radius": 1.0e10, "face_yaw": 0.0}),
]


# Not refused: a numerical failure (a step beyond seed-rk4's stability) and a proven trap.
NOT_REFUSED = [
    ("simulate", {"solver": "seed-rk4", "dt": 1e-3}, kick.NumericalError),
    ("simulate", {"drive_force": 1e5}, RuntimeError),
]


@pytest.mark.parametrize("function,case,raises", [(f, c, ValueError) for f, c in ERRORS] + NOT_REFUSED)
def test_errors_carry_the_cli_message(kick_bin, function, case, raises):
    message = cli(kick_bin, function, *flags(**case), ok=False)
    with pytest.raises(raises) as error:
        getattr(kick, function)(**case)
    assert type(error.value) is raises
    assert str(error.value) == message


def test_many_refuses_settings_that_do_not_apply():
    """A setting the law or solver would ignore fails the call, not each row."""
    with pytest.raises(ValueError, match="`damping` does not apply to law `flores`"):
        kick.simulate_many(law="flores", restitution=0.5, damping=[10.0, 20.0])
    with pytest.raises(ValueError, match="`restitution` does not apply to law `power-law`"):
        kick.simulate3d_many(restitution=[0.5, 0.6])
    with pytest.raises(ValueError, match="`dt` does not apply to solver `auto`"):
        kick.simulate_many(dt=1e-6, foot_mass=[1.0, 2.0])


def test_unknown_names_list_the_valid_ones():
    """The CLI refuses these in its argument parser (clap's wording); Python gives the library's."""
    with pytest.raises(ValueError, match="unknown solver `rk5`: expected one of auto, seed-rk4, accurate"):
        kick.simulate(solver="rk5")
    with pytest.raises(ValueError, match="unknown 3D solver `ode`: expected one of auto, accurate, full-state, 1d, rapier"):
        kick.simulate3d(solver="ode")
    with pytest.raises(ValueError, match="hertz"):
        kick.simulate(law="hertz")


def test_unknown_keywords_name_the_nearby_ones():
    with pytest.raises(ValueError, match=r"unknown parameter `foot_mas` of the 1D scenario or bounce or foot: did you mean `foot_mass`\?"):
        kick.simulate(foot_mas=3.0)
    # A 3D parameter is not a keyword of the 1D function.
    with pytest.raises(ValueError, match="unknown parameter `offset` of the 1D scenario"):
        kick.simulate(offset=0.01)
    with pytest.raises(ValueError, match="`foot_inertia` takes three numbers, got a number"):
        kick.simulate3d(foot_inertia=1.0)
    with pytest.raises(ValueError, match="`foot_mass` takes a number, got three numbers"):
        kick.simulate(foot_mass=[1.0, 2.0, 3.0])


def test_every_declared_keyword_is_accepted_with_its_default():
    """The keywords are exactly the CLI's flags; giving each its declared default changes nothing."""
    for function in ("simulate", "simulate3d"):
        base = getattr(kick, function)()
        shell = getattr(kick, function)(law="shell")
        leg = getattr(kick, function)(leg=True)
        for p in kick.keywords(function):
            if p["default"] is not None:
                # The shell ball's keywords apply under law="shell" only.
                if p["level"] == "bounce":
                    same(getattr(kick, function)(law="shell", **{p["name"]: p["default"]}), _plain(shell))
                # The leg's pose applies with leg=True only (refused without it, by name).
                elif p["name"] in ("knee", "ankle", "hip"):
                    same(getattr(kick, function)(leg=True, **{p["name"]: p["default"]}), _plain(leg))
                else:
                    same(getattr(kick, function)(**{p["name"]: p["default"]}), _plain(base))


def _plain(d):
    return {k: (_plain(v) if isinstance(v, dict) else v.tolist() if hasattr(v, "tolist") else v) for k, v in d.items()}


def test_help_lists_keywords_with_symbol_unit_and_default():
    doc = kick.simulate.__doc__
    assert "foot_mass : scalar, m_f [kg], default 3" in doc
    assert "stiffness : scalar, k [N/m^n], default 4.2e5" in doc
    assert "v_ball_out : m/s" in doc
    import inspect

    signature = inspect.signature(kick.simulate3d)
    assert signature.parameters["foot_half_extents"].default == (0.03, 0.12, 0.05)
    assert signature.parameters["ball_inertia"].default is None  # derived: 2/3 m_b R^2
    assert list(signature.parameters)[:2] == ["foot_mass", "ball_mass"]


def test_a_ball_hitting_a_resting_foot_has_no_speed_ratio():
    """v_f- = 0: the ratio v_b+/v_f- is undefined (None, never NaN); the rest
    of the outcome conserves momentum (no drive force)."""
    out = kick.simulate(foot_speed=0.0, ball_speed=-6.0, drive_force=0.0)
    assert out["speed_ratio"] is None
    m_f, m_b = out["scenario"]["foot_mass"], out["scenario"]["ball_mass"]
    momentum = m_f * out["v_foot_out"] + m_b * out["v_ball_out"]
    assert abs(momentum - m_b * -6.0) <= 1e-9 * m_b * 6.0


def test_every_law_is_listed_from_the_one_list():
    """Issue 33, fault 14: kick.LAWS and every ``law`` help list the shell."""
    assert kick.LAWS == ["power-law", "hunt-crossley", "lankarani-nikravesh", "flores", "hunt-crossley-exact", "kelvin-voigt", "shell"]
    for f in (kick.simulate, kick.simulate_many, kick.simulate3d, kick.simulate3d_many, kick.history, kick.history3d, kick.aim):
        law = f.__doc__[f.__doc__.index("law : str"):]
        assert all(name in law for name in kick.LAWS), f.__name__


def test_the_leg_is_the_clis_leg_and_its_pose_needs_it(kick_bin):
    """leg=True with a pose is `kick simulate --leg --knee ...`, bit for bit: the
    leg's apparent mass (Eq. 11, below Table 1's 3 kg) and the identified boot
    (a longer kick than the rigid foot's). A pose without the leg is refused by name."""
    out = kick.simulate(law="shell", leg=True, knee=40.0)
    same(out, cli(kick_bin, "simulate", "--format", "json", "--law", "shell", *flags(leg=True, knee=40.0)))
    assert 1.0 < out["scenario"]["foot_mass"] < 2.0
    assert out["foot"]["boot_stiffness"] > 0 and out["foot"]["knee"] == 40.0
    assert out["contact_time"] > kick.simulate(law="shell")["contact_time"]
    with pytest.raises(ValueError, match="`knee`"):
        kick.simulate(knee=40.0)
