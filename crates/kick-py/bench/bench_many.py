"""simulate_many against `kick sweep`, alternately, in one run.

    python crates/kick-py/bench/bench_many.py [--samples 1000000] [--repeats 3] [--kick target/release/kick]

Each repeat runs `kick sweep --samples N --seed 1 --out TMP/sweep.h5` (its own
printed throughput: scenarios/s of the solve streamed to HDF5) and then
`kick.simulate_many` on the very scenarios of that file (read with h5py, not
timed), no file written. Prints both throughputs per repeat, the medians and
the ratio sweep/simulate_many (1.0: as fast; the target is <= 1.2).
"""

import argparse
import os
import re
import statistics
import subprocess
import tempfile
import time

import h5py
import numpy as np

import kick

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--samples", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--kick", default=os.path.join(ROOT, "target", "release", "kick"))
    args = parser.parse_args()
    sweep_rates, python_rates = [], []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "sweep.h5")
        for repeat in range(args.repeats):
            done = subprocess.run(
                [args.kick, "sweep", "--samples", str(args.samples), "--seed", "1", "--out", out],
                capture_output=True, text=True, check=True,
            )
            rate = float(re.search(r"([0-9.]+) scenarios/s", done.stdout).group(1))
            sweep_rates.append(rate)
            with h5py.File(out) as f:
                params = {name: f["parameters"][name][:] for name in f["parameters"]}
                expected = f["outcomes"]["v_ball_out"][:]
            start = time.perf_counter()
            result = kick.simulate_many(**params)
            seconds = time.perf_counter() - start
            python_rates.append(args.samples / seconds)
            same = np.array_equal(result["v_ball_out"], expected, equal_nan=True)
            print(f"repeat {repeat + 1}: kick sweep {rate:,.0f}/s, simulate_many {args.samples / seconds:,.0f}/s"
                  f" ({seconds:.2f} s; same v_ball_out as the file: {same})", flush=True)
    s, p = statistics.median(sweep_rates), statistics.median(python_rates)
    print(f"median: kick sweep {s:,.0f} scenarios/s, simulate_many {p:,.0f} scenarios/s; "
          f"ratio sweep/simulate_many = {s / p:.3f}")


if __name__ == "__main__":
    main()
