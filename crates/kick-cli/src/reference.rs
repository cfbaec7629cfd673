//! The generated reference pages `paper/reference/cli.md` (every subcommand
//! and flag, from the clap definitions) and `paper/reference/parameters.md`
//! (the declared parameter lists): `kick reference cli|parameters` prints
//! them; a test (`tests/kick/cli.rs`) keeps the committed pages current.

use clap::{Arg, Command};
use kick_core::parameters::{Bound, ParameterDef, Shape, PARAMETERS};
use kick_flight::FLIGHT_PARAMETERS;
use std::fmt::Write as _;

/// Which page.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum Page {
    /// Every subcommand and flag of `kick` (paper/reference/cli.md)
    Cli,
    /// The declared parameters: keys, flags, columns, keywords (paper/reference/parameters.md)
    Parameters,
    /// The result-file layouts, every file's contract (paper/reference/files.md)
    Files,
}

/// Text for one Markdown table cell: one line, `|` escaped.
fn cell(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ").replace('|', "\\|")
}

/// How a flag is written: `--name VALUE`, `-s, --name`, or a positional `FILE`.
fn written(arg: &Arg) -> String {
    let value = || {
        arg.get_value_names()
            .map(|names| names.iter().map(|n| format!("<{n}>")).collect::<Vec<_>>().join(" "))
            .unwrap_or_else(|| format!("<{}>", arg.get_id().as_str().to_uppercase()))
    };
    let takes_value = arg.get_num_args().is_some_and(|n| n.takes_values());
    match arg.get_long() {
        Some(long) => {
            let short = arg.get_short().map(|s| format!("-{s}, ")).unwrap_or_default();
            let optional = arg.get_num_args().is_some_and(|n| n.min_values() == 0);
            match (takes_value, optional) {
                (false, _) => format!("{short}--{long}"),
                (true, true) => format!("{short}--{long} [{}]", value()),
                (true, false) => format!("{short}--{long} {}", value()),
            }
        }
        None => value(),
    }
}

fn command_section(page: &mut String, command: &Command, path: &str) {
    let _ = writeln!(page, "## `{path}`\n");
    if let Some(about) = command.get_long_about().or(command.get_about()) {
        let _ = writeln!(page, "{}\n", about.to_string().trim_end());
    }
    let mut usage = command.clone().bin_name(path).render_usage().to_string();
    usage = usage.trim_start_matches("Usage: ").trim_end().to_string();
    let _ = writeln!(page, "    {usage}\n");
    let args: Vec<&Arg> =
        command.get_arguments().filter(|a| !a.is_hide_set() && !matches!(a.get_id().as_str(), "help" | "version")).collect();
    if !args.is_empty() {
        let _ = writeln!(page, "| flag | help | default |\n| --- | --- | --- |");
        for arg in args {
            let mut help = arg.get_long_help().or(arg.get_help()).map(|h| h.to_string()).unwrap_or_default();
            let values: Vec<String> =
                arg.get_possible_values().iter().filter(|v| !v.is_hide_set()).map(|v| v.get_name().to_string()).collect();
            if !values.is_empty() && !help.contains(&values.join(" | ")) {
                let _ = write!(help, " (one of: {})", values.join(", "));
            }
            if arg.is_required_set() {
                help.push_str(" (required)");
            }
            let mut default = arg.get_default_values().iter().map(|v| v.to_string_lossy().into_owned()).collect::<Vec<_>>().join(",");
            // A default the help states (the declared parameters', `[default: X]`) goes to its column.
            if let (true, Some(start)) = (default.is_empty(), help.rfind(" [default: ")) {
                if help.ends_with(']') {
                    default = help[start + 11..help.len() - 1].to_string();
                    help.truncate(start);
                }
            }
            let _ = writeln!(page, "| `{}` | {} | {} |", cell(&written(arg)), cell(help.trim()), cell(&default));
        }
        page.push('\n');
    }
    for sub in command.get_subcommands().filter(|s| !s.is_hide_set() && s.get_name() != "help") {
        command_section(page, sub, &format!("{path} {}", sub.get_name()));
    }
}

/// `paper/reference/cli.md` from the command definitions.
pub fn cli(mut command: Command) -> String {
    command.build();
    let mut page = String::from(
        "# `kick` command-line reference\n\n\
         Generated from the clap definitions in `crates/kick-cli` by `kick reference cli > paper/reference/cli.md`; \
         do not edit (the test `reference_pages_are_current` fails when it is stale). The parameter flags come from \
         the declared parameters ([parameters.md](parameters.md)); `kick SUBCOMMAND --help` prints the same text, \
         `kick man` the manual page.\n\n",
    );
    let subcommands: Vec<&Command> = command.get_subcommands().filter(|s| !s.is_hide_set() && s.get_name() != "help").collect();
    for sub in &subcommands {
        let _ = writeln!(
            page,
            "- [`kick {}`](#kick-{}): {}",
            sub.get_name(),
            sub.get_name(),
            cell(&sub.get_about().map(|a| a.to_string()).unwrap_or_default())
        );
    }
    page.push('\n');
    for sub in subcommands {
        command_section(&mut page, sub, &format!("kick {}", sub.get_name()));
    }
    page.trim_end().to_string() + "\n"
}

fn bound(b: Bound, low: bool) -> String {
    match (b, low) {
        (Bound::Unbounded, true) => "(−∞".into(),
        (Bound::Unbounded, false) => "∞)".into(),
        (Bound::Open(x), true) => format!("({}", kick_core::short(x)),
        (Bound::Open(x), false) => format!("{})", kick_core::short(x)),
        (Bound::Closed(x), true) => format!("[{}", kick_core::short(x)),
        (Bound::Closed(x), false) => format!("{}]", kick_core::short(x)),
    }
}

fn parameter_table(page: &mut String, list: &[ParameterDef]) {
    let _ = writeln!(page, "| name | flag | symbol | unit | level | shape | default | valid | sampled | meaning |");
    let _ = writeln!(page, "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    for p in list {
        let valid = match p.shape {
            Shape::Switch => "true or false".to_string(),
            _ => format!("{}, {}: {}", bound(p.valid.low, true), bound(p.valid.high, false), p.valid.requirement),
        };
        let columns = p.columns().join(", ");
        let name = if columns == p.name { format!("`{}`", p.name) } else { format!("`{}` (columns {columns})", p.name) };
        let _ = writeln!(
            page,
            "| {name} | `{}` | {} | {} | {} | {} | {} | {} | {} | {} |",
            p.flag(),
            cell(p.symbol),
            cell(p.unit),
            p.level.name(),
            p.shape.describe(),
            cell(&p.default.text()),
            cell(&valid),
            p.sample.map(|s| cell(&s.describe())).unwrap_or_default(),
            cell(p.doc)
        );
    }
    page.push('\n');
}

/// Where each contact law holds (`kick_core::LawKind::validity`), and what
/// a result outside it is.
fn law_validity(page: &mut String) {
    page.push_str(
        "### Where each law holds\n\n\
         Each law holds up to a compression, a fraction of the ball's radius R (the shell ball's own; the 1D \
         model's other laws take the default ball's 0.11 m). A contact that goes deeper is solved, but its \
         numbers are the law's, not a ball's: its status is 4, `outside validity` (`kick_core::Status`). A row \
         of a result file, a sweep or a `_many` function keeps its numbers with that status and the reason \
         (`/failures`, `failure_message`); `kick simulate`, `simulate3d` and `bounce` print the result with its \
         status and exit 1; Python's single calls return it with `status` and warn \
         (`kick.OutsideValidityWarning`). kick-3d refuses a compression past R outright (status 3).\n\n\
         | law | holds while | why | also assumes (not checked) |\n| --- | --- | --- | --- |\n",
    );
    for law in kick_core::LawKind::SELECTABLE {
        let v = law.validity();
        let _ = writeln!(page, "| `{}` | δ_max ≤ {} | {} | {} |", law.name(), v.limit, v.why, v.assumes);
    }
    page.push('\n');
}

/// `paper/reference/parameters.md` from the declared lists.
pub fn parameters() -> String {
    let mut page = String::from(
        "# Declared parameters\n\n\
         Generated from `kick_core::parameters::PARAMETERS` and `kick_flight::FLIGHT_PARAMETERS` by \
         `kick reference parameters > paper/reference/parameters.md`; do not edit (the test \
         `reference_pages_are_current` fails when it is stale).\n\n\
         Each parameter is declared once. Its name is the key in experiment and fit files, the dataset under \
         `/parameters` (or `/fixed`) of result files (a vector as `_x`, `_y`, `_z` columns) and the Python keyword; \
         its flag is `--` plus the name in kebab case, with the meaning, symbol, unit and default as help \
         ([cli.md](cli.md)). A value outside the valid range is refused with an error naming the parameter; \
         `kick sweep` and `kick sweep3d` draw from the sampled range.\n\n\
         ## The kick: 1D scenario and 3D kick (`kick_core::parameters::PARAMETERS`)\n\n",
    );
    parameter_table(&mut page, &PARAMETERS);
    let _ = writeln!(
        page,
        "`--law NAME` (TOML `law`, Python `law`) chooses the contact law of the 1D and 3D levels \
         (`kick_core::LawKind`): {}.\n",
        kick_core::LawKind::NAMES
    );
    law_validity(&mut page);
    page.push_str(
        "## The flight (`kick_flight::FLIGHT_PARAMETERS`)\n\n\
         The flight's parameters have a name space of their own (its `gravity` is g, the 3D kick's a switch).\n\n",
    );
    parameter_table(&mut page, &FLIGHT_PARAMETERS);
    page.trim_end().to_string() + "\n"
}
