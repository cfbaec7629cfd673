//! What a result table is made of, without its file format: named columns
//! with units, outcome sets with their solver settings, and the compression
//! a file asks for (kick-store writes them as HDF5).

/// A named column and its unit.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    pub name: String,
    pub unit: String,
}

impl Column {
    pub fn new(name: &str, unit: &str) -> Column {
        Column { name: name.into(), unit: unit.into() }
    }
}

/// One set of outcome columns: which solver, where, with what settings.
#[derive(Debug, Clone, PartialEq)]
pub struct OutcomeSet {
    /// Solver name, written as the `solver` attribute.
    pub solver: String,
    /// Settings (step, tolerances, contact law...), one typed attribute each.
    pub settings: Vec<(String, Setting)>,
    pub columns: Vec<Column>,
}

/// `numbers` and the scenario's contact law: `law` (its name) and, for a
/// law other than the paper's, `restitution` (its target).
pub fn law_settings<'a>(scenario: &kick_core::Scenario, numbers: impl IntoIterator<Item = (&'a str, f64)>) -> Vec<(String, Setting)> {
    let mut settings = Setting::numbers(numbers);
    settings.push(("law".into(), Setting::Text(scenario.law_kind().name().into())));
    if let Some(e) = scenario.restitution_target() {
        settings.push(("restitution".into(), Setting::Number(e)));
    }
    settings.extend(ball_settings(scenario.contact_law()));
    settings.extend(foot_settings(scenario.foot()));
    settings
}

/// The foot's settings under their declared names (the leg's switch and
/// pose, the boot's two numbers; `boot_stiffness` inf for a leg without
/// one), so a file records the foot it was solved with; none for Table 1's
/// rigid foot.
pub fn foot_settings(foot: kick_core::Foot) -> Vec<(String, Setting)> {
    Setting::numbers(foot.settings())
}

/// The shell ball's own quantities under their declared names, so a file
/// records the ball it was solved with (none for the other laws, whose
/// parameters are columns or the scenario's).
pub fn ball_settings(law: kick_core::AnyLaw) -> Vec<(String, Setting)> {
    use kick_core::shell::{GAS_EXPONENT, INFLATION_PRESSURE, SHELL_DAMPING, SHELL_STIFFNESS};
    match law {
        kick_core::AnyLaw::Shell(b) => Setting::numbers([
            (INFLATION_PRESSURE.name, b.pressure),
            (GAS_EXPONENT.name, b.gas_exponent),
            (SHELL_STIFFNESS.name, b.shell_stiffness),
            (SHELL_DAMPING.name, b.shell_damping),
        ]),
        _ => Vec::new(),
    }
}

/// The value of one setting attribute: a number or a text, never both in one string.
#[derive(Debug, Clone, PartialEq)]
pub enum Setting {
    Number(f64),
    Text(String),
}

impl Setting {
    /// Numeric settings under their names.
    pub fn numbers<N: Into<String>>(settings: impl IntoIterator<Item = (N, f64)>) -> Vec<(String, Setting)> {
        settings.into_iter().map(|(name, value)| (name.into(), Setting::Number(value))).collect()
    }
}

/// How the per-row numeric datasets of a result file (parameters, outcomes,
/// status, failure indices) are stored: plain, or through HDF5's byte
/// shuffle and deflate (gzip) filters, chunk by chunk. Readers decompress
/// transparently, so the values read back are the same bits; the file is
/// smaller and slower to write (kick-store's README.md, "Compressed result files").
/// Text datasets (failure messages, names) stay plain: deflate would see
/// only their references into HDF5's heap.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Compression {
    #[default]
    None,
    /// Shuffle, then deflate at this level (1 fastest ..= 9 smallest).
    Deflate(u8),
}

impl Compression {
    /// The level of `--compress` without a value and of `compress = true`.
    pub const DEFAULT_LEVEL: u8 = 4;

    /// Shuffle + deflate at `level` (`None`: [`Self::DEFAULT_LEVEL`]), given
    /// as `what` (a flag or key, named in the error).
    pub fn deflate(level: Option<i64>, what: &str) -> Result<Compression, crate::error::StudyError> {
        match level {
            None => Ok(Compression::Deflate(Self::DEFAULT_LEVEL)),
            Some(l @ 1..=9) => Ok(Compression::Deflate(l as u8)),
            Some(level) => Err(crate::error::StudyError::Deflate { what: what.into(), level }),
        }
    }
}
