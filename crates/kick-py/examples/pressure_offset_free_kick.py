"""How inflation pressure and impact offset change ball speed, spin and the
bend of a free kick, and which setting is best from 25 m over a wall.

    python crates/kick-py/examples/pressure_offset_free_kick.py

A worked study with kick's Python API (the Python tests run it:
crates/kick-py/tests/test_examples.py):

1. One call of ``kick.simulate3d_many`` solves every kick of a grid of
   inflation pressure x impact offset on the pressurised-shell ball
   (``law="shell"``), flies each ball from the ground (``flight=True``) and
   reports where it crosses the wall's plane (9.15 m) and the goal line
   (25 m): ``distance=[9.15, 25.0]``. ``kick.to_xarray`` labels the result,
   its dimensions named after the inputs (inflation_pressure, offset).
2. ``kick.aim`` with ``objective="min-foot-speed"`` finds, for each pressure,
   the kick that passes over the wall and reaches the top corner with the
   least foot speed: offset, contact depth and heading free.

Axes (as ``help(kick.simulate3d)``): x the foot's horizontal line of motion,
y the kicker's left, z up. ``offset`` > 0 puts the ball's centre to the
foot's right of its line of motion: the ball leaves toward -y spinning
spin_z < 0 and curves further to -y. ``contact_depth`` > 0 puts the ball's
centre above the foot's line (the foot strikes below it): lift and backspin.

Every number below is the model's at its defaults (Table 1's foot at
22 m/s, kick-3d's instep, friction 0.5, the shell ball's identified loss):
a prediction to compare with measurements, not a measurement.
"""

from __future__ import annotations

import numpy as np

import kick

#: Inflation pressures, gauge, Pa (Law 2 allows 0.6-1.1 atm; FIFA tests at 0.8 bar).
PRESSURES = np.array([0.6e5, 0.8e5, 1.1e5])
#: Lateral offsets of the ball's centre from the foot's line of motion, m.
OFFSETS = np.array([0.0, 0.02, 0.04, 0.06])
#: The ball's centre 3 cm above the foot's line: the free kicks of paper/flight.md.
CONTACT_DEPTH = 0.03
WALL = (9.15, 1.8, 1.0)  # distance, height of its top, half-width, m
GOAL = 25.0  # m from the ball to the goal line
TARGET = (GOAL, -3.0, 2.1)  # inside the near top corner (posts at y = +-3.66 m, bar at 2.44 m)


def grid():
    """Every kick of the grid flown: an xarray Dataset over (inflation_pressure, offset)."""
    result = kick.simulate3d_many(
        law="shell",
        inflation_pressure=PRESSURES[:, None],
        offset=OFFSETS,
        contact_depth=CONTACT_DEPTH,
        flight=True,
        distance=[WALL[0], GOAL],
    )
    ds = kick.to_xarray(result)
    # Bend: how far the ball has curved at the goal line from the straight
    # line of its launch direction (negative: toward -y).
    straight = GOAL * np.tan(np.radians(ds["launch_azimuth"]))
    ds["bend"] = ds["crossing_lateral_offset"].sel(distance=GOAL) - straight
    ds["bend"].attrs["units"] = "m"
    ds["spin_rev_per_s"] = np.hypot(ds["spin"].sel(xyz="z"), ds["spin"].sel(xyz="y")) / (2 * np.pi)
    ds["spin_rev_per_s"].attrs["units"] = "rev/s"
    return ds


def best_kicks():
    """For each pressure, the least foot speed that puts the ball over the wall into the corner."""
    return {
        p: kick.aim(TARGET, wall=WALL, from_="kick", law="shell", inflation_pressure=float(p), objective="min-foot-speed")
        for p in PRESSURES
    }


def bend_text(bend: float) -> str:
    """The bend at the goal line, or "short" for a ball that lands before it."""
    return f"{bend:8.2f}" if np.isfinite(bend) else f"{'short':>8}"


def foot_speed(aimed: dict) -> float:
    """The foot speed of an aimed kick (``kick.aim(..., from_="kick")``)."""
    return dict(aimed["kick"]["parameters"])["foot_speed"]


def main():
    ds = grid()
    print(f"The kick at 22 m/s, contact depth {CONTACT_DEPTH * 100:.0f} cm (shell ball), flown to {GOAL:.0f} m:")
    print(f"{'P (bar)':>8} {'offset (cm)':>11} {'speed (m/s)':>11} {'spin (rev/s)':>12} {'sidespin z':>10}"
          f" {'contact (ms)':>12} {'z at wall (m)':>13} {'bend (m)':>8}")
    for p in ds["inflation_pressure"].values:
        for e in ds["offset"].values:
            row = ds.sel(inflation_pressure=p, offset=e)
            wall_z = float(row["crossing_height"].sel(distance=WALL[0]))
            print(
                f"{p / 1e5:8.1f} {e * 100:11.0f} {float(row['speed']):11.2f} {float(row['spin_rev_per_s']):12.2f}"
                f" {float(row['spin'].sel(xyz='z')) / (2 * np.pi):10.2f} {float(row['contact_time']) * 1e3:12.2f}"
                f" {wall_z:13.2f} {bend_text(float(row['bend']))}"
            )
    best = best_kicks()
    print()
    print(f"Over a wall {WALL[1]} m high at {WALL[0]} m into ({TARGET[1]}, {TARGET[2]}) m at {GOAL:.0f} m,"
          " the least foot speed:")
    print(f"{'P (bar)':>8} {'foot (m/s)':>10} {'ball (m/s)':>10} {'offset (cm)':>11} {'depth (cm)':>10}"
          f" {'heading':>8} {'spin (rev/s)':>12} {'clearance (m)':>13} {'wall':>6}")
    for p, a in best.items():
        k = dict(a["kick"]["parameters"])
        print(
            f"{p / 1e5:8.1f} {k['foot_speed']:10.2f} {np.linalg.norm(a['launch_velocity']):10.2f}"
            f" {k['offset'] * 100:11.1f} {k['contact_depth'] * 100:10.1f} {a['kick']['heading']:8.1f}"
            f" {a['kick']['spin_rev_per_s']:12.2f} {a['wall_clearance']:13.2f} {a['wall_pass']:>6}"
        )
    easiest = min(best, key=lambda p: foot_speed(best[p]))
    print(f"\nBest from {GOAL:.0f} m: {easiest / 1e5:.1f} bar, {foot_speed(best[easiest]):.2f} m/s of foot speed;"
          " a firmer ball returns more of the foot's speed (compare the speeds above).")
    return ds, best


if __name__ == "__main__":
    ds, best = main()
