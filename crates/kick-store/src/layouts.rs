//! The file contract: every layout a result file can have, with its name and
//! version (root attributes `layout` and `layout_version` of every file), who
//! writes it and what it holds. This table is the specification, written
//! once: `kick reference files` prints it as `paper/reference/files.md`
//! (kept current by a test of kick-cli), and the writers take their
//! `layout` attributes from it.
//!
//! Conventions shared by every layout: every dataset has a `units` attribute
//! (SI; `1` dimensionless, empty for text); a vector quantity is three 1-D
//! columns `NAME_x`, `NAME_y`, `NAME_z`; a status is a `u8` of
//! `kick_core::Status` codes (0 separated, 1 numerical failure, 2 trapped,
//! 3 refused, 4 outside validity) with a `meaning` attribute; the root carries the provenance
//! (tool, tool_version, git_commit, git_dirty, experiment, experiment_file,
//! experiment_text); no time stamps, so the same run writes the same bytes.

use crate::h5::{write_str_attr, write_u64_attr, H5Error};
use std::fmt::Write as _;
use std::path::Path;

/// One layout of result files.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// The root attribute `layout`.
    pub name: &'static str,
    /// The root attribute `layout_version`; bumped on incompatible changes.
    pub version: u64,
    /// The library code that writes it (the studies that do, and their
    /// commands, are `kick_study::studies`').
    pub writer: &'static str,
    /// What a file of this layout is.
    pub summary: &'static str,
    /// Its objects: path, type, meaning.
    pub objects: &'static [(&'static str, &'static str, &'static str)],
    /// What changed from the version before, if any.
    pub changes: &'static str,
}

impl Layout {
    /// Write `layout` and `layout_version` on `file`'s root.
    pub fn stamp(&self, file: &hdf5::Location, path: &Path) -> Result<(), H5Error> {
        write_str_attr(file, path, "layout", self.name)?;
        write_u64_attr(file, path, "layout_version", self.version)
    }
}

/// A table of rows: one row per scenario, kick or cell.
pub const SWEEP: Layout = Layout {
    name: "sweep",
    version: 3,
    writer: "`kick_store::h5::SweepWriter`, filled by the one run loop `kick_study::level::run_rows`",
    summary: "A table: named parameter columns and one or more outcome sets (one per solver, one per chained flight), \
              every per-row dataset 1-D of length `rows` (attribute `rows`), rows in input order (grids in C order, the \
              last axis fastest).",
    objects: &[
        (
            "/",
            "attributes",
            "provenance; `description`; the first set's `solver` and its settings as typed attributes \
                             (step, tolerances, `law`, ...); `rows`; `grid_shape` (u64[axes], grids); `level` (`3d` for \
                             3D files); `seed`, `samples` (`kick sweep3d`); `history_interval` (history runs); a shard's \
                             `shard_*` attributes",
        ),
        (
            "/parameters/<name>",
            "f64[rows]",
            "each parameter of the row: the 1D model's eight (and `restitution` under a \
                                             law that takes one), a 3D grid's axes, every declared 1D and 3D parameter of \
                                             `kick sweep3d` (vectors as `_x/_y/_z`, switches 0/1)",
        ),
        (
            "/outcomes/<name>",
            "f64[rows]",
            "the first set's outcome columns, NaN where its status has no outcome (1, 2, 3; a row outside its \
                                           law's validity, 4, keeps its numbers): the 1D \
                                           model's `kick_core::OBSERVABLES`, the 3D model's `kick_3d::OBSERVABLES_3D`, a \
                                           flight's `kick_flight::OUTCOME_COLUMNS`",
        ),
        ("/outcomes/status", "u8[rows]", "kick_core::Status code of each row in the first set"),
        (
            "/failures/index, /failures/message",
            "u64[f], string[f]",
            "row and message of every row whose status is not 0 (why it failed, or which validity it left)",
        ),
        (
            "/histories/<row:06>/<column>",
            "f64[samples]",
            "time histories of a row (history runs; attribute `row`), the \
                                                           columns of the history layout",
        ),
        (
            "/solvers/<set>/...",
            "groups",
            "`outcomes/`, `failures/`, `histories/` of every further set, with its own \
                                          `solver` and settings attributes; a flight after solver S is the set `S+flight`",
        ),
        ("/scenario_names", "string[rows]", "named scenarios (Table 2 rows)"),
        ("/paper/<column>", "f64[rows]", "Table 2 as printed, when every row is one of its rows"),
        (
            "/grid/<axis>, /grid/axes",
            "f64[n], string[axes]",
            "grid experiments: each axis's values with units, and the \
                                                              axes in order; f[\"outcomes/X\"][:].reshape(f.attrs[\"grid_shape\"]) \
                                                              is the grid",
        ),
        ("/fixed/<name>", "f64[1 or 3]", "3D grids: every parameter not swept, as the kick was built"),
    ],
    changes: "3: status 4, outside validity: a row whose contact went past where its law holds (the shell ball past \
              R/2, another law past R) keeps its numbers and says why under /failures (such rows had status 0). \
              2: status codes are kick_core::Status in every table (1D failures were 1 whatever their cause); \
              `kick sweep3d` writes this layout (it had its own, `sweep3d`, with [rows, 3] vectors and an `energy` group); \
              the root attribute `layout`.",
};

/// A uniform time history of one contact or flight.
pub const HISTORY: Layout = Layout {
    name: "history",
    version: 1,
    writer: "`kick_store::history`",
    summary: "Rows uniform in time from first touch (launch, for a flight), then the separation (landing) row.",
    objects: &[
        (
            "/",
            "attributes",
            "provenance; `level` (`1d`, `3d`, `flight`); `solver` and `law` (1D, 3D) or `drag`, `lift` \
                             (flight); `samples` (rows); `samples_requested` or `interval` (s)",
        ),
        (
            "/history/<name>",
            "f64[samples]",
            "one column each: kick_core::HISTORY_COLUMNS (1D), \
                                             kick_3d::HISTORY_COLUMNS_3D (3D; then kick_3d::PATCH_COLUMNS_3D when the \
                                             normal force is spread over a patch), the flight's FLIGHT_HISTORY_COLUMNS",
        ),
        ("/fixed/<name>", "f64[1 or 3]", "every parameter the run was solved with (defaults filled in; switches 0/1)"),
    ],
    changes: "",
};

/// `kick fit data --out`: one identification.
pub const FIT: Layout = Layout {
    name: "kick-fit",
    version: 2,
    writer: "`kick_store::identify::fit`",
    summary: "The estimates of one identification from a measured history, with what they rest on.",
    objects: &[
        ("/", "attributes", "provenance"),
        (
            "/fit",
            "scalars, strings",
            "a fit report: law, termination, converged, chi_square, degrees_of_freedom, \
                                      residual_variance, evaluations, parameters (the free ones, in order); \
                                      outside_validity, when a contact at the estimate leaves its law's validity (status 4), \
                                      one line each",
        ),
        (
            "/fit/estimates/<parameter>/...",
            "scalars",
            "each estimate with its start, truth (synthetic data) and \
                                                       standard error",
        ),
        (
            "/fit/correlation/<parameter>, /fit/singular_values",
            "f64[free]",
            "the correlation matrix by column and the \
                                                                            singular values of the weighted Jacobian",
        ),
        (
            "/fit/residuals/<observable or channel>/...",
            "f64[samples]",
            "the data fitted and the weighted residuals at \
                                                                        the estimates (histories: time s and each channel)",
        ),
        (
            "/fit/measurements/<i>/name, conditions/<parameter>, residuals/...",
            "string, scalars, f64[samples]",
            "each `[[measurement]]`: its name, the values it was taken at (in their units) and its residuals as above",
        ),
    ],
    changes: "2: /fit/measurements/<i>/ for the measurements of a `[[measurement]]` fit, each at its own conditions",
};

/// `kick fit table2 --out`: Table 2 read back.
pub const FIT_TABLE2: Layout = Layout {
    name: "kick-fit-table2",
    version: 1,
    writer: "`kick_store::identify::files`",
    summary: "Each free parameter of Table 2 identified from the paper's rounded outputs, beside the unrounded ones.",
    objects: &[
        ("/", "attributes", "provenance"),
        (
            "/rows/<NN>",
            "strings, scalars",
            "one group per Table 2 row: name, parameter (the one identified), \
                                            file_value, seed_fit_value",
        ),
        ("/rows/<NN>/fit/...", "group", "the row's fit report, as `/fit` of the `kick-fit` layout"),
    ],
    changes: "",
};

/// `kick fit identifiability`: misfit profiles and maps.
pub const IDENTIFIABILITY: Layout = Layout {
    name: "kick-identifiability",
    version: 1,
    writer: "`kick_store::identify::files`",
    summary: "Whether a history identifies the parameters: profiles of the misfit along each parameter and maps over pairs.",
    objects: &[
        ("/", "attributes", "provenance"),
        (
            "/settings, /truth, /history_sigma",
            "scalars, strings",
            "the study: seed, history_times, exit_speed_sigma, \
                                                                  law; the true parameters; the noise of each channel",
        ),
        (
            "/profiles/<source>/<parameter>/...",
            "f64[points]",
            "source `exit_speed` or `histories`: truth, factor, \
                                                              value, chi_square, and the other parameters' factors (`others/`)",
        ),
        (
            "/maps/<source>/...",
            "f64[points]",
            "x and y (parameter names), x_factor, y_factor, chi_square over a grid of \
                                              the two",
        ),
    ],
    changes: "",
};

/// Spin against offset of one kick per contact model and friction, the
/// points solved only (`kick reproduce`'s patch step).
pub const PATCH_SPIN: Layout = Layout {
    name: "patch-spin",
    version: 1,
    writer: "`kick_store::patch`",
    summary: "Off-center 3D kicks of one ball and foot against the offset, one curve per contact model and friction \
              coefficient; a kick the solver refuses is left out of its curve (no NaN), its offset and the reason kept.",
    objects: &[
        ("/", "attributes", "provenance; `description`; `law`; `solver`"),
        ("/fixed/<name>", "f64[1 or 3]", "every parameter the contacts' kicks share, offset and friction aside (defaults filled in)"),
        ("/grid/offset", "f64[n]", "the offsets asked for, m"),
        (
            "/asai2002/friction_gain, peak_offset",
            "f64[1]",
            "what the figure is drawn beside: Asai et al.'s (2002) \
                                                           largest spin gain from friction 0 → 1 (rad/s) and offset of \
                                                           largest spin (m), from the measurement file (attribute \
                                                           `source`: the file and keys)",
        ),
        (
            "/curves/<contact>/mu_<μ>",
            "group",
            "one curve: `<contact>` is `point` (the rigid sphere's point contact on \
                                              the knife-edge face) or `patch_cap` (the patch on a cap); attribute \
                                              `contact` (what it is, in words); datasets `friction` (1), `patch_contact` \
                                              (0/1) and `instep_radius` (m, 0: flat) of one element",
        ),
        (
            "/curves/<contact>/mu_<μ>/offset, spin_z, spin, speed, launch_azimuth, contact_time",
            "f64[solved]",
            "the solved \
              kicks: offset (m), the spin's vertical component and size (rad/s), ball speed (m/s), launch azimuth \
              (deg), contact time (s)",
        ),
        ("/curves/<contact>/mu_<μ>/refused_offset, refused_reason", "f64[r], string[r]", "the offsets of the grid left out and why"),
    ],
    changes: "",
};

/// Every layout, in the order of the reference page.
pub const LAYOUTS: [&Layout; 6] = [&SWEEP, &HISTORY, &FIT, &FIT_TABLE2, &IDENTIFIABILITY, &PATCH_SPIN];

/// The layout called `name`.
pub fn find(name: &str) -> Option<&'static Layout> {
    LAYOUTS.iter().copied().find(|l| l.name == name)
}

/// Who writes layout `l`: the file-writing command lines of the studies
/// that write it (`kick_study::studies`), the `kick reproduce` steps among
/// them, and the library code.
pub fn written_by(l: &Layout) -> String {
    let mut commands: Vec<String> = Vec::new();
    let mut steps: Vec<String> = Vec::new();
    for study in kick_study::studies::writing(l.name) {
        for c in study.commands.iter().filter(|c| c.contains("-out") || c.contains(".h5")) {
            let c = format!("`{c}`");
            if !commands.contains(&c) {
                commands.push(c);
            }
        }
        if study.reproduced {
            steps.push(format!("`{}`", study.name));
        }
    }
    if !steps.is_empty() {
        commands.push(format!("`kick reproduce` (step{} {})", if steps.len() > 1 { "s" } else { "" }, steps.join(", ")));
    }
    format!("{}; {}", commands.join(", "), l.writer)
}

/// The reference page of result files (markdown), from [`LAYOUTS`].
pub fn markdown() -> String {
    let mut w = String::new();
    let _ = writeln!(w, "# Result files\n");
    let _ = writeln!(
        w,
        "Generated by `kick reference files` from `kick_store::layouts` (the specification, written once); \
         a test keeps this page current.\n"
    );
    let _ = writeln!(w, "Every HDF5 result file names its layout in two root attributes, `layout` and `layout_version`.");
    let _ = writeln!(w, "Conventions shared by every layout:\n");
    for rule in [
        "every dataset has a `units` attribute (SI; `1` dimensionless, empty for text);",
        "a vector quantity is three 1-D columns `NAME_x`, `NAME_y`, `NAME_z`;",
        &format!("a status is a `u8` of `kick_core::Status` codes ({}) with a `meaning` attribute;", crate::h5::status_meaning()),
        "the root carries the provenance: tool, tool_version, git_commit and git_dirty (absent outside a checkout), \
         experiment, experiment_file, experiment_text; git_commit is the last commit that changed the sources when the \
         file's content last changed: a rerun that would write the same content otherwise leaves the file as it is;",
        "no time stamps: the same run writes the same bytes; a file is written whole or not at all \
         (`kick_store::output`).",
    ] {
        let _ = writeln!(w, "- {rule}");
    }
    let _ = writeln!(w, "\n| layout | version | written by |\n| --- | --- | --- |");
    for l in LAYOUTS {
        let _ = writeln!(w, "| [`{}`](#{}) | {} | {} |", l.name, l.name, l.version, written_by(l));
    }
    for l in LAYOUTS {
        let _ = writeln!(w, "\n## {}\n\n`layout = \"{}\"`, `layout_version = {}`. {}\n", l.name, l.name, l.version, l.summary);
        let _ = writeln!(w, "| object | type | holds |\n| --- | --- | --- |");
        for (path, kind, holds) in l.objects {
            let _ = writeln!(w, "| `{path}` | {kind} | {holds} |");
        }
        if !l.changes.is_empty() {
            let _ = writeln!(w, "\nChanges in version {}", l.changes);
        }
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every layout is written by a declared study, and every layout a study
    /// declares exists.
    #[test]
    fn studies_and_layouts_name_each_other() {
        for l in LAYOUTS {
            assert!(kick_study::studies::writing(l.name).next().is_some(), "no study writes `{}`", l.name);
        }
        for study in kick_study::studies::STUDIES {
            for name in study.layouts {
                assert!(find(name).is_some(), "study `{}` writes an undeclared layout `{name}`", study.name);
            }
        }
        assert!(written_by(&SWEEP).contains("`kick sweep3d --out FILE.h5`"), "{}", written_by(&SWEEP));
        assert!(written_by(&PATCH_SPIN).contains("`kick reproduce` (step `patch`)"), "{}", written_by(&PATCH_SPIN));
    }

    /// Names are unique and each layout has its section on the page.
    #[test]
    fn every_layout_is_named_once_and_specified_on_the_page() {
        let page = markdown();
        for (i, l) in LAYOUTS.iter().enumerate() {
            assert!(LAYOUTS[..i].iter().all(|m| m.name != l.name), "{} twice", l.name);
            assert!(page.contains(&format!("## {}\n", l.name)), "{}", l.name);
            assert!(!l.objects.is_empty() && l.version >= 1, "{}", l.name);
            assert_eq!(find(l.name), Some(*l));
        }
        assert_eq!(find("sweep3d"), None, "sweep3d files are sweep tables since layout 2");
    }
}
