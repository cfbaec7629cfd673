"""kick.fit against `kick fit data SPEC --format json` on the same data."""

import numpy as np
import pytest

import kick
from conftest import cli

TRUTH = {"stiffness": 4.2e5, "damping": 120.0}
SIGMA = 25.0


def synthetic(n=60, seed=3):
    """A force history of Table 1's baseline plus Gaussian noise of SIGMA."""
    h = kick.history(samples=n, solver="accurate", **TRUTH)
    rng = np.random.default_rng(seed)
    return h["time"], h["force"] + rng.normal(0.0, SIGMA, n)


def test_fit_equals_the_cli_and_finds_the_truth(kick_bin, tmp_path):
    time, force = synthetic()
    (tmp_path / "data.csv").write_text("time,force\n" + "".join(f"{t!r},{f!r}\n" for t, f in zip(time.tolist(), force.tolist())))
    (tmp_path / "spec.toml").write_text(
        'free = ["stiffness", "damping"]\n[scenario]\nstiffness = 3e5\ndamping = 150.0\n'
        f'[history]\nfile = "data.csv"\nsigma = {{ force = {SIGMA!r} }}\n'
    )
    expected = cli(kick_bin, "fit", "data", tmp_path / "spec.toml", "--format", "json")
    out = kick.fit(time, force, sigma=SIGMA, free=["stiffness", "damping"], stiffness=3e5, damping=150.0)

    assert out["names"] == [e["parameter"] for e in expected["estimates"]] == ["stiffness", "damping"]
    assert out["estimate"].tolist() == [e["value"] for e in expected["estimates"]]
    assert out["standard_error"].tolist() == [e["standard_uncertainty"] for e in expected["estimates"]]
    assert out["start"].tolist() == [3e5, 150.0]
    assert out["correlation"].tolist() == expected["correlation"]
    assert out["singular_values"].tolist() == expected["singular_values"]
    assert out["residuals"].tolist() == [r["weighted"] for r in expected["residuals"]]
    for key in ("chi_square", "degrees_of_freedom", "residual_variance", "termination", "converged", "evaluations"):
        assert out[key] == expected[key], key
    assert out["stop"] == expected["stop"]["kind"] == "converged"
    # Covariance: ρ_ij σ_i σ_j, so σ² on the diagonal.
    s = out["standard_error"]
    np.testing.assert_allclose(out["covariance"], out["correlation"] * np.outer(s, s), rtol=1e-15)
    # The truth lies within 4 standard errors of the estimate.
    for name, value, error in zip(out["names"], out["estimate"], s):
        assert abs(value - TRUTH[name]) < 4 * error, (name, value, error)


def test_bad_input_is_refused_naming_it(kick_bin, tmp_path):
    time, force = synthetic(20)
    with pytest.raises(ValueError, match=r"unknown parameter `stifness`: did you mean `stiffness`\?"):
        kick.fit(time, force, sigma=SIGMA, free=["stifness"])
    with pytest.raises(ValueError, match=r"fit data: time\[3\] = .* does not increase"):
        kick.fit(time[[0, 1, 2, 2, 4]], force[:5], sigma=SIGMA, free=["stiffness"])
    with pytest.raises(ValueError, match="`force` has 19 values for 20 times"):
        kick.fit(time, force[:-1], sigma=SIGMA, free=["stiffness"])
    with pytest.raises(ValueError, match="no data channel"):
        kick.fit(time, sigma=SIGMA, free=["stiffness"])
    with pytest.raises(ValueError, match="unknown keyword `forces`: did you mean `force`"):
        kick.fit(time, sigma=SIGMA, free=["stiffness"], forces=force)
    # The same refusal as the CLI for an unknown free parameter in a specification file.
    (tmp_path / "d.csv").write_text("time,force\n" + "".join(f"{t!r},{f!r}\n" for t, f in zip(time.tolist(), force.tolist())))
    (tmp_path / "s.toml").write_text(f'free = ["stifness"]\n[history]\nfile = "d.csv"\nsigma = {{ force = {SIGMA} }}\n')
    message = cli(kick_bin, "fit", "data", tmp_path / "s.toml", ok=False)
    with pytest.raises(ValueError) as error:
        kick.fit(time, force, sigma=SIGMA, free=["stifness"])
    # The file's refusal also names where: `s.toml:1: `free[0]`: ` before the same words.
    assert message.endswith(str(error.value)) and "s.toml:1" in message, message


def test_two_channels_with_their_own_sigma():
    h = kick.history(samples=40, solver="accurate")
    out = kick.fit(
        h["time"], h["force"], compression=h["compression"], sigma={"force": 10.0, "compression": 1e-5},
        free=["stiffness"], stiffness=5e5,
    )
    # Noise-free data of the truth: the fit returns it.
    assert out["estimate"][0] == pytest.approx(4.2e5, rel=1e-6)
    assert len(out["residuals"]) == 80
