"""kick.bounce and kick.bounce_many: the ball alone on a rigid plate (kick-bounce),
against `kick bounce --format json`, closed forms computed here, and each other."""

import math

import numpy as np
import pytest

import kick
from conftest import cli, flags

G = 9.81
FIFA_DROP = 2.0  # m: the FIFA Quality Programme rebound test drops the ball from 2 m onto steel


def exact_restitution(x0: float) -> float:
    """e = x_e/x0, x_e in (0, 1) the root of x0 - ln(1 + x0) = -x_e - ln(1 - x_e),
    by bisection here (the hysteresis relation the shell's loss obeys on a plate)."""
    lhs = x0 - math.log1p(x0)
    low, high = 0.0, 1.0 - 1e-16
    for _ in range(200):
        mid = 0.5 * (low + high)
        if lhs - (-mid - math.log1p(-mid)) > 0.0:
            low = mid
        else:
            high = mid
    return 0.5 * (low + high) / x0


def test_the_fifa_drop_equals_the_cli_and_meets_the_test(kick_bin):
    out = kick.bounce(drop_height=FIFA_DROP)
    expected = cli(kick_bin, "bounce", "--drop-height", FIFA_DROP, "--format", "json")
    assert sorted(out) == sorted(expected)
    for key, value in expected.items():
        if isinstance(value, list):
            assert np.asarray(out[key]).tolist() == value, key
        else:
            assert out[key] == value, key
    # Dropped from rest: V = sqrt(2 g H); the rebound v_z = e V rises e^2 H.
    assert out["impact_velocity"][2] == pytest.approx(-math.sqrt(2 * G * FIFA_DROP), rel=1e-15)
    assert out["rebound_height"] == pytest.approx(out["restitution"] ** 2 * FIFA_DROP, rel=1e-12)
    # A licensed ball rebounds 115-165 cm.
    assert 1.15 <= out["rebound_height"] <= 1.65, out["rebound_height"]


def test_slow_impacts_follow_the_hysteresis_relation_computed_here():
    """At small compression the shell law is Hunt-Crossley with chi = beta/(p0 + k_s/(2 pi R)):
    a slow, gravity-free bounce has the hysteresis relation's e(chi V), to O(delta/R) of 1 - e."""
    keywords = {p["name"]: p["default"] for p in kick.keywords("bounce")}
    beta, p0 = keywords["shell_damping"], keywords["inflation_pressure"]
    for v, damping in ((0.05, beta), (0.05, 30 * beta), (0.1, 10 * beta)):
        out = kick.bounce(speed=v, gravity=0.0, shell_damping=damping)
        e = exact_restitution(damping / p0 * v)
        assert abs(out["restitution"] - e) < out["max_compression"] / 0.11 * (1 - e), v


def test_energy_in_is_energy_out_plus_the_losses():
    """Oblique, spinning, gripping (friction inf), gravity off: the kinetic energy lost is
    the normal phase's 1/2 m Vn^2 (1 - e^2) plus the grip's 1/2 m_t u^2 (1 - e_t^2),
    with u the contact point's slip and m_t = 1/(1/m + R^2/I)."""
    m, r, speed, angle, e_t = 0.43, 0.11, 14.0, 35.0, 0.3
    spin = np.array([0.0, -12.0, 5.0])
    inertia = 2.0 / 3.0 * m * r * r
    out = kick.bounce(speed=speed, angle=angle, spin=spin, friction=math.inf, tangential_restitution=e_t, gravity=0.0)
    assert out["tangential"] == "grips"

    def kinetic(v, w):
        return 0.5 * m * np.dot(v, v) + 0.5 * inertia * np.dot(w, w)

    v_in = np.array(out["impact_velocity"])
    v_n = speed * math.cos(math.radians(angle))
    u = speed * math.sin(math.radians(angle)) - r * spin[1]
    m_t = 1.0 / (1.0 / m + r * r / inertia)
    loss = 0.5 * m * v_n**2 * (1 - out["restitution"] ** 2) + 0.5 * m_t * u**2 * (1 - e_t**2)
    energy_in = kinetic(v_in, spin)
    energy_out = kinetic(np.array(out["exit_velocity"]), np.array(out["exit_spin"]))
    assert energy_in == pytest.approx(energy_out + loss, rel=1e-12)
    assert loss > 0.05 * energy_in  # a real loss, not rounding


def test_many_equals_one_by_one():
    speed = np.array([3.0, 8.0, 20.0, 0.0])[:, None]  # 0: refused in its row
    angle = np.array([0.0, 20.0, 60.0])
    spin = np.array([[0.0, -30.0, 2.0], [10.0, 0.0, 0.0], [0.0, 40.0, 0.0]])
    many = kick.bounce_many(speed=speed, angle=angle, spin=spin, friction=0.4)
    assert many["restitution"].shape == (4, 3) and many["exit_spin"].shape == (4, 3, 3)
    codes = {"no_slip": 0, "grips": 1, "slides": 2}
    for i in range(4):
        for j in range(3):
            row = dict(speed=float(speed[i, 0]), angle=float(angle[j]), spin=spin[j], friction=0.4)
            if speed[i, 0] == 0.0:
                with pytest.raises(ValueError) as refused:
                    kick.bounce(**row)
                assert kick.STATUS[int(many["status"][i, j])] == "refused"
                k = list(many["failure_index"]).index(i * 3 + j)
                assert many["failure_message"][k] == str(refused.value)
                assert np.isnan(many["restitution"][i, j])
                continue
            one = kick.bounce(**row)
            assert many["status"][i, j] == 0 and many["evaluations"][i, j] == one["evaluations"]
            for name, _ in kick.BOUNCE_COLUMNS:
                got = many[name][i, j]
                if name == "tangential":
                    assert got == codes[one[name]]
                elif name == "rebound_height":
                    assert np.isnan(got)
                else:
                    np.testing.assert_array_equal(got, one[name], err_msg=name)


def test_keywords_are_the_flags_and_unknown_ones_are_refused(kick_bin):
    names = [p["name"] for p in kick.keywords("bounce")]
    assert names == [p["name"] for p in kick.BOUNCE_PARAMETERS] and "speed" in names and "foot_mass" not in names
    args = dict(speed=9.0, angle=15.0, spin=[1.0, -2.0, 3.0], inflation_pressure=9e4)
    assert cli(kick_bin, "bounce", *flags(**args), "--format", "json")["exit_spin"] == list(kick.bounce(**args)["exit_spin"])
    for call in (kick.bounce, kick.bounce_many):
        with pytest.raises(ValueError, match=r"unknown parameter `sped` of the bounce: did you mean `speed`\?"):
            call(sped=3.0)
        with pytest.raises(ValueError, match="unknown parameter `foot_mass`"):
            call(speed=3.0, foot_mass=2.0)
        with pytest.raises(ValueError, match="unknown contact law `hertz`: expected one of power-law, .*, shell"):
            call(speed=3.0, law="hertz")
    with pytest.raises(ValueError, match=r"`speed` takes a number, got a bool \(true or false\)"):
        kick.bounce(speed=True)  # a switch where a number belongs, as `simulate` says it
    with pytest.raises(ValueError, match="`stiffness`"):
        kick.bounce(speed=5.0, stiffness=1e5)  # a parameter of the kick's laws, not the shell's
    paper = kick.bounce(law="power-law", drop_height=FIFA_DROP)
    assert paper["restitution"] == cli(kick_bin, "bounce", "--law", "power-law", "--drop-height", FIFA_DROP, "--format", "json")["restitution"]
