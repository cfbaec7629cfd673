//! `kick`: the command line of the kick workspace. Each subcommand parses its
//! arguments, calls one function of the library crates (kick-study, kick-store, kick-paper) and prints what it returns.

mod bounce;
mod flags;
mod output;
mod reference;

use clap::{Args, CommandFactory, Parser, Subcommand};
use flags::{Flags, FlightAfter1d, FlightAfter3d};
use kick_3d::{KickSpec, Solver3d};
use kick_compliant::SolverChoice;
use kick_core::ScenarioSpec;
use kick_flight::FlightSpec;
use output::{note, CliResult, Format, Out};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "kick", version, about = "Millisecond physics of a soccer kick")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Simulate one 1D contact (defaults: Table 1's baseline).
    Simulate(Simulate),
    /// Simulate one off-center 3D kick: spin, friction, launch direction.
    ///
    /// Axes (right-handed, the ball's centre at the origin): x is the foot's
    /// horizontal direction, the kick's direction at zero approach angle; y is
    /// lateral (the kicker's left); z is up. The foot moves at --foot-speed
    /// along û = (cos α, 0, sin α), α = --approach-angle. The ball moves at
    /// --ball-speed along x. --offset e and --contact-depth h place the
    /// foot's line of motion: the ball's centre is e from it sideways and h
    /// above it (perpendicular to the line), so e > 0 sends the ball toward
    /// −y spinning ω_z < 0 (and Magnus curves it further to −y), and h > 0
    /// lifts it with backspin ω_y < 0. The instep face is tangent to the ball
    /// where that line meets it (the knife edge), or a surface of its own
    /// (--face-yaw, --face-pitch, --instep-radius) whose pole moves on the
    /// line. --foot-half-extents hx,hy,hz is the instep box's outer half-size
    /// (hx along the face normal), --border-radius rounds its edges inside
    /// that size. Vectors in the output (launch_velocity, spin, ...) are in
    /// these axes; with --flight the ball flies from the ground (its centre
    /// at height R), each --distance a crossing plane.
    Simulate3d(Simulate3d),
    /// Fly the ball from its launch: drag crisis, Magnus lift, landing, apex, plane crossing.
    Flight(FlightArgs),
    /// Aim a free kick: the launch (or the 3D kick) that clears the wall and
    /// crosses the goal plane at the target.
    ///
    /// Axes as `kick flight`: the ball starts at the origin, x toward the
    /// goal, y lateral, z up; the goal (7.32 m x 2.44 m) and the wall are
    /// centred on y = 0. Least squares (Levenberg-Marquardt) over the free
    /// parameters within their ranges; prints the solution, the miss, the
    /// wall clearance and d(y, z at the goal)/d(each free parameter), or
    /// says that none was found from its starts within the ranges (exit 1).
    /// Every launch and kick parameter is held or free. A parameter's flag
    /// holds it at that value; free are those --free names, else the default
    /// ones not given: launch: speed, launch_angle, azimuth (also spin_x,
    /// spin_y, spin_z); kick: foot_speed, offset, contact_depth, heading
    /// (also any number parameter of the kick: approach_angle, friction,
    /// inflation_pressure, ...). A free parameter's bounds: --range
    /// NAME=LOW,HIGH, else the aim's own; its start: its flag's value, else
    /// speed 25 m/s, launch_angle 15°, azimuth and heading toward the target,
    /// spin 0, foot_speed 18 m/s, offset 0.02 m, contact_depth 0.03 m. More
    /// free parameters than two leave a family of solutions: its extent is
    /// reported, and --objective picks one member.
    Aim(AimArgs),
    /// Fire the ball at a rigid, massive, horizontal plate: the shell ball
    /// (pressure over the flat patch, adiabatic gas, shell loss; kick-bounce).
    ///
    /// Axes: the plate is z = 0 with normal +z; the ball comes down in the
    /// x–z plane at --angle from the normal; --spin in the same axes. Give
    /// --speed, or --drop-height for a square drop from rest (FIFA's rebound
    /// test: --drop-height 2 at the default 0.8 bar).
    Bounce(BounceArgs),
    /// Table 2 side by side: printed, seed-rk4 and accurate values.
    Table2(Table2),
    /// Cross-model checks: each model level against the others' limits (exits 1 on a failure).
    Check(FormatOnly),
    /// Effective mass of the articulated leg (Eq. 11) and the exit speed it gives.
    ///
    /// With no arguments, the default pose (`kick_study::leg::LegSettings::default`):
    /// knee flexed 30°, ankle plantarflexed 60°, thigh 10° forward of vertical;
    /// free knee and ankle, pinned hip, planar leg; contact at 0.65 of the
    /// foot's length, horizontal impact; de Leva's (1996) reference male.
    Leg(Leg),
    /// Contact laws (paper, Hunt–Crossley, Lankarani–Nikravesh, Flores, Kelvin–Voigt) on Table 2's scenarios.
    Laws(Laws),
    /// Identify parameters from printed or measured data.
    #[command(subcommand)]
    Fit(Fit),
    /// Run one experiment file, 1D or 3D (experiments/*.toml, experiments/3d/*.toml) into DIR/NAME.h5, or one shard of it.
    #[command(alias = "run3d")]
    Run(Run),
    /// Join shard files of one experiment or sweep (`--shard` of run, sweep, sweep3d) into the file an unsharded run writes.
    Merge(Merge),
    /// Work–precision of every 1D solver, cost ratios and sweep throughput (HDF5 + figure).
    Bench(Bench),
    /// Random scenarios around the baseline, solved in parallel into one HDF5 file.
    Sweep(Sweep),
    /// Random off-center 3D kicks around the baseline, solved in parallel into one HDF5 file.
    Sweep3d(Sweep3d),
    /// Run every experiment, draw the figures, run the checks, write paper/README.md.
    Reproduce(Reproduce),
    /// Shell completions on stdout, e.g. `kick completions bash > /etc/bash_completion.d/kick`.
    Completions {
        /// bash, zsh, fish, elvish or powershell
        #[arg(value_enum)]
        shell: clap_complete::Shell,
    },
    /// The manual page (roff) on stdout: `kick man > kick.1; man ./kick.1`.
    Man,
    /// A generated reference page (Markdown) on stdout: `kick reference cli > paper/reference/cli.md`.
    Reference {
        #[arg(value_enum)]
        page: reference::Page,
    },
}

#[derive(Args)]
struct FormatOnly {
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

#[derive(Args)]
struct Simulate {
    /// The declared 1D parameters and --law; left out, Table 1's baseline and the paper's law.
    #[command(flatten)]
    scenario: Flags<ScenarioSpec>,
    /// Step of the fixed-step solvers (seed-rk4, rk4-events), s [default: 5e-6]
    #[arg(long, allow_negative_numbers = true)]
    dt: Option<f64>,
    #[arg(long, default_value = "auto", value_parser = SolverChoice::NAMES)]
    solver: String,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    #[command(flatten)]
    history: HistoryArgs,
    /// Then fly the ball: v_b+ at --launch-angle (and --azimuth), no spin
    #[arg(long)]
    flight: bool,
    /// The flight's parameters (with --flight)
    #[command(flatten)]
    flight_parameters: Flags<FlightAfter1d>,
}

#[derive(Args)]
struct BounceArgs {
    /// The declared bounce parameters: --speed or --drop-height required
    #[command(flatten)]
    bounce: Flags<kick_bounce::BounceSpec>,
    /// The ball's contact law: shell (the pressurised ball, kick-core's
    /// ShellBall) or a law of the kick's family by its --law name
    #[arg(long, value_name = "NAME", default_value = "shell", value_parser = bounce::parse_law)]
    law: kick_bounce::LawChoice,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

#[derive(Args)]
struct FlightArgs {
    /// The declared flight parameters: --speed and --launch-angle (or --launch-velocity) required
    #[command(flatten)]
    flight: Flags<FlightSpec>,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    #[command(flatten)]
    history: HistoryArgs,
}

#[derive(Args)]
struct AimArgs {
    /// Where the ball's centre should cross the goal plane x = X, m (inside the posts, under the bar)
    #[arg(long, value_name = "X,Y,Z", value_delimiter = ',', allow_hyphen_values = true, required = true)]
    target: Vec<f64>,
    /// The wall: distance, height of its top and half-width, m [default: 9.15,1.8,1]
    #[arg(long, value_name = "DIST,HEIGHT,HALF_WIDTH", value_delimiter = ',', allow_hyphen_values = true)]
    wall: Option<Vec<f64>>,
    /// Solve for the launch or for the 3D kick before it
    #[arg(long, default_value = "launch", value_parser = kick_study::aim::AimFrom::NAMES)]
    from: String,
    /// The free parameters, comma-separated (see above)
    #[arg(long, value_name = "NAMES", value_delimiter = ',')]
    free: Option<Vec<String>>,
    /// Bounds of a free parameter (repeat the flag for several)
    #[arg(long, value_name = "NAME=LOW,HIGH")]
    range: Vec<String>,
    /// Which member of the family of solutions: min-foot-speed (--from kick),
    /// min-speed (launch speed), min-time (to the goal line), max-clearance
    /// (of the wall), the best of the members solved on the family's grid,
    /// not a proven optimum [default: the one the solve reaches from the starts]
    #[arg(long, value_name = "NAME", value_parser = ["min-foot-speed", "min-speed", "min-time", "max-clearance"])]
    objective: Option<String>,
    /// The declared flight parameters: fixed values, or the starts of free ones
    #[command(flatten)]
    flight: Flags<FlightSpec>,
    /// With --from kick: the kick's parameters (--foot-speed: fixed, or the start when free)
    #[command(flatten)]
    kick: Flags<flags::AimKick>,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

/// Three numbers given to `flag`, or an error naming it.
fn three(flag: &str, values: &[f64]) -> Result<[f64; 3], String> {
    match values {
        &[x, y, z] => Ok([x, y, z]),
        other => Err(format!("{flag} takes three numbers separated by commas, got {}", other.len())),
    }
}

/// `--history FILE [--samples N | --interval DT]` (kick_store::history).
#[derive(Args)]
struct HistoryArgs {
    /// Write the time history to FILE: .csv (header `name [unit]`, then numbers only)
    /// or .h5/.hdf5 (one dataset per column with its units, and the parameters);
    /// uniform samples from first touch (t = 0) plus the last row at the end
    /// (separation, or the landing of a flight). Columns and units:
    /// crates/kick-store/README.md, "Time-history files". Only the summary goes to standard output.
    #[arg(long, value_name = "FILE")]
    history: Option<PathBuf>,
    /// Rows in all, both ends included [default: 201]
    #[arg(long, value_name = "N", requires = "history", conflicts_with = "interval")]
    samples: Option<usize>,
    /// Instead of --samples: rows DT seconds apart from t = 0, then the end row
    #[arg(long, value_name = "DT", requires = "history", allow_negative_numbers = true)]
    interval: Option<f64>,
}

impl HistoryArgs {
    fn request(&self) -> Result<Option<kick_study::history::HistoryRequest>, kick_store::StoreError> {
        self.history.as_deref().map(|path| kick_store::history::request(path, self.samples, self.interval)).transpose()
    }
}

#[derive(Args)]
struct Simulate3d {
    /// The declared 1D and 3D parameters and --law (the normal force's law).
    #[command(flatten)]
    kick: Flags<KickSpec>,
    /// auto | accurate | 1d | rapier
    #[arg(long, default_value = "auto", value_parser = Solver3d::NAMES)]
    solver: String,
    /// Step of the rapier scene path (--solver rapier), s [default: 1e-6]
    #[arg(long, allow_negative_numbers = true)]
    dt: Option<f64>,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Print the wall time of the solve (one run) on stderr
    #[arg(long)]
    time: bool,
    /// Instead of one solve: the rapier scene path at steps 4e-5 s halving to
    /// 6.25e-7 s against the accurate path (error, observed order, wall time)
    #[arg(long, conflicts_with_all = ["history", "flight", "time", "format", "solver"])]
    scene_convergence: bool,
    /// Then fly the ball from its launch velocity and spin
    #[arg(long)]
    flight: bool,
    /// The flight's air, coefficients and crossing plane (with --flight)
    #[command(flatten)]
    flight_parameters: Flags<FlightAfter3d>,
    /// The accurate path's history (--solver auto or accurate)
    #[command(flatten)]
    history: HistoryArgs,
}

#[derive(Args)]
struct Table2 {
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Scenario file with the rows' parameters
    #[arg(long, default_value = "experiments/table2.toml")]
    scenarios: PathBuf,
}

/// `kick leg`'s defaults: the library's documented default pose.
static POSE: std::sync::LazyLock<kick_study::leg::LegSettings> = std::sync::LazyLock::new(Default::default);

#[derive(Args)]
struct Leg {
    /// Knee flexion, degrees (0 = straight)
    #[arg(long, default_value_t = POSE.knee, allow_hyphen_values = true)]
    knee: f64,
    /// Ankle plantarflexion from neutral, degrees (0 = foot at right angles to the shank)
    #[arg(long, default_value_t = POSE.ankle, allow_hyphen_values = true)]
    ankle: f64,
    /// Thigh angle from the downward vertical, degrees, positive forward
    #[arg(long, default_value_t = POSE.hip, allow_hyphen_values = true)]
    hip: f64,
    /// Ankle rigid during contact (default: a free hinge)
    #[arg(long, conflicts_with = "ankle_stiffness")]
    locked_ankle: bool,
    /// Ankle torsional stiffness, N m/rad: leg and ball integrated together, m_eff = the 1D-equivalent mass
    #[arg(long, allow_hyphen_values = true)]
    ankle_stiffness: Option<f64>,
    /// Knee rigid during contact (default: a free hinge)
    #[arg(long)]
    locked_knee: bool,
    /// Let the hip translate freely (default: pinned hip)
    #[arg(long)]
    free_hip: bool,
    /// Spatial leg (ball-joint hip); enables --abduction, --rotation, --lateral-offset
    #[arg(long)]
    spatial: bool,
    /// Spatial: hip abduction, degrees
    #[arg(long, default_value_t = POSE.abduction, allow_hyphen_values = true)]
    abduction: f64,
    /// Spatial: thigh rotation about its long axis, degrees
    #[arg(long, default_value_t = POSE.rotation, allow_hyphen_values = true)]
    rotation: f64,
    /// Spatial: contact offset along the foot's mediolateral axis, m
    #[arg(long, default_value_t = POSE.lateral_offset, allow_hyphen_values = true)]
    lateral_offset: f64,
    /// Contact point from the ankle along the foot, fraction of foot length
    #[arg(long, default_value_t = POSE.contact, allow_hyphen_values = true)]
    contact: f64,
    /// Impact direction in the sagittal plane, degrees above horizontal-forward
    #[arg(long, default_value_t = POSE.direction, allow_hyphen_values = true)]
    direction: f64,
    /// Body mass, kg [de Leva's reference subject]
    #[arg(long, default_value_t = POSE.body_mass, allow_hyphen_values = true)]
    body_mass: f64,
    /// Stature, m [de Leva's reference subject]
    #[arg(long, default_value_t = POSE.height, allow_hyphen_values = true)]
    height: f64,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Also write the figure data to DIR (kick-store's HDF5 sweep layout):
    /// leg_effective_mass.h5 (knee 0-120 x ankle 0-90 deg, locked and free
    /// ankle) and leg_exit_speed.h5 (v_b+ vs m_f); other settings as given
    #[arg(long, value_name = "DIR")]
    sweep_out: Option<PathBuf>,
}

#[derive(Args)]
struct Laws {
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Scenario file with the rows' parameters
    #[arg(long, default_value = "experiments/table2.toml")]
    scenarios: PathBuf,
    /// Write laws.h5 (outcomes, force pulses, restitution of each formula) and
    /// laws.png/svg, drawn from laws.h5, here
    #[arg(long)]
    out: Option<PathBuf>,
    /// Pulse samples per undamped contact time (at most)
    #[arg(long, default_value_t = 200)]
    samples: u32,
}

#[derive(Subcommand)]
enum Fit {
    /// Table 2: each row's changed parameter by least squares on the four printed
    /// observables (accurate solver); --write keeps writing the seed-rk4 scenario file.
    Table2 {
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Write the scenario file (TOML, seed-rk4 Brent roots) here
        #[arg(long)]
        write: Option<PathBuf>,
        /// Write the fits (HDF5) here, with the scenario file's values and the
        /// same fits to seed-rk4's unrounded outputs at those values
        #[arg(long)]
        out: Option<PathBuf>,
        /// The scenario file whose values --out compares with
        #[arg(long, default_value = "experiments/table2.toml")]
        scenarios: PathBuf,
    },
    /// Fit the parameters a specification file names to its data (TOML/JSON; format: crates/kick-identify/README.md).
    Data {
        /// Fit specification (TOML, or JSON)
        spec: PathBuf,
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Write the fit report (HDF5: estimates, uncertainties, correlations, residuals) here
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Write a synthetic history (CSV) and a fit specification for it: Table 1's
    /// baseline (with the parameters and law given) plus seeded noise, to be fitted back with `kick fit data`.
    Synthesize {
        /// Directory for NAME.csv and NAME.toml
        #[arg(long, default_value = "results/identification")]
        out: PathBuf,
        /// File stem of the data and the specification
        #[arg(long, default_value = "synthetic")]
        name: String,
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Samples over 1.2 contact times (from t = 0, whatever the time offset)
        #[arg(long, default_value_t = 80)]
        times: usize,
        /// The truth: the declared 1D parameters and --law
        #[command(flatten)]
        truth: Flags<ScenarioSpec>,
        /// Time of first touch in the data, s; when non-zero the specification also fits `time_offset`
        #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
        time_offset: f64,
        /// Also write NAME_as_LAW.toml: the same data to be fitted with this other contact law
        /// (its parameters free), to see what a wrong law leaves in the residuals
        #[arg(long, value_name = "LAW", value_parser = flags::parse_law)]
        also_fit_law: Option<kick_core::LawKind>,
    },
    /// Identifiability (Section 17.8): misfit profiles of m_f, k, c, n from the exit
    /// speed alone and from noisy histories, and (k, c) misfit maps.
    Profile {
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Write identifiability.h5 and identifiability.png/svg (drawn from it) here
        #[arg(long)]
        out: Option<PathBuf>,
        /// Profile over [1/spread, spread] x the truth
        #[arg(long, default_value_t = 1.5)]
        spread: f64,
        #[arg(long, default_value_t = 9)]
        points: usize,
        /// Grid points per axis of the misfit maps
        #[arg(long, default_value_t = 21)]
        map_points: usize,
        #[arg(long, default_value_t = 5)]
        seed: u64,
    },
}

#[derive(Args)]
struct Run {
    /// Experiment file (experiments/*.toml)
    file: PathBuf,
    /// Directory for the result file NAME.h5
    #[arg(long, default_value = "results")]
    out: PathBuf,
    /// Worker threads (default: one per core)
    #[arg(long)]
    threads: Option<usize>,
    /// Run only shard I of N (numbered from 0, like Slurm array tasks):
    /// rows floor(I*rows/N)..floor((I+1)*rows/N) into DIR/NAME.shard-I-of-N.h5
    #[arg(long, value_name = "I/N")]
    shard: Option<String>,
}

#[derive(Args)]
struct Merge {
    /// The merged result file to write
    out: PathBuf,
    /// Shard files (NAME.shard-I-of-N.h5), all N of them, any order
    #[arg(required = true)]
    parts: Vec<PathBuf>,
}

#[derive(Args)]
struct Bench {
    /// Directory for work_precision.h5 (figures go to DIR/figures)
    #[arg(long, default_value = "results")]
    out: PathBuf,
    /// Least wall time per measured point, s
    #[arg(long, default_value_t = 0.3)]
    min_time: f64,
    /// Scenarios in the throughput sweep
    #[arg(long, default_value_t = 200_000)]
    sweep_samples: u64,
    /// Short variant for CI: a few ladder points, little time each
    #[arg(long)]
    quick: bool,
    /// Also write a Markdown page with the measured times (and the machine) here
    #[arg(long)]
    report: Option<PathBuf>,
    /// Also write the solvers' page (errors and evaluation counts, the same on every run) here
    #[arg(long)]
    solvers_report: Option<PathBuf>,
}

#[derive(Args)]
struct Sweep {
    /// Number of scenarios
    #[arg(long)]
    samples: u64,
    /// Seed of the sampler (the same seed gives the same file)
    #[arg(long, default_value_t = 1)]
    seed: u64,
    #[arg(long, default_value = "auto", value_parser = SolverChoice::NAMES)]
    solver: String,
    /// Step of the fixed-step solvers (seed-rk4, rk4-events), s [default: 5e-6]
    #[arg(long)]
    dt: Option<f64>,
    /// Result file (its directory is created)
    #[arg(long)]
    out: PathBuf,
    /// Worker threads (default: one per core)
    #[arg(long)]
    threads: Option<usize>,
    /// Solve only shard I of N of the samples (numbered from 0, like Slurm array
    /// tasks) into NAME.shard-I-of-N.h5 beside --out; join them with `kick merge`
    #[arg(long, value_name = "I/N")]
    shard: Option<String>,
    /// Store the per-row datasets through HDF5's shuffle + deflate filters at
    /// LEVEL 1 (fastest) to 9 (smallest), 4 without a value: a smaller file,
    /// a slower write; read back unchanged
    #[arg(long, value_name = "LEVEL", num_args = 0..=1)]
    compress: Option<Option<i64>>,
    /// Draw this parameter from LOW to HIGH (uniform, or log-uniform where its
    /// declared range is) instead of its declared range; any number parameter
    /// of the scenario and its ball (repeat for several). Without it every
    /// parameter with a declared range is drawn from it, the others held
    #[arg(long, value_name = "NAME=LOW,HIGH")]
    range: Vec<String>,
    /// A 1D parameter given is held at that value instead of drawn; --law
    /// and --restitution set the contact law of every scenario
    #[command(flatten)]
    fixed: Flags<ScenarioSpec>,
}

#[derive(Args)]
struct Sweep3d {
    /// Number of kicks
    #[arg(long)]
    samples: u64,
    /// Seed of the sampler (the same seed gives the same data, whatever the thread count)
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Result file NAME.h5 (its directory is created)
    #[arg(long)]
    out: PathBuf,
    /// Worker threads (default: one per core)
    #[arg(long)]
    threads: Option<usize>,
    /// Solve only shard I of N of the kicks (numbered from 0, like Slurm array
    /// tasks) into NAME.shard-I-of-N.h5 beside --out; join them with `kick merge`
    #[arg(long, value_name = "I/N")]
    shard: Option<String>,
    /// Store the per-row datasets through HDF5's shuffle + deflate filters at
    /// LEVEL 1 (fastest) to 9 (smallest), 4 without a value: a smaller file,
    /// a slower write; read back unchanged
    #[arg(long, value_name = "LEVEL", num_args = 0..=1)]
    compress: Option<Option<i64>>,
    /// Draw this parameter from LOW to HIGH (uniform, or log-uniform where its
    /// declared range is) instead of the off-center box's or its declared
    /// range; any number parameter of the kick, or with --flight of the
    /// flight (repeat for several)
    #[arg(long, value_name = "NAME=LOW,HIGH")]
    range: Vec<String>,
    /// A parameter of the kick given is held at that value instead of drawn;
    /// --law and --restitution set the normal contact law of every kick
    #[command(flatten)]
    fixed: Flags<flags::SampledKick>,
    /// Then fly each kick's ball from the ground (outcome set auto-3d+flight)
    #[arg(long)]
    flight: bool,
    /// The flight's air, coefficients and crossing planes (with --flight)
    #[command(flatten)]
    flight_parameters: Flags<FlightAfter3d>,
}

#[derive(Args)]
struct Reproduce {
    /// Directory of experiment files (every *.toml directly inside is run)
    #[arg(long, default_value = "experiments")]
    experiments: PathBuf,
    /// Directory for the result files; figures go to OUT/figures
    #[arg(long, default_value = "results")]
    out: PathBuf,
    /// Report to (re)generate
    #[arg(long, default_value = "paper/README.md")]
    report: PathBuf,
    /// The benchmark's short variant (as `kick bench --quick`): for tests, not for the committed pages
    #[arg(long)]
    quick_bench: bool,
    /// Regenerate into a temporary folder and compare with OUT and the report's folder (HDF5 by value,
    /// other files by bytes; timing outputs and the git_commit/git_dirty attributes left out); exits 1
    /// naming every file and dataset that differs
    #[arg(long)]
    check: bool,
    /// Worker threads (default: one per core)
    #[arg(long)]
    threads: Option<usize>,
    /// Print each step's name and the command lines it runs, and exit
    #[arg(long, conflicts_with = "check")]
    list: bool,
    /// Run only these steps (repeat the flag or give a comma list; `--list` names them)
    #[arg(long, value_name = "STEP", value_delimiter = ',', conflicts_with = "check")]
    only: Vec<String>,
}

fn main() -> ExitCode {
    kick_store::h5::disable_file_locking();
    if let Err(e) = kick_store::output::install_signal_cleanup() {
        eprintln!("warning: {e}; an interrupted run may leave a temporary file");
    }
    let cli = Cli::parse();
    let mut out = Out::new();
    match execute(cli.command, &mut out) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            note(&format!("error: {message}"));
            ExitCode::FAILURE
        }
    }
}

/// `--compress [LEVEL]` as given: absent, without a level, or with one.
fn compression(given: Option<Option<i64>>) -> Result<kick_store::h5::Compression, kick_study::StudyError> {
    given.map_or(Ok(kick_store::h5::Compression::None), |level| kick_store::h5::Compression::deflate(level, "--compress"))
}

fn execute(command: Command, out: &mut Out) -> CliResult {
    use kick_paper::{bench, identify, leg, reproduce};
    use kick_store::{shard, sweep, sweep3d};
    use kick_study::{checks, flight, set_threads, simulate, table2};
    use std::io::Write as _;
    match command {
        Command::Completions { shell } => {
            let mut text = Vec::new();
            clap_complete::generate(shell, &mut Cli::command(), "kick", &mut text);
            out.write_all(&text).and_then(|()| out.flush()).map_err(|e| format!("cannot write to standard output: {e}"))
        }
        Command::Man => {
            let mut text = Vec::new();
            clap_mangen::Man::new(Cli::command()).render(&mut text).map_err(|e| e.to_string())?;
            out.write_all(&text).and_then(|()| out.flush()).map_err(|e| format!("cannot write to standard output: {e}"))
        }
        Command::Reference { page } => {
            let text = match page {
                reference::Page::Cli => reference::cli(Cli::command()),
                reference::Page::Parameters => reference::parameters(),
                reference::Page::Files => kick_store::layouts::markdown(),
            };
            out.write_all(text.as_bytes()).and_then(|()| out.flush()).map_err(|e| format!("cannot write to standard output: {e}"))
        }
        Command::Simulate(a) => {
            let flight = a.flight.then(|| a.flight_parameters.plan(a.flight_parameters.spec().0)).transpose().map_err(flight::flight_error)?;
            let history = a.history.request()?;
            let simulation = simulate::simulate(&a.scenario.spec(), &a.solver, a.dt, history.as_ref(), flight.as_ref())?;
            out.print(a.format, &simulation)
        }
        Command::Simulate3d(a) if a.scene_convergence => match a.dt {
            Some(_) => Err("`dt` does not apply to --scene-convergence: it runs the rapier path at its own steps (4e-5 s halving to 6.25e-7 s); leave it out".into()),
            None => out.print(Format::Text, &simulate::scene_convergence(&a.kick.spec())?),
        },
        Command::Simulate3d(a) => {
            let flight = a.flight.then(|| a.flight_parameters.plan(a.flight_parameters.spec().0)).transpose().map_err(flight::flight_error)?;
            let history = a.history.request()?;
            let simulation = simulate::simulate3d(&a.kick.spec(), &a.solver, a.dt, history.as_ref(), flight.as_ref())?;
            if a.time {
                note(&format!("solver {} took {:.3} ms", simulation.outcome.solver, simulation.seconds * 1e3));
            }
            out.print(a.format, &simulation)
        }
        Command::Flight(a) => {
            let plan = a.flight.plan(a.flight.spec()).map_err(flight::flight_error)?;
            out.print(a.format, &flight::flight_report_planes(&plan, a.history.request()?.as_ref())?)
        }
        Command::Aim(a) => {
            use kick_study::aim::{aim, AimFrom, AimRequest};
            let request = AimRequest {
                target: Some(three("--target", &a.target)?),
                wall: a.wall.as_deref().map(|w| three("--wall", w)).transpose()?,
                from: Some(AimFrom::from_name(&a.from)?),
                free: a.free,
                ranges: a.range,
                objective: a.objective.as_deref().map(kick_flight::Objective::from_name).transpose().map_err(|e| e.to_string())?,
                flight: a.flight.spec(),
                // Nothing given: the default kick (so --from launch can refuse a kick flag given).
                kick: match (a.kick.given.is_empty(), a.kick.law) {
                    (true, None | Some(kick_core::LawKind::PowerLaw)) => kick_3d::KickSpec::default(),
                    _ => a.kick.spec().0,
                },
            };
            out.print(a.format, &aim(&request)?)
        }
        Command::Bounce(a) => {
            let mut spec = a.bounce.spec();
            spec.law = Some(a.law);
            out.print(a.format, &bounce::bounce(&spec)?)
        }
        Command::Table2(a) => {
            let table = table2::compare(&a.scenarios)?;
            out.print(a.format, &table)?;
            table.all_match().then_some(()).ok_or_else(|| "seed-rk4 does not reproduce every printed digit of Table 2".into())
        }
        Command::Check(a) => {
            let table = checks::run_all();
            out.print(a.format, &table)?;
            match table.failed() {
                0 => Ok(()),
                failed => Err(format!("{failed} of {} cross-model checks failed", table.rows.len())),
            }
        }
        Command::Leg(a) => {
            let settings = kick_study::leg::LegSettings {
                knee: a.knee,
                ankle: a.ankle,
                hip: a.hip,
                locked_ankle: a.locked_ankle,
                ankle_stiffness: a.ankle_stiffness,
                locked_knee: a.locked_knee,
                free_hip: a.free_hip,
                spatial: a.spatial,
                abduction: a.abduction,
                rotation: a.rotation,
                lateral_offset: a.lateral_offset,
                contact: a.contact,
                direction: a.direction,
                body_mass: a.body_mass,
                height: a.height,
            };
            let run = leg::LegRun { settings, sweep_out: a.sweep_out, command: std::env::args().collect::<Vec<_>>().join(" ") };
            out.print(a.format, &leg::leg(&run)?)
        }
        Command::Laws(a) => {
            let settings = identify::LawsSettings { scenarios: a.scenarios, out: a.out, samples: a.samples };
            out.print(a.format, &identify::laws(&settings)?)
        }
        Command::Fit(Fit::Table2 { format, write, out: file, scenarios }) => {
            out.print(format, &identify::table2(write.as_deref(), file.as_deref(), &scenarios)?)
        }
        Command::Fit(Fit::Data { spec, format, out: file }) => {
            let fit = identify::data(&spec, file.as_deref())?;
            out.print(format, &fit)?;
            Ok(fit.converged()?)
        }
        Command::Fit(Fit::Synthesize { out: dir, name, seed, times, truth, time_offset, also_fit_law }) => {
            out.print(Format::Text, &identify::synthesize(&dir, &name, seed, times, &truth.spec(), time_offset, also_fit_law)?)
        }
        Command::Fit(Fit::Profile { format, out: dir, spread, points, map_points, seed }) => {
            let settings = identify::ProfileSettings { out: dir, spread, points, map_points, seed };
            out.print(format, &identify::profile(&settings)?)
        }
        Command::Run(a) => {
            set_threads(a.threads).map_err(|e| e.to_string())?;
            out.print(Format::Text, &shard::run_file(&a.file, &a.out, a.shard.as_deref())?)
        }
        Command::Merge(a) => out.print(Format::Text, &shard::merge(&a.out, &a.parts).map_err(|e| e.to_string())?),
        Command::Bench(a) => {
            let settings =
                bench::BenchSettings { out: a.out, min_time: a.min_time, sweep_samples: a.sweep_samples, quick: a.quick, report: a.report, solvers_report: a.solvers_report };
            let report = bench::bench(&settings, out)?;
            out.print(Format::Text, &report)
        }
        Command::Sweep(a) => {
            let find = |name: &str| {
                use kick_core::parameters::SetParameter;
                kick_core::parameters::find_at(ScenarioSpec::LEVELS, name)
            };
            let settings = sweep::SweepSettings {
                samples: a.samples,
                seed: a.seed,
                solver: a.solver,
                dt: a.dt,
                out: a.out,
                fixed: a.fixed.spec(),
                ranges: kick_study::sample::Ranges::parse(&a.range, find)?,
                shard: a.shard,
                threads: a.threads,
                compress: compression(a.compress)?,
            };
            out.print(Format::Text, &sweep::sweep(&settings)?)
        }
        Command::Sweep3d(a) => {
            let flight = a.flight.then(|| a.flight_parameters.plan(a.flight_parameters.spec().0)).transpose().map_err(flight::flight_error)?;
            let ranges = kick_study::sample::Ranges::parse(&a.range, |name| sweep3d::find_range(name, a.flight))?;
            let settings = sweep3d::Sweep3dSettings {
                samples: a.samples,
                seed: a.seed,
                out: a.out,
                fixed: a.fixed.spec().0,
                ranges,
                flight,
                shard: a.shard,
                threads: a.threads,
                compress: compression(a.compress)?,
            };
            out.print(Format::Text, &sweep3d::sweep3d(&settings)?)
        }
        Command::Reproduce(a) => {
            set_threads(a.threads).map_err(|e| e.to_string())?;
            let settings = reproduce::ReproduceSettings {
                experiments: a.experiments,
                out: a.out,
                report: a.report,
                quick_bench: a.quick_bench,
                steps: if a.only.is_empty() { reproduce::Steps::All } else { reproduce::Steps::Only(a.only) },
            };
            if a.list {
                return out.print(Format::Text, &reproduce::list(&settings)?);
            }
            if a.check {
                let found = reproduce::check(&settings, &mut std::io::sink())?;
                out.print(Format::Text, &found)?;
                return match found.differences.len() {
                    0 => Ok(()),
                    _ => Err("the committed results differ from a regeneration (listed above)".into()),
                };
            }
            let done = reproduce::reproduce(&settings, out)?;
            out.print(Format::Text, &done)?;
            match done.failed_checks {
                0 => Ok(()),
                failed => Err(format!("{failed} cross-model check(s) failed; see {}", done.report.display())),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every command line the study registry (`kick_study::studies`) names
    /// runs: its subcommands (`kick fit data`) and its long flags exist.
    #[test]
    fn the_study_registry_names_real_commands() {
        let cli = Cli::command();
        for study in kick_study::studies::STUDIES {
            for line in study.commands {
                let words: Vec<&str> = line.split_whitespace().skip(1).collect();
                let (mut command, mut depth) = (&cli, 0);
                while let Some(sub) = words.get(depth).and_then(|w| command.find_subcommand(w)) {
                    command = sub;
                    depth += 1;
                }
                assert!(depth > 0, "{line}: no such subcommand");
                for flag in words[depth..].iter().filter_map(|w| w.strip_prefix("--")) {
                    assert!(command.get_arguments().any(|a| a.get_long() == Some(flag)), "{line}: no flag --{flag}");
                }
            }
        }
    }
}
