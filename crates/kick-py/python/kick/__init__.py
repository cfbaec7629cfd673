"""kick: the millisecond physics of a soccer kick, from Python.

The same library functions as the ``kick`` command line, numpy in and numpy
out. Keywords are the declared scenario parameters (``kick.PARAMETERS``, the
list ``kick_core::parameters`` and ``kick_flight::FLIGHT_PARAMETERS`` of the
Rust workspace): the name of a parameter is its keyword, its default the
CLI's, SI units throughout (angles in degrees).

Functions
---------
simulate, simulate3d      one contact; the dict ``kick simulate[3d] --format json`` prints
simulate_many, simulate3d_many
                          many contacts from arrays (numpy broadcasting), solved in
                          parallel in Rust; a status per row instead of exceptions;
                          ``progress=True`` (every ``*_many``) draws a bar on stderr
history                   uniform time history of one 1D contact (dict of 1-D arrays)
history3d                 uniform time history of one 3D kick, accurate path (dict of 1-D arrays)
fit                       identify parameters from a measured history (``kick fit data``)
flight                    the ball's flight after the kick (kick-flight)
flight_many               many flights from arrays (numpy broadcasting), in parallel in Rust
bounce                    the ball alone on a rigid plate (``kick bounce``; kick-bounce)
bounce_many               many bounces from arrays (numpy broadcasting), in parallel in Rust
aim                       the launch (or 3D kick) that clears the wall and hits a target in the goal
to_xarray                 a ``*_many`` result as an xarray Dataset: dimensions from the
                          broadcast axes, units in attributes
kick.dask.simulate_many   ``simulate_many`` spread over a dask ``distributed`` cluster
                          (also simulate3d_many, flight_many, bounce_many; ``kick.dask.to_zarr``
                          writes each chunk on its worker)

Errors raise by what became of the call (``kick.STATUS``), with the command
line's message: bad input (status 3, refused) ``ValueError``; a numerical
limit (status 1: a step budget, a step too large, an integration failure)
``kick.NumericalError``, a ``RuntimeError``, never a physical answer; a ball
proven trapped (status 2) ``RuntimeError``. A result outside the region
where its contact law holds (status 4: the shell ball compressed past R/2,
another law past R) is returned with ``status`` ``"outside_validity"`` and
why (``outside_validity``), and warns ``kick.OutsideValidityWarning``; in
the ``_many`` functions its row keeps its numbers, status 4 and the
message. A keyword
takes real numbers (Python or numpy ints and floats; bools for switches):
a complex, datetime, string, bool (among numbers), Decimal, Fraction or
other object value is a ``TypeError`` and a masked element a
``ValueError``, each naming the keyword: one guard for every function. Outputs too large to
allocate are a ``MemoryError`` before any row is solved. Ctrl-C stops a
long call within moments (``KeyboardInterrupt``).
"""

from __future__ import annotations

import inspect as _inspect

from . import _kick
from ._kick import (
    BOUNCE_COLUMNS,
    CHANNELS,
    HISTORY_COLUMNS,
    HISTORY_COLUMNS_3D,
    LAWS,
    OBSERVABLES,
    SOLVERS,
    SOLVERS_3D,
    STATUS,
    STUDIES,
    NumericalError,
    OutsideValidityWarning,
    __version__,
)
from ._labelled import ManyResult, to_xarray

__all__ = [
    "simulate",
    "simulate_many",
    "simulate3d",
    "simulate3d_many",
    "history",
    "history3d",
    "fit",
    "flight",
    "flight_many",
    "bounce",
    "bounce_many",
    "aim",
    "NumericalError",
    "OutsideValidityWarning",
    "PARAMETERS",
    "BOUNCE_PARAMETERS",
    "STATUS",
    "STUDIES",
    "OBSERVABLES",
    "HISTORY_COLUMNS",
    "HISTORY_COLUMNS_3D",
    "CHANNELS",
    "SOLVERS",
    "SOLVERS_3D",
    "LAWS",
    "keywords",
    "to_xarray",
]

def _labelled(function: str, values: dict, arrays: dict) -> ManyResult:
    """A ``*_many`` answer that remembers its call, for ``to_xarray``."""
    names = {p["name"] for p in keywords(function)}
    inputs = {k: v for k, v in arrays.items() if k in names}
    # How the call ran, not what it computed: no attribute of the result.
    options = {k: v for k, v in arrays.items() if k not in names and k != "progress"}
    return ManyResult(values, function, inputs, options)


#: Every declared parameter (1D, 3D, flight): dicts with name, symbol, unit,
#: level, shape, default, default_text, doc, requirement.
PARAMETERS = tuple(_kick.parameters())
#: The parameters of ``bounce`` (kick-bounce's declared list, ``kick bounce``'s flags).
BOUNCE_PARAMETERS = tuple(_kick.bounce_parameters())


def keywords(function: str) -> list[dict]:
    """The declared parameters a function takes as keywords, in declaration order."""
    names = _kick.keywords(function)
    if function in ("bounce", "bounce_many"):
        return [p for n in names for p in BOUNCE_PARAMETERS if p["name"] == n]
    flight = function in ("flight", "flight_many")
    return [p for n in names for p in PARAMETERS if p["name"] == n and (p["level"] == "flight") == flight]


def _unit(p: dict) -> str:
    return "" if p["unit"] in ("", "1") else f" [{p['unit']}]"


def _keyword_docs(function: str, exclude=()) -> str:
    lines = []
    for p in keywords(function):
        if p["name"] in exclude:
            continue
        lines.append(f"{p['name']} : {p['shape'].replace('_', ' ')}, {p['symbol']}{_unit(p)}, default {p['default_text']}")
        lines.append(f"    {p['doc']}; must be {p['requirement']}.")
    return "\n".join(lines)


def _outputs_docs(columns) -> str:
    return "\n".join(f"{name} : {'1' if unit in ('', '1') else unit}" for name, unit in columns)


def _declare(func, function: str, head: list, tail: list, intro: str, outputs: str = "", exclude=()):
    """Give ``func`` the signature and docstring generated from the declared
    list (less the keywords in ``exclude``, which ``func`` refuses)."""
    KW = _inspect.Parameter.KEYWORD_ONLY
    declared = []
    for p in keywords(function):
        if p["name"] in exclude:
            continue
        default = p["default"]
        if isinstance(default, list):
            default = tuple(default)
        declared.append(_inspect.Parameter(p["name"], KW, default=default))
    func.__signature__ = _inspect.Signature(head + declared + tail)
    doc = intro.strip() + "\n\nParameters (keyword only; the declared list)\n" + "-" * 44 + "\n" + _keyword_docs(function, exclude)
    if outputs:
        doc += "\n\n" + outputs.strip()
    func.__doc__ = doc
    return func


_KW = _inspect.Parameter.KEYWORD_ONLY
_solver = _inspect.Parameter("solver", _KW, default="auto")
_law = _inspect.Parameter("law", _KW, default="power-law")
_dt = _inspect.Parameter("dt", _KW, default=None)
_threads = _inspect.Parameter("threads", _KW, default=None)
_progress = _inspect.Parameter("progress", _KW, default=False)

_STATUS_DOC = ", ".join(f"{code} {name}" for code, name in sorted(STATUS.items()))
_SOLVER_DOC = f"""
solver : str, default "auto"
    One of {", ".join(SOLVERS)} (as ``kick simulate --solver``).
law : str, default "power-law"
    Contact law: {", ".join(LAWS)}. The paper's takes ``damping`` (and refuses
    ``restitution``); shell takes its ball's own parameters (inflation_pressure,
    gas_exponent, shell_stiffness, shell_damping) and refuses both; the others need
    ``restitution`` (and refuse ``damping``). Each holds up to a compression
    (shell R/2, the others R; ``kick reference parameters``): beyond, status 4.
dt : float, optional
    Step of the fixed-step solvers (seed-rk4, rk4-events), s; default as the CLI's (5e-6 s);
    a ValueError with any other solver, which chooses its own steps.
"""
_SOLVER3D_DOC = f"""
solver : str, default "auto"
    One of {", ".join(SOLVERS_3D)} (as ``kick simulate3d --solver``).
law : str, default "power-law"
    Normal contact law: {", ".join(LAWS)}.
dt : float, optional
    Step of the rapier scene path (solver "rapier"), s; default as the CLI's (1e-6 s);
    a ValueError with any other solver.
"""
_MANY_DOC = f"""
threads : int, optional
    Worker threads (an own pool of that many, 1 to 4 per core; an int or numpy
    integer, not a float or bool); default: rayon's pool, one per core.
progress : bool, default False
    Draw a bar on ``sys.stderr`` counting the rows done (its label the
    function, then done/total rows, elapsed time and an estimate of the time
    left); redrawn 10 times a second on a terminal, once a second off one (a
    log file). The rows are the same with or without it, and Ctrl-C still
    stops the call within moments. A bool only (a 1 or a string is a
    ``TypeError`` naming ``progress``). ``kick.dask`` draws no bar on its
    workers: use ``distributed``'s own progress there.

Every parameter is a scalar or an array; they broadcast by numpy's rules to
the rows' shape S (a vector parameter has a trailing axis of 3). The rows are
solved in parallel in Rust with the GIL released.

Returns a dict of arrays of shape S (vectors S + (3,)): every outcome below,
``evaluations`` (uint64), ``status`` (uint8: {_STATUS_DOC}; the codes of
``kick_core::Status``), and for the rows whose status is not 0
``failure_index`` (int64, flat C-order row indices) and ``failure_message``
(list of str, the library's message): rows that gave no outcome (their
outcomes NaN), and rows outside their law's validity (status 4, their
outcomes kept). No exception for a failed row.
"""


def simulate(**params):
    return _kick.simulate(**params)


_declare(
    simulate,
    "simulate",
    [],
    [_solver, _law, _dt],
    "Solve one 1D contact (the paper's compliant model), as ``kick simulate``.\n\n"
    "Returns the dict ``kick simulate --format json`` prints: every observable\n"
    "(SI units, below), energy_residual (J), solver, method (the path that ran),\n"
    "stop, evaluations, scenario (the eight parameters used) and law.\n" + _SOLVER_DOC,
    "Observables\n-----------\n" + _outputs_docs(OBSERVABLES),
)


def simulate_many(**arrays):
    return _labelled("simulate_many", _kick.simulate_many(**arrays), arrays)


_declare(
    simulate_many,
    "simulate_many",
    [],
    [_solver, _law, _dt, _threads, _progress],
    "Solve many 1D contacts, as ``kick sweep`` does, from arrays.\n" + _SOLVER_DOC + _MANY_DOC,
    "Outcomes\n--------\n" + _outputs_docs(list(OBSERVABLES) + [("energy_residual", "J")]),
)


def simulate3d(**params):
    return _kick.simulate3d(**params)


_flight = _inspect.Parameter("flight", _KW, default=False)
_distance = _inspect.Parameter("distance", _KW, default=None)
#: The flight's keywords a 3D kick leaves to its flight (``flight=True``).
_FLIGHT_SET_BY_KICK = ("speed", "launch_angle", "azimuth", "launch_velocity", "spin", "ball_mass", "ball_radius", "gravity", "distance")
_flight_rest = [_inspect.Parameter(p["name"], _KW, default=None) for p in keywords("flight") if p["name"] not in _FLIGHT_SET_BY_KICK]
_FLIGHT_AFTER_DOC = f"""
flight : bool, default False
    Then fly the ball from the ground (its centre at height R) with the kick's
    launch velocity and spin, as ``kick simulate3d --flight``; the flight's
    keywords ({", ".join(p.name for p in _flight_rest)}) are then taken too.
distance : float or list of float, optional
    With ``flight``: the plane x = distance (m) whose crossing is reported, or a
    list of planes, each located in the one solve.

Offset and contact depth: the ball's centre lies ``offset`` sideways of the
foot's line of motion and ``contact_depth`` above it (perpendicular to the
line; axes: x the foot's horizontal direction, y the kicker's left, z up).
offset > 0 sends the ball toward -y spinning spin_z < 0 and curving further to
-y; contact_depth > 0 lifts it with backspin spin_y < 0.
"""

_declare(
    simulate3d,
    "simulate3d",
    [],
    [_solver, _law, _dt, _flight, _distance] + _flight_rest,
    "Solve one off-center 3D kick (spin, friction), as ``kick simulate3d``.\n\n"
    "Returns the dict ``kick simulate3d --format json`` prints: launch_velocity\n"
    "and spin (arrays of 3: m/s, rad/s; x along the foot's path, z up), speed,\n"
    "spin_rpm, launch_angle and launch_azimuth (deg), contact_time (s), peak\n"
    "forces (N), max_compression (m), slip_time (s), impulses (N s), the energy\n"
    "partition (J), energy_residual, evaluations, solver, law, law_parameters;\n"
    "with ``flight``, ``flight`` (the dict ``flight`` returns, with ``crossings``,\n"
    "one per plane of a list of distances, None where the ball lands first).\n" + _SOLVER3D_DOC + _FLIGHT_AFTER_DOC,
)


def simulate3d_many(**arrays):
    return _labelled("simulate3d_many", _kick.simulate3d_many(**arrays), arrays)


_declare(
    simulate3d_many,
    "simulate3d_many",
    [],
    [_solver, _law, _dt, _threads, _progress, _flight, _distance] + _flight_rest,
    "Solve many off-center 3D kicks from arrays.\n" + _SOLVER3D_DOC + _MANY_DOC + _FLIGHT_AFTER_DOC
    + "\nThe outcomes are ``simulate3d``'s numbers, ``energy`` flattened to\n"
    "``energy_<part>``; vectors (launch_velocity, spin, ...) have shape S + (3,).\n"
    "With ``flight`` (its keywords broadcast too): flight_time, landing_point\n"
    "(S + (2,)), apex_height, apex_time, landing_velocity, landing_spin, and with\n"
    "``distance`` crossed, crossing_time, crossing_height, crossing_lateral_offset\n"
    "and crossing_velocity (S + (3,)); a list of P distances adds a trailing axis\n"
    "of P (S + (P,), crossing_velocity S + (P, 3)). ``flight_status`` is the\n"
    "flight's code (0 flown; 3 refused: a flight input refused, or the ball does\n"
    "not leave the ground; 1 a numerical failure; its flight outcomes then NaN,\n"
    "the kick's kept): such a row keeps the kick's ``status`` and is listed in\n"
    "``failure_index`` with why in ``failure_message``.\n",
)


def history(**params):
    return _kick.history(**params)


_declare(
    history,
    "history",
    [],
    [_solver, _law, _dt, _inspect.Parameter("samples", _KW, default=None), _inspect.Parameter("interval", _KW, default=None)],
    "Time history of one 1D contact, uniform samples, as ``kick simulate --history``.\n\n"
    "Give one of ``samples`` (how many, an int from 2 to 1e6: first touch to separation) or\n"
    "``interval`` (s apart from first touch). The last row is the separation\n"
    "state (phase 0). Returns a dict of 1-D float64 arrays (below).\n" + _SOLVER_DOC,
    "Columns\n-------\n" + _outputs_docs(HISTORY_COLUMNS)
    + "\n(phase: +1 compressing, -1 restoring, 0 the separation row)",
)


def history3d(**params):
    return _kick.history3d(**params)


_declare(
    history3d,
    "history3d",
    [],
    [_solver, _law, _inspect.Parameter("samples", _KW, default=None), _inspect.Parameter("interval", _KW, default=None)],
    "Time history of one off-center 3D kick, uniform samples, as ``kick simulate3d --history``.\n\n"
    "The accurate path's samples (solver ``auto`` or ``accurate``), world frame\n"
    "(x along the foot's path, z up). Give one of ``samples`` (how many, an int from 2 to 1e6:\n"
    "first touch to separation) or ``interval`` (s apart from first touch). The\n"
    "last row is the separation state (contact_state 0), the outcome's exit\n"
    "velocities. Returns a dict of 1-D float64 arrays (below); vectors as\n"
    "``_x``, ``_y``, ``_z`` columns, as in the CLI's history file.\n" + _SOLVER3D_DOC,
    "Columns\n-------\n" + _outputs_docs(HISTORY_COLUMNS_3D)
    + "\n(contact_state: 1 grip, 2 slip (also friction 0), 0 the separation row)",
)


def fit(time, force=None, **kwargs):
    return _kick.fit(time, force, **kwargs)


_channels_doc = "\n".join(f"{name} : array [{unit}]" for name, unit in CHANNELS)
_declare(
    fit,
    "simulate",
    [
        _inspect.Parameter("time", _inspect.Parameter.POSITIONAL_OR_KEYWORD),
        _inspect.Parameter("force", _inspect.Parameter.POSITIONAL_OR_KEYWORD, default=None),
        _inspect.Parameter("sigma", _KW),
        _inspect.Parameter("free", _KW),
        _law,
        _inspect.Parameter("time_offset", _KW, default=None),
    ]
    + [_inspect.Parameter(name, _KW, default=None) for name, _ in CHANNELS if name != "force"],
    [],
    f"""Identify parameters from a measured history, as ``kick fit data``.

Levenberg-Marquardt on the accurate 1D solver (crate kick-identify): the
parameters named in ``free`` are fitted, the other keywords are known
values (and starting guesses of the free ones).

time : array [s]
    Sample times (increasing), from the data's clock; the model is read at
    t - time_offset.
{_channels_doc}
    The channels measured at ``time`` (at least one).
sigma : float or dict
    Standard uncertainty of every channel, or {{channel: sigma}}.
free : list of str
    Names to fit: any 1D parameter, ``restitution`` (laws other than the
    paper's) or ``time_offset``.
time_offset : float, optional
    t0, s: time of first touch in the data (start value when fitted; default 0).

Returns a dict: names, units, estimate, standard_error, start (arrays in
``names`` order), covariance and correlation (n x n arrays; NaN when the
data do not determine them), singular_values, residuals (weighted),
predicted, chi_square, degrees_of_freedom, residual_variance, stop (a word:
converged, lost_patience, ...), termination (in words), converged,
evaluations, law.
""",
)


def flight(**params):
    return _kick.flight(**params)


_declare(
    flight,
    "flight",
    [],
    [_inspect.Parameter("samples", _KW, default=None)],
    "The ball's flight after the kick (crate kick-flight): drag crisis in Re,\n"
    "Magnus lift, spin decay; landing, apex and the crossing of x = distance.\n\n"
    "``distance`` is one plane, or a list of planes (each located in the one\n"
    "solve: ``crossings``). ``samples`` (an int from 2 to 1e6) adds the trajectory.\n\n"
    "Returns a dict: flight_time (s), landing_point (array of 2: x, y in m),\n"
    "apex_height (m), apex_time (s), landing_velocity (array of 3, m/s),\n"
    "landing_spin (array of 3, rad/s), crossing (None, or a dict with\n"
    "distance, time, height, lateral_offset, velocity when one ``distance`` is\n"
    "given and reached), crossings (with a list of distances: one such dict or\n"
    "None per plane), launch (dict: reynolds, spin_parameter,\n"
    "drag_coefficient, lift_coefficient at launch), steps, evaluations; with\n"
    "``samples`` N, trajectory (dict: time [N] s, position [N, 3] m, velocity\n"
    "[N, 3] m/s, spin [N, 3] rad/s at uniform times from launch to landing).",
)


def aim(target, **params):
    return _kick.aim(target, **params)


_declare(
    aim,
    "flight",
    [
        _inspect.Parameter("target", _inspect.Parameter.POSITIONAL_OR_KEYWORD),
        _inspect.Parameter("wall", _KW, default=None),
        _inspect.Parameter("from_", _KW, default="launch"),
        _inspect.Parameter("free", _KW, default=None),
        _inspect.Parameter("law", _KW, default="power-law"),
        _inspect.Parameter("objective", _KW, default=None),
        _inspect.Parameter("bounds", _KW, default=None),
    ],
    [],
    """Aim a free kick, as ``kick aim``: the launch (or the 3D kick) that clears
the wall and crosses the goal plane at ``target`` (crate kick-flight's
``aim``: Levenberg-Marquardt over the free parameters within their ranges).

Axes as ``flight``: the ball starts at the origin, x toward the goal, y
lateral, z up; the goal (7.32 m x 2.44 m) and the wall centred on y = 0.

target : (X, Y, Z) [m]
    The goal plane x = X and where the ball's centre should cross it
    (inside the posts, under the bar).
wall : (DIST, HEIGHT, HALF_WIDTH) [m], default (9.15, 1.8, 1)
    The wall's plane, the height of its top and its half-width.
from_ : str, default "launch"
    "launch" (free: speed, launch_angle, azimuth, spin_x, spin_y, spin_z)
    or "kick" (free: any number parameter of the kick, e.g. foot_speed,
    offset, contact_depth, approach_angle, inflation_pressure, and heading;
    Table 1's foot and kick-3d's defaults otherwise).
free : list of str, optional
    The free parameters; default speed, launch_angle, azimuth (launch) or
    foot_speed, offset, contact_depth, heading (kick), less any given: a
    keyword holds its parameter at that value, unless ``free`` names it (then
    it is the start).
law : str, default "power-law"
    With from_="kick": the kick's normal contact law (``kick aim --law``):
    {laws} ("shell": the pressurised ball, its keywords inflation_pressure,
    ... then apply).
objective : str, optional
    Which member of the family of solutions (more free parameters than
    two): "min-foot-speed" (from_="kick"), "min-speed" (launch speed),
    "min-time" (to the goal line), "max-clearance" (of the wall): the best of
    the members solved on the family's grid, not a proven optimum; default
    the member the solve reaches from the starts.
bounds : dict, optional
    {name: (low, high)} of free parameters, instead of the aim's own.

Returns a dict: from, scene, parameters (list of dicts: name, unit, value,
low, high, sensitivity = d(y, z at the goal)/d parameter), launch_velocity,
spin, crossing, miss (m), wall_clearance (m), wall_crossing, wall_pass
("over" its top or "beside" it), family (None with two free parameters, else
dimension, pivots, members found, extent of each free parameter, goal_time,
clearance and launch_speed ranges, objective), outcome (the flight's, as
``flight`` returns), evaluations, starts, kick (with from_="kick": every
parameter of the kick solved, heading, contact_time, spin_rev_per_s; else None).
No solution within the ranges raises ValueError saying so.

With ``from_="kick"`` the keywords of ``simulate3d`` that the flight does
not declare too (foot_mass, foot_speed, friction, ...; not ball_mass,
ball_radius, gravity) set the kick (Table 1's and kick-3d's defaults
otherwise).
""".replace("{laws}", ", ".join(LAWS)),
    # The target's X is the goal plane and the launch is what is solved for:
    # aim refuses both (they were in its signature all the same).
    exclude=("distance", "launch_velocity"),
)
_flight_names = {p["name"] for p in keywords("flight")}
aim.__signature__ = aim.__signature__.replace(
    parameters=list(aim.__signature__.parameters.values())
    + [_inspect.Parameter(p["name"], _KW, default=None) for p in keywords("simulate3d") if p["name"] not in _flight_names]
)


def flight_many(**arrays):
    return _labelled("flight_many", _kick.flight_many(**arrays), arrays)


_FLIGHT_MANY_OUTPUTS = [
    ("flight_time", "s"),
    ("landing_point", "m (x, y: trailing axis of 2)"),
    ("apex_height", "m"),
    ("apex_time", "s"),
    ("landing_velocity", "m/s (trailing axis of 3)"),
    ("landing_spin", "rad/s (trailing axis of 3)"),
    ("crossed", "1 when the ball reaches x = distance before landing, else 0"),
    ("crossing_time", "s (NaN when not crossed)"),
    ("crossing_height", "m"),
    ("crossing_lateral_offset", "m"),
    ("crossing_velocity", "m/s (trailing axis of 3)"),
    ("launch_reynolds", "1"),
    ("launch_spin_parameter", "1"),
    ("launch_drag_coefficient", "1"),
    ("launch_lift_coefficient", "1"),
    ("steps", "1"),
]

_declare(
    flight_many,
    "flight_many",
    [],
    [_threads, _progress],
    "Solve many flights, as ``flight`` does, from arrays "
    "(``kick_flight::solve`` per row).\n" + _MANY_DOC.replace("1 numerical failure, 2 trapped", "1 numerical failure")
    .replace("0 separated", "0 landed"),
    "Outcomes\n--------\n" + _outputs_docs(_FLIGHT_MANY_OUTPUTS),
)

def bounce(**params):
    return _kick.bounce(**params)


_bounce_law = _inspect.Parameter("law", _KW, default="shell")
_BOUNCE_LAW_DOC = """
law : str, default "shell"
    The ball's law, as ``kick bounce --law``: shell (the pressurised ball) or a
    law of the kick's family (power-law, hunt-crossley, ...).
"""

_declare(
    bounce,
    "bounce",
    [_bounce_law],
    [],
    "The ball alone on a rigid, massive plate (``kick bounce``; ``kick_bounce::run``).\n\n"
    "Fired square or oblique, with or without spin: give ``speed`` (and ``angle``,\n"
    "``spin``) or ``drop_height``.\n" + _BOUNCE_LAW_DOC + "\n"
    "Returns the dict ``kick bounce --format json`` prints: restitution (normal),\n"
    "contact_time (s), peak_force (N), peak_force_time (s), max_compression (m),\n"
    "max_compression_time (s), normal_impulse (N s), impact_velocity, exit_velocity\n"
    "(lists of 3, m/s), exit_spin (list of 3, rad/s), tangential (no_slip, grips\n"
    "or slides), rebound_height (m, with drop_height), evaluations.",
)


def bounce_many(**arrays):
    return _labelled("bounce_many", _kick.bounce_many(**arrays), arrays)


_declare(
    bounce_many,
    "bounce_many",
    [_bounce_law],
    [_threads, _progress],
    "Solve many bounces, as ``bounce`` does, from arrays.\n" + _BOUNCE_LAW_DOC + _MANY_DOC.replace(", 2 trapped", ""),
    "Outcomes\n--------\n" + _outputs_docs(BOUNCE_COLUMNS),
)

from . import dask  # noqa: E402  (kick.dask.simulate_many; needs `distributed` only when called)
