"""Ctrl-C during a long call stops it within moments: the calls solve
without the GIL and check for signals while they run."""

import re
import signal
import subprocess
import sys
import time

import pytest

# Each call would run for tens of seconds (2e7 1D rows took 46 s on 2 cores in release).
CALLS = {
    "simulate_many": ("np.linspace(1.0, 8.0, 20_000_000)", "kick.simulate_many(foot_mass=x, threads=1)"),
    "simulate3d_many": ("np.linspace(0.0, 0.05, 2_000_000)", "kick.simulate3d_many(offset=x, threads=1)"),
    # A fit of six parameters to a reversed pulse of 200,000 samples: 22 s in a
    # debug build; the optimiser asks the cancel check before every evaluation.
    "fit": (
        "kick.history(samples=200_000, solver='accurate')",
        "kick.fit(x['time'], x['force'][::-1].copy(), sigma=25.0, stiffness=3e5, foot_mass=2.0, "
        "free=['stiffness', 'damping', 'foot_mass', 'exponent', 'foot_speed', 'time_offset'])",
    ),
    # Issue 33, fault 8: these two ignored Ctrl-C until they finished (46.5 s, 11.8 s).
    "flight_many": ("np.linspace(20.0, 30.0, 5_000_000)", "kick.flight_many(speed=x, launch_angle=20.0, threads=1)"),
    # Issue 32: the progress bar draws from the loop that listens for Ctrl-C.
    "simulate3d_many with a bar": ("np.linspace(0.0, 0.05, 2_000_000)", "kick.simulate3d_many(offset=x, threads=1, progress=True)"),
    "aim": ("(25.0, -2.0, 1.8)", "[kick.aim(x, from_='kick', wall=(9.15, 1.9, 1.0), law=law) for _ in range(20) for law in ('power-law', 'shell')]"),
}
# Seconds between the start of a call and Ctrl-C (the fit is the shortest call).
WAIT = {"fit": 0.3, "aim": 0.3}


@pytest.mark.skipif(sys.platform == "win32", reason="SIGINT to a child process")
@pytest.mark.parametrize("call", sorted(CALLS))
def test_ctrl_c_interrupts_a_long_call(call):
    given, solve = CALLS[call]
    script = f"import numpy as np, kick\nx = {given}\nprint('solving', flush=True)\n{solve}\nprint('returned', flush=True)\n"
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline() == "solving\n"
        time.sleep(WAIT.get(call, 1.0))
        child.send_signal(signal.SIGINT)
        sent = time.monotonic()
        out, err = child.communicate(timeout=10)
    except subprocess.TimeoutExpired:
        child.kill()
        child.communicate()
        pytest.fail(f"{call} ignored Ctrl-C for 10 s")
    waited = time.monotonic() - sent
    assert "returned" not in out
    assert err.rstrip().endswith("KeyboardInterrupt"), err[-2000:]
    print(f"\n{call}: interrupted {waited:.2f} s after SIGINT")
    assert waited < 5.0
    if "progress=True" in solve:
        # The bar left at the rows done, below the total; the traceback on a line of its own.
        counts = [int(n) for n in re.findall(r"(\d+)/2000000 rows", err)]
        assert counts and 0 < counts[-1] < 2_000_000, err[-2000:]
        assert "\nTraceback" in err
