//! Command-line flags derived from the declared parameters
//! (`kick_core::parameters`, kick-flight's `FLIGHT_PARAMETERS`): one flag per
//! parameter of the spec, `--` plus the kebab case of its name, with its
//! symbol as the value name and its doc, unit and default as help. Values are
//! validated where the spec is built, so a bad value gets the library's typed
//! error naming it.

use clap::{Arg, ArgAction, ArgMatches, Command};
use kick_3d::KickSpec;
use kick_core::parameters::{self, ParameterDef, SetLaw, SetParameter, Shape, Value};
use kick_core::{LawKind, ScenarioSpec};
use kick_flight::{FlightParameter, FlightSpec, FLIGHT_PARAMETERS};
use kick_study::flight::After;
use std::marker::PhantomData;

/// A spec the flags fill: its declared parameters, and (if it takes one) the contact law.
pub trait FlagSpec: Default {
    /// Whether the spec takes `--law`.
    const LAW: bool;
    /// A flag every one of these flags needs beside it (`--flight`).
    const REQUIRES: Option<&'static str> = None;
    /// The declared parameters that are flags, in declaration order.
    fn parameters() -> Vec<&'static ParameterDef>;
    /// Set a parameter given as a flag (of its declared shape).
    fn set(&mut self, parameter: &'static ParameterDef, value: Value);
    fn set_law(&mut self, _law: LawKind) {}
}

/// The specs of declared parameters that take a contact law (1D and 3D
/// kicks): their levels' parameters and `--law`, set through kick-core's
/// traits.
macro_rules! law_spec_flags {
    ($($spec:ty),*) => {$(
        impl FlagSpec for $spec {
            const LAW: bool = true;
            fn parameters() -> Vec<&'static ParameterDef> {
                parameters::at_levels(Self::LEVELS).collect()
            }
            fn set(&mut self, parameter: &'static ParameterDef, value: Value) {
                // Flags exist only for the spec's parameters, with their shapes.
                let _ = self.set_parameter(parameter, value);
            }
            fn set_law(&mut self, law: LawKind) {
                SetLaw::set_law(self, law);
            }
        }
    )*};
}

law_spec_flags!(ScenarioSpec, KickSpec);

fn set_flight(spec: &mut FlightSpec, parameter: &'static ParameterDef, value: Value) {
    if let Ok(p) = FlightParameter::from_name(parameter.name) {
        let _ = match value {
            Value::Number(x) => spec.set(p, &[x]),
            Value::Vector(v) => spec.set(p, &v),
            Value::Switch(_) => Ok(()),
        };
    }
}

/// `kick flight`: every flight parameter.
impl FlagSpec for FlightSpec {
    const LAW: bool = false;
    fn parameters() -> Vec<&'static ParameterDef> {
        FLIGHT_PARAMETERS.iter().collect()
    }
    fn set(&mut self, parameter: &'static ParameterDef, value: Value) {
        set_flight(self, parameter, value);
    }
}

/// The flight after a kick (`--flight` of `kick simulate`, `THREE_D` false,
/// and of `kick simulate3d`): the flight parameters the kick does not set
/// ([`After::sets`]), each needing `--flight`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct FlightAfter<const THREE_D: bool>(pub FlightSpec);

pub type FlightAfter1d = FlightAfter<false>;
pub type FlightAfter3d = FlightAfter<true>;

impl<const THREE_D: bool> FlightAfter<THREE_D> {
    pub const KICK: After = if THREE_D { After::Kick3d } else { After::Kick1d };
}

impl<const THREE_D: bool> FlagSpec for FlightAfter<THREE_D> {
    const LAW: bool = false;
    const REQUIRES: Option<&'static str> = Some(FLIGHT);
    fn parameters() -> Vec<&'static ParameterDef> {
        FlightParameter::ALL.iter().filter(|&&p| !Self::KICK.sets(p)).map(|p| p.def()).collect()
    }
    fn set(&mut self, parameter: &'static ParameterDef, value: Value) {
        set_flight(&mut self.0, parameter, value);
    }
}

/// `kick sweep3d`'s held parameters: every parameter of the kick and
/// `--law` (a sampled file's columns hold every one its law uses, the
/// instep's when one is given).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SampledKick(pub KickSpec);

impl FlagSpec for SampledKick {
    const LAW: bool = true;
    fn parameters() -> Vec<&'static ParameterDef> {
        parameters::at_levels(KickSpec::LEVELS).collect()
    }
    fn set(&mut self, parameter: &'static ParameterDef, value: Value) {
        let _ = self.0.set_parameter(parameter, value);
    }
    fn set_law(&mut self, law: LawKind) {
        SetLaw::set_law(&mut self.0, law);
    }
}

/// `kick aim --from kick`: the 1D and 3D kick parameters and `--law`, but
/// not those whose names the flight declares too (`ball_mass`,
/// `ball_radius`, `gravity`: one flag per name; the kick keeps their defaults).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AimKick(pub KickSpec);

impl FlagSpec for AimKick {
    const LAW: bool = true;
    fn parameters() -> Vec<&'static ParameterDef> {
        parameters::at_levels(KickSpec::LEVELS).filter(|p| FlightParameter::from_name(p.name).is_err()).collect()
    }
    fn set(&mut self, parameter: &'static ParameterDef, value: Value) {
        let _ = self.0.set_parameter(parameter, value);
    }
    fn set_law(&mut self, law: LawKind) {
        SetLaw::set_law(&mut self.0, law);
    }
}

/// The switch that chains a kick into its flight; its id, for `requires`.
pub const FLIGHT: &str = "flight";

const LAW: &str = "law";

/// The flags of `S`'s parameters and `--law`; [`Flags::spec`] is what was given.
#[derive(Debug, Clone, Default)]
pub struct Flags<S> {
    /// Each parameter given, in declaration order.
    pub given: Vec<(&'static ParameterDef, Value)>,
    pub law: Option<LawKind>,
    /// Every value of the flight's `--distance`, which may be repeated (one
    /// crossing plane each); the spec's `distance` is the first.
    pub distances: Vec<f64>,
    spec: PhantomData<S>,
}

/// `help` with the note that the flag repeats, before its `[default: ...]`
/// (the reference page reads the default from the end).
fn repeat_note(help: &str) -> String {
    const NOTE: &str = " (repeat for several planes, located in one solve)";
    match help.rfind(" [default: ") {
        Some(at) => format!("{}{NOTE}{}", &help[..at], &help[at..]),
        None => format!("{help}{NOTE}"),
    }
}

/// The flight's crossing plane: its flag may be given more than once.
fn repeatable(p: &ParameterDef) -> bool {
    std::ptr::eq(p, FlightParameter::Distance.def())
}

impl<S: FlagSpec> Flags<S> {
    /// The flight plan of these flags: `rest` with the planes of `--distance`
    /// (one: `rest`'s distance; several: each located in the one solve).
    pub fn plan(&self, rest: FlightSpec) -> Result<kick_study::flight::FlightPlan, kick_flight::FlightError> {
        kick_study::flight::FlightPlan::with_distances(FlightSpec { distance: None, ..rest }, &self.distances)
    }
}

impl<S: FlagSpec> Flags<S> {
    /// The spec with the values given (the rest left to the defaults) and the
    /// law (the paper's unless chosen).
    pub fn spec(&self) -> S {
        let mut spec = S::default();
        if S::LAW {
            spec.set_law(self.law.unwrap_or(LawKind::PowerLaw));
        }
        for &(parameter, value) in &self.given {
            spec.set(parameter, value);
        }
        spec
    }
}

fn parameter_arg(p: &'static ParameterDef, requires: Option<&'static str>) -> Arg {
    let arg = Arg::new(p.name).long(p.long()).help(p.help());
    let arg = match requires {
        Some(other) => arg.requires(other),
        None => arg,
    };
    // Hyphen values: `-4,3,2` and `-inf` are values, not flags. A
    // non-finite number the parameter does not admit (friction admits inf)
    // is refused here, naming the flag; the rest is the spec's to validate.
    let number = move |text: &str| -> Result<f64, String> {
        let x: f64 = text.trim().parse().map_err(|_| format!("`{text}` is not a number"))?;
        match x.is_finite() {
            true => Ok(x),
            false => p.check(x).map_err(|_| format!("{x} is not a finite number")),
        }
    };
    match p.shape {
        Shape::Scalar if repeatable(p) => {
            arg.value_name(p.symbol).value_parser(number).allow_hyphen_values(true).action(ArgAction::Append).help(repeat_note(&p.help()))
        }
        Shape::Scalar => arg.value_name(p.symbol).value_parser(number).allow_hyphen_values(true).action(ArgAction::Set),
        // The three numbers are one value, checked as a whole where clap
        // names the subcommand (a count checked after parsing printed the
        // top command's usage, `kick <COMMAND>`); the last occurrence wins.
        Shape::Vector3 => arg
            .value_name(format!("{0}x,{0}y,{0}z", p.symbol))
            .value_parser(move |text: &str| -> Result<[f64; 3], String> {
                let numbers = text.split(',').map(number).collect::<Result<Vec<f64>, String>>()?;
                <[f64; 3]>::try_from(numbers.as_slice()).map_err(|_| format!("takes three numbers (x,y,z), got {}", numbers.len()))
            })
            .allow_hyphen_values(true)
            .action(ArgAction::Set),
        Shape::Switch => arg.action(ArgAction::SetTrue),
    }
}

pub fn parse_law(name: &str) -> Result<LawKind, String> {
    LawKind::from_name(name).map_err(|e| e.to_string())
}

impl<S: FlagSpec> clap::Args for Flags<S> {
    fn augment_args(mut command: Command) -> Command {
        for p in S::parameters() {
            command = command.arg(parameter_arg(p, S::REQUIRES));
        }
        if !S::LAW {
            return command;
        }
        command.arg(
            Arg::new(LAW)
                .long(LAW)
                .value_name("NAME")
                .help(format!("Contact law: {} (power-law: the paper's, Eq. 20)", LawKind::NAMES))
                .default_value("power-law")
                .value_parser(parse_law),
        )
    }
    fn augment_args_for_update(command: Command) -> Command {
        Self::augment_args(command)
    }
}

impl<S: FlagSpec> clap::FromArgMatches for Flags<S> {
    fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
        let mut flags = Flags { given: Vec::new(), law: None, distances: Vec::new(), spec: PhantomData };
        flags.update_from_arg_matches(matches)?;
        Ok(flags)
    }

    fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
        for p in S::parameters() {
            if repeatable(p) {
                if let Some(values) = matches.get_many::<f64>(p.name) {
                    self.distances = values.copied().collect();
                }
            }
            let value = match p.shape {
                Shape::Scalar if repeatable(p) => matches.get_many::<f64>(p.name).and_then(|mut v| v.next()).map(|&x| Value::Number(x)),
                Shape::Scalar => matches.get_one::<f64>(p.name).map(|&x| Value::Number(x)),
                Shape::Vector3 => matches.get_one::<[f64; 3]>(p.name).map(|&v| Value::Vector(v)),
                Shape::Switch => matches.get_flag(p.name).then_some(Value::Switch(true)),
            };
            if let Some(value) = value {
                self.given.retain(|(q, _)| q.name != p.name);
                self.given.push((p, value));
            }
        }
        if S::LAW {
            if let Some(&law) = matches.get_one::<LawKind>(LAW) {
                self.law = Some(law);
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::{Args, FromArgMatches};
    use kick_3d::KickSpec;
    use kick_core::ScenarioSpec;

    fn parse<S: FlagSpec>(args: &[&str]) -> Result<Flags<S>, clap::Error> {
        let command = Flags::<S>::augment_args(Command::new("kick"));
        let matches = command.try_get_matches_from(std::iter::once("kick").chain(args.iter().copied()))?;
        Flags::<S>::from_arg_matches(&matches)
    }

    /// A parameter's flag with a value of its shape.
    fn flag_args(p: &ParameterDef) -> Vec<String> {
        match p.shape {
            Shape::Scalar => vec![p.flag(), "0.25".into()],
            Shape::Vector3 => vec![p.flag(), "0.25,0.5,0.75".into()],
            Shape::Switch => vec![p.flag()],
        }
    }

    /// Every declared 1D and 3D parameter is a flag of `kick simulate3d`,
    /// every 1D one of `kick simulate`, and the value lands in the spec.
    #[test]
    fn every_declared_parameter_is_a_flag() {
        for p in parameters::at_levels(KickSpec::LEVELS) {
            let args = flag_args(p);
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            let flags = parse::<KickSpec>(&args).unwrap_or_else(|e| panic!("{}: {e}", p.name));
            let mut expected = KickSpec::default();
            FlagSpec::set_law(&mut expected, LawKind::PowerLaw);
            let value = flags.given.iter().find(|(q, _)| q.name == p.name).map(|(_, v)| *v).expect("given");
            expected.set_parameter(p, value).unwrap();
            assert_eq!(flags.spec(), expected, "{}", p.name);
            if matches!(p.level, kick_core::Level::Scenario | kick_core::Level::Bounce | kick_core::Level::Foot) {
                assert!(parse::<ScenarioSpec>(&args).is_ok(), "{}", p.name);
            } else {
                assert!(parse::<ScenarioSpec>(&args).is_err(), "{} is not a 1D flag", p.name);
            }
        }
    }

    /// `kick sweep3d` holds every parameter of the kick (its file records
    /// every one the law uses, the instep's when given).
    #[test]
    fn sweep3d_holds_every_parameter_of_the_kick() {
        for p in parameters::at_levels(KickSpec::LEVELS) {
            let args = flag_args(p);
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            assert!(parse::<SampledKick>(&args).is_ok(), "{}", p.name);
        }
    }

    /// `--distance` may be repeated after a kick: every value is a plane,
    /// the first is the spec's distance.
    #[test]
    fn distance_repeats() {
        let command =
            Flags::<FlightAfter3d>::augment_args(Command::new("kick")).arg(Arg::new(FLIGHT).long(FLIGHT).action(ArgAction::SetTrue));
        let matches = command.try_get_matches_from(["kick", "--flight", "--distance", "9.15", "--distance", "25"]).unwrap();
        let flags = Flags::<FlightAfter3d>::from_arg_matches(&matches).unwrap();
        assert_eq!(flags.distances, [9.15, 25.0]);
        let plan = flags.plan(flags.spec().0).unwrap();
        assert_eq!(plan.planes, Some(vec![9.15, 25.0]));
    }

    #[test]
    fn help_and_vector_lengths() {
        let command = Flags::<KickSpec>::augment_args(Command::new("kick"));
        let arg = command.get_arguments().find(|a| a.get_id() == "foot_mass").unwrap();
        assert_eq!(arg.get_help().unwrap().to_string(), "Effective foot mass (Eqs. 11-12): m_f, kg [default: 3]");
        let error = parse::<KickSpec>(&["--foot-inertia", "1,2"]).unwrap_err();
        let error = error.to_string();
        assert!(error.contains("'--foot-inertia <") && error.contains("takes three numbers (x,y,z), got 2"), "{error}");
        let flags = parse::<ScenarioSpec>(&["--law", "flores", "--restitution", "0.6", "--damping", "-5"]).unwrap();
        let spec = flags.spec();
        assert_eq!((spec.law, spec.restitution, spec.damping), (Some(LawKind::Flores), Some(0.6), Some(-5.0)));
    }

    /// Every flight parameter is a flag of `kick flight`, landing in the
    /// spec; after a kick only those the kick does not set are, and they need `--flight`.
    #[test]
    fn flight_flags_are_the_declared_flight_parameters() {
        for p in FlightParameter::ALL {
            let arg = match p.components() {
                3 => "0.25,0.5,0.75",
                _ => "0.25",
            };
            let flags = parse::<FlightSpec>(&[&p.def().flag(), arg]).unwrap_or_else(|e| panic!("{}: {e}", p.name()));
            assert!(flags.spec().is_set(p), "{}", p.name());
            let with_flight = |args: &[&str]| {
                let command = Flags::<FlightAfter3d>::augment_args(Command::new("kick"))
                    .arg(Arg::new(FLIGHT).long(FLIGHT).action(ArgAction::SetTrue));
                command.try_get_matches_from(std::iter::once("kick").chain(args.iter().copied()))
            };
            let flag = p.def().flag();
            let given = with_flight(&["--flight", &flag, arg]);
            assert_eq!(given.is_ok(), !After::Kick3d.sets(p), "{}", p.name());
            if given.is_ok() {
                assert!(with_flight(&[&flag, arg]).is_err(), "{} without --flight", p.name());
            }
        }
        assert!(parse::<FlightSpec>(&["--law", "flores"]).is_err());
    }

    /// A leading minus is a value (`--spin -4,3,2`, `--ball-speed -6`), and a
    /// value outside the declared range (`-inf`) is refused naming the flag.
    #[test]
    fn negative_values_and_non_finite_values_name_the_flag() {
        let flags = parse::<FlightSpec>(&["--spin", "-4,3,2", "--launch-velocity", "-25,0,8"]).unwrap();
        let given: Vec<Value> = flags.given.iter().map(|(_, v)| *v).collect();
        assert_eq!(given, [Value::Vector([-25.0, 0.0, 8.0]), Value::Vector([-4.0, 3.0, 2.0])]);
        let flags = parse::<ScenarioSpec>(&["--ball-speed", "-6", "--foot-speed", "0"]).unwrap();
        assert_eq!((flags.spec().ball_speed, flags.spec().foot_speed), (Some(-6.0), Some(0.0)));
        for args in [["--ball-speed", "-inf"], ["--ball-speed", "nan"], ["--spin", "-inf,0,0"]] {
            let error =
                if args[0] == "--spin" { parse::<FlightSpec>(&args).unwrap_err() } else { parse::<ScenarioSpec>(&args).unwrap_err() };
            let text = error.to_string();
            assert!(text.contains(args[0]) && text.contains("finite"), "{args:?}: {text}");
        }
    }
}
