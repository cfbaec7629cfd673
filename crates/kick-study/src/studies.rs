//! Every study kick runs, declared once: its name, what it computes, the
//! command lines and Python and Dask functions that run it, the result-file
//! layouts it writes, and whether `kick reproduce` runs it (and in which
//! order). `kick reproduce --list/--only` takes its steps from here,
//! `kick reference files` its "written by" column (kick-store), and Python
//! its `kick.STUDIES`; tests hold each list to what exists (every layout,
//! subcommand, Python and Dask function named here, and no other).

use crate::error::StudyError;

/// One study.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub struct Study {
    /// Its name, and `kick reproduce --only`'s for a step.
    pub name: &'static str,
    /// What it computes, in a line.
    pub computes: &'static str,
    /// The command lines that run it (`kick …`).
    pub commands: &'static [&'static str],
    /// Python's functions that run it (`kick.…`).
    pub python: &'static [&'static str],
    /// `kick.dask`'s functions that run it on a cluster.
    pub dask: &'static [&'static str],
    /// The result-file layouts it writes (`kick_store::layouts`).
    pub layouts: &'static [&'static str],
    /// A step of `kick reproduce` (the steps run in this list's order).
    pub reproduced: bool,
}

const fn step(name: &'static str, computes: &'static str, commands: &'static [&'static str], layouts: &'static [&'static str]) -> Study {
    Study { name, computes, commands, python: &[], dask: &[], layouts, reproduced: true }
}

/// Every study: first `kick reproduce`'s steps in the order they run, then
/// the studies a user runs on their own.
pub const STUDIES: [Study; 28] = [
    step(
        "experiments",
        "every 1D experiment file (experiments/*.toml): grids, named rows and random samples, each kick flown where the file asks",
        &["kick run FILE --out DIR"],
        &["sweep"],
    ),
    step("figures", "the 1D figures, drawn from the experiments' result files", &["kick reproduce --only figures"], &[]),
    step("checks", "the cross-model checks: each model level against the others' limits", &["kick check"], &[]),
    step("3d", "every 3D experiment file (experiments/3d/*.toml) and its figures", &["kick run FILE --out DIR"], &["sweep"]),
    step(
        "force-history",
        "the contact force's time history of the off-center kick, against the 1D force",
        &["kick simulate3d --history FILE.h5"],
        &["history"],
    ),
    step(
        "patch",
        "spin against offset and friction on the shell ball's patch, knife-edge face and convex instep",
        &["kick reproduce --only patch"],
        &["patch-spin"],
    ),
    step("leg", "the leg's effective mass over its pose, and the exit speed it gives", &["kick leg --sweep-out DIR"], &["sweep"]),
    step(
        "ball",
        "the ball alone on a plate (experiments/ball/*.toml): restitution, contact time and compression against speed and pressure",
        &["kick run FILE --out DIR"],
        &["sweep"],
    ),
    step("laws", "the contact laws on Table 2's scenarios", &["kick laws --out DIR"], &["sweep"]),
    step(
        "profile",
        "profile likelihoods and identifiability of the paper's law's parameters",
        &["kick reproduce --only profile"],
        &["kick-identifiability"],
    ),
    step(
        "synthesize",
        "synthetic measured data from known parameters (the paper's law, and Hunt–Crossley)",
        &["kick fit synthesize --out DIR"],
        &[],
    ),
    step("fit", "the synthetic data fitted back, with uncertainties", &["kick fit data SPEC --out FILE"], &["kick-fit"]),
    step(
        "table2-fit",
        "each Table 2 row's parameters identified from its printed numbers",
        &["kick fit table2 --out FILE"],
        &["kick-fit-table2"],
    ),
    step(
        "bench",
        "work–precision of every 1D solver, cost ratios, sweep throughput and the off-center kick's cost",
        &["kick bench --out DIR"],
        &["sweep"],
    ),
    step("pages", "the 1D pages from the result files", &["kick reproduce --only pages"], &[]),
    step(
        "validation",
        "the model beside published measurements, one count per distinct measurement",
        &["kick reproduce --only validation"],
        &[],
    ),
    step("3d-pages", "the 3D, flight and free-kick pages from the result files", &["kick reproduce --only 3d-pages"], &[]),
    step(
        "model",
        "the model page: equations with the declared parameters' symbols, units and defaults",
        &["kick reproduce --only model"],
        &[],
    ),
    step("report", "the report's front page", &["kick reproduce --only report"], &[]),
    Study {
        name: "simulate",
        computes: "one 1D contact, or many broadcast over arrays of its parameters",
        commands: &["kick simulate", "kick simulate --history FILE.h5"],
        python: &["simulate", "simulate_many", "history"],
        dask: &["simulate_many"],
        layouts: &["history"],
        reproduced: false,
    },
    Study {
        name: "simulate3d",
        computes: "one off-center 3D kick (and its flight), or many broadcast over arrays of its parameters",
        commands: &["kick simulate3d", "kick simulate3d --flight --distance D", "kick simulate3d --history FILE.h5"],
        python: &["simulate3d", "simulate3d_many", "history3d"],
        dask: &["simulate3d_many"],
        layouts: &["history"],
        reproduced: false,
    },
    Study {
        name: "flight",
        computes: "the ball's flight from its launch: landing, apex, plane crossings, trajectory",
        commands: &["kick flight", "kick flight --history FILE.h5"],
        python: &["flight", "flight_many"],
        dask: &["flight_many"],
        layouts: &["history"],
        reproduced: false,
    },
    Study {
        name: "bounce",
        computes: "the ball fired at a rigid plate: restitution, contact time, compression",
        commands: &["kick bounce"],
        python: &["bounce", "bounce_many"],
        dask: &["bounce_many"],
        layouts: &[],
        reproduced: false,
    },
    Study {
        name: "aim",
        computes: "the launch or 3D kick that clears the wall and crosses the goal plane at a target, picked by an objective",
        commands: &["kick aim"],
        python: &["aim"],
        dask: &[],
        layouts: &[],
        reproduced: false,
    },
    Study {
        name: "sweep",
        computes: "random 1D scenarios over the declared parameters' sampled ranges",
        commands: &["kick sweep --out FILE.h5", "kick sweep --shard K/N --out FILE.h5"],
        python: &[],
        dask: &[],
        layouts: &["sweep"],
        reproduced: false,
    },
    Study {
        name: "sweep3d",
        computes: "random off-center 3D kicks over the declared parameters' sampled ranges, each flown where asked",
        commands: &["kick sweep3d --out FILE.h5", "kick sweep3d --flight --distance D --out FILE.h5"],
        python: &[],
        dask: &[],
        layouts: &["sweep"],
        reproduced: false,
    },
    Study {
        name: "merge",
        computes: "the shards of one experiment or sweep joined into the file an unsharded run writes",
        commands: &["kick merge FILE.h5 PART.h5..."],
        python: &[],
        dask: &[],
        layouts: &["sweep"],
        reproduced: false,
    },
    Study {
        name: "identify",
        computes: "parameters identified from the user's own measurements, with uncertainties and identifiability",
        commands: &["kick fit data SPEC --out FILE"],
        python: &["fit"],
        dask: &[],
        layouts: &["kick-fit"],
        reproduced: false,
    },
];

/// `kick reproduce`'s steps, in the order they run.
pub fn reproduce_steps() -> impl Iterator<Item = &'static Study> {
    STUDIES.iter().filter(|s| s.reproduced)
}

/// The step of `kick reproduce` called `name`, or an error naming `flag`
/// (`--only`) and listing the steps.
pub fn reproduce_step(name: &str, flag: &'static str) -> Result<&'static Study, StudyError> {
    reproduce_steps().find(|s| s.name == name).ok_or_else(|| {
        let names: Vec<&str> = reproduce_steps().map(|s| s.name).collect();
        StudyError::Flag { flag, message: format!("{flag}: no step `{name}`; the steps are {}", names.join(", ")) }
    })
}

/// The studies that write layout `layout`.
pub fn writing(layout: &str) -> impl Iterator<Item = &'static Study> + '_ {
    STUDIES.iter().filter(move |s| s.layouts.contains(&layout))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Names are unique, steps come first, and a study runs from somewhere.
    #[test]
    fn each_study_is_declared_once_and_runs_from_somewhere() {
        for (i, a) in STUDIES.iter().enumerate() {
            assert!(STUDIES[i + 1..].iter().all(|b| b.name != a.name), "`{}` twice", a.name);
            assert!(!a.commands.is_empty() || !a.python.is_empty(), "`{}` runs from nowhere", a.name);
            assert!(a.commands.iter().all(|c| c.starts_with("kick ")), "`{}`: {:?}", a.name, a.commands);
            assert!(a.dask.iter().all(|d| a.python.contains(d)), "`{}`: a Dask function without its Python one", a.name);
        }
        let steps = STUDIES.iter().take_while(|s| s.reproduced).count();
        assert_eq!(steps, reproduce_steps().count(), "the steps are the list's head");
        assert_eq!(steps, 19);
    }

    #[test]
    fn an_unknown_step_is_refused_with_the_flag_and_the_steps() {
        let e = reproduce_step("figure", "--only").unwrap_err();
        assert!(e.to_string().starts_with("--only: no step `figure`; the steps are experiments, figures,"), "{e}");
        assert_eq!(reproduce_step("bench", "--only").unwrap().name, "bench");
        assert!(reproduce_step("aim", "--only").is_err(), "a user's study is not a step");
    }
}
