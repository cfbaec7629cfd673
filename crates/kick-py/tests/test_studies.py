"""``kick.STUDIES``, the one registry of studies (kick_study::studies), names
exactly the functions that exist: each Python function that runs a study
belongs to one, and ``kick.dask`` runs what the registry says it runs."""

import inspect

import kick
import kick.dask

# Helpers that run no study: they describe keywords or relabel results.
HELPERS = {"keywords", "to_xarray"}


def test_every_study_function_exists_and_belongs_to_one_study():
    named = [f for study in kick.STUDIES for f in study["python"]]
    assert len(named) == len(set(named)), named
    functions = {n for n in kick.__all__ if inspect.isroutine(getattr(kick, n)) and n not in HELPERS}
    assert set(named) == functions


def test_dask_runs_what_the_registry_declares():
    declared = {f for study in kick.STUDIES for f in study["dask"]}
    assert declared == {"simulate_many", "simulate3d_many", "flight_many", "bounce_many"}
    assert declared == {n for n in kick.dask.__all__ if n != "to_zarr"}
    for name in declared:
        assert callable(getattr(kick.dask, name))


def test_reproduce_steps_come_first_in_run_order():
    steps = [s["name"] for s in kick.STUDIES if s["reproduced"]]
    assert steps[:3] == ["experiments", "figures", "checks"] and steps[-1] == "report"
    assert all(s["reproduced"] for s in kick.STUDIES[: len(steps)])
