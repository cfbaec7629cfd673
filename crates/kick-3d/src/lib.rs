//! Off-center 3D kicks: a sphere and a rigid instep with the scenario's normal
//! contact law (the paper's Eq. 20 or any law of `kick_core::laws`), Coulomb
//! friction with the shell's tangential compliance ([`tangential`]), and the spin
//! that an off-center contact gives (Eq. 61). Section 17 of the paper lists
//! what its 1D model leaves out; this crate adds 17.4–17.5.
//!
//! Solvers (one law, four paths):
//! - [`accurate::Accurate3d`] (`accurate`): the relative motion in the foot's
//!   frame ([`contact`]) on DOP853 with switches located on its dense
//!   output; analytic geometry on the face, parry3d on edges and borders;
//! - [`full_state::FullState3d`] (`full-state`): both rigid bodies in the
//!   world frame on ode_solvers' Dop853, parry3d at every evaluation; the
//!   independent reference of `accurate`;
//! - [`one_d`] (`1d`): the 1D accurate solver along the normal, exact for
//!   central, square kicks (nothing slides, so no friction and no torque);
//! - [`scene::Scene`] (`rapier`, feature `rapier`): a rapier3d world (ground,
//!   gravity, later a leg) with the same law applied as external forces.
//!
//! [`Solver3d::Auto`] picks the cheapest path the scene needs.

pub mod accurate;
pub mod checks;
pub mod contact;
pub mod dynamics;
pub mod error;
pub mod full_state;
pub mod history;
pub mod model;
pub mod models;
pub mod one_d;
pub mod outcome;
pub mod patch;
pub mod precision;
#[cfg(feature = "rapier")]
pub mod scene;
pub mod sweep;
pub mod tangential;
pub mod validation;

pub use accurate::Accurate3d;
pub use error::Kick3dError;
pub use full_state::FullState3d;
pub use history::{ContactState, Sample3d, HISTORY_COLUMNS_3D, PATCH_COLUMNS_3D};
pub use model::{FootShape, Instep, Kick3d, Kick3dSpec, KickSpec};
pub use outcome::{EnergyPartition, Outcome3d, FIELDS_3D, FIELD_VALUES_3D, OBSERVABLES_3D};

/// The rapier scene path's step when none is given, s (see [`scene`]).
pub const DEFAULT_SCENE_STEP: f64 = 1e-6;

/// The 3D solvers selectable by name (`--solver`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Solver3d {
    /// 1d for central, square kicks (any μ: nothing slides), rapier when the
    /// scene has a ground, accurate otherwise. A frictionless off-center kick
    /// goes to accurate: the contact point slides along the face and the
    /// normal force then turns the foot, which the 1D model cannot follow.
    Auto,
    Accurate(Accurate3d),
    FullState(FullState3d),
    OneD,
    #[cfg(feature = "rapier")]
    Rapier(scene::Scene),
}

impl Solver3d {
    #[cfg(feature = "rapier")]
    pub const NAMES: [&'static str; 5] = ["auto", "accurate", "full-state", "1d", "rapier"];
    #[cfg(not(feature = "rapier"))]
    pub const NAMES: [&'static str; 4] = ["auto", "accurate", "full-state", "1d"];

    /// Look a solver up by name; `scene_step` is the rapier path's step, s.
    pub fn from_name(name: &str, scene_step: f64) -> Result<Solver3d, Kick3dError> {
        match name {
            "auto" => Ok(Solver3d::Auto),
            "accurate" => Ok(Solver3d::Accurate(Accurate3d::default())),
            "full-state" => Ok(Solver3d::FullState(FullState3d::default())),
            "1d" => Ok(Solver3d::OneD),
            #[cfg(feature = "rapier")]
            "rapier" => Ok(Solver3d::Rapier(scene::Scene::new(scene_step)?)),
            _ => {
                let _ = scene_step;
                Err(Kick3dError::UnknownSolver { name: name.to_string(), expected: "auto, accurate, full-state, 1d, rapier" })
            }
        }
    }

    /// As `from_name`, with `dt` as the user gave it: `None` is the scene's
    /// default step; a step given to a path other than `rapier` (which
    /// choose their own steps, `auto` included) is refused rather than ignored.
    pub fn with_step(name: &str, dt: Option<f64>) -> Result<Solver3d, Kick3dError> {
        let solver = Solver3d::from_name(name, dt.unwrap_or(DEFAULT_SCENE_STEP))?;
        if dt.is_some() && name != "rapier" {
            return Err(kick_core::KickError::DoesNotApply {
                given: "dt",
                to: format!("3D solver `{name}`"),
                reason: "it chooses its own steps; `dt` is the step of the rapier scene path (`--solver rapier`)",
            }
            .into());
        }
        Ok(solver)
    }

    /// The path `Auto` takes for this kick.
    pub fn resolve(&self, kick: &Kick3d) -> Solver3d {
        match self {
            Solver3d::Auto if kick.ground => {
                #[cfg(feature = "rapier")]
                {
                    Solver3d::Rapier(scene::Scene::default())
                }
                #[cfg(not(feature = "rapier"))]
                {
                    Solver3d::Accurate(Accurate3d::default())
                }
            }
            Solver3d::Auto if kick.is_one_dimensional() => Solver3d::OneD,
            Solver3d::Auto => Solver3d::Accurate(Accurate3d::default()),
            other => *other,
        }
    }

    pub fn solve(&self, kick: &Kick3d) -> Result<Outcome3d, Kick3dError> {
        match self.resolve(kick) {
            Solver3d::Accurate(s) => s.solve(kick),
            Solver3d::FullState(s) => s.solve(kick),
            Solver3d::OneD => one_d::solve(kick),
            #[cfg(feature = "rapier")]
            Solver3d::Rapier(s) => s.solve(kick),
            Solver3d::Auto => unreachable!("resolve never returns Auto"),
        }
    }
}
