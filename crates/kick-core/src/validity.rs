//! Where each contact law holds, and the verdict on a result outside it.
//!
//! Every law of [`LawKind::SELECTABLE`] states its region of validity as a
//! largest compression, a fraction of the ball's radius R, and what else it
//! assumes (not checked at run time). A solve that went deeper still ends
//! (the formulas stay finite), but its numbers describe the law, not a
//! ball: [`check`] says so, and every front end and file reports it as
//! [`crate::Status::OutsideValidity`] (code 4) with the outcome's numbers
//! kept, never as an ordinary result.
//!
//! - The shell ball ([`crate::ShellBall`]): δ ≤ R/2. Its gas law and flat
//!   patch under a uniform gauge pressure describe a patch small against the
//!   ball; deeper, a real ball's shell buckles inward and the formulas (finite
//!   up to δ → 2R) no longer describe it (shell.rs's module docs).
//! - The paper's law (Eq. 20), the hysteresis family and Kelvin–Voigt:
//!   δ ≤ R. They are phenomenological, one compliance coordinate lumping ball
//!   and foot (the paper's Section 18: central impact, constant parameters, no
//!   wave propagation, no internal air dynamics); beyond R the ball's centre
//!   would cross the contact surface, where no contact is left to describe
//!   (kick-3d refuses such a kick outright, `KickError::BeyondGeometry`).

use crate::laws::LawKind;
use crate::number::short;
use serde::Serialize;

/// A law's region of validity.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Validity {
    /// Largest δ_max / R the law holds at.
    pub compression_over_radius: f64,
    /// That limit as written (`R/2`, `R`).
    pub limit: &'static str,
    /// Why the law holds up to there, and not beyond.
    pub why: &'static str,
    /// What else the law assumes; stated, not checked.
    pub assumes: &'static str,
}

/// The paper's Section 18, shared by the laws of the paper's family.
const LUMPED: &str = "one compliance coordinate lumping ball and foot, central impact, constant parameters, \
                      no wave propagation or internal air dynamics (the paper's Section 18)";
const BEYOND_RADIUS: &str = "beyond R the ball's centre would cross the contact surface: no contact is left to describe";

impl LawKind {
    /// Where the law holds (module docs).
    pub const fn validity(self) -> Validity {
        const fn lumped(assumes: &'static str) -> Validity {
            Validity { compression_over_radius: 1.0, limit: "R", why: BEYOND_RADIUS, assumes }
        }
        match self {
            LawKind::Shell => Validity {
                compression_over_radius: 0.5,
                limit: "R/2",
                why: "the gas law over a flat patch holds while the patch is small against the ball; deeper, a real \
                      ball's shell buckles",
                assumes: "a flat rigid counter-surface (the instep's curvature enters through kick-3d's patch), uniform \
                          gauge pressure over the patch, adiabatic gas, a thin shell whose bending is the linear k_s",
            },
            LawKind::PowerLaw => lumped(LUMPED),
            LawKind::HuntCrossley | LawKind::LankaraniNikravesh => lumped(
                "the paper's family's lumped compliance; the damping factor χ from the target restitution is first order \
                 in χ V0, exact only as e → 1 (paper/laws.md measures the miss)",
            ),
            LawKind::Flores => lumped("the paper's family's lumped compliance; χ from Flores et al.'s formula for any e"),
            LawKind::HuntCrossleyExact => {
                lumped("the paper's family's lumped compliance; χ meets the target restitution exactly at the reference speed")
            }
            LawKind::KelvinVoigt => lumped(
                "the paper's family's lumped compliance with a linear spring; the clamped dashpot makes e differ from its \
                 target",
            ),
        }
    }
}

/// A result computed outside its law's region of validity: what went too
/// deep, and where the law stops.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, thiserror::Error)]
#[error(
    "outside the validity of law `{law}`: δ_max = {} m exceeds {limit} = {} m ({why}); the numbers are the law's, not a ball's",
    short(*.max_compression),
    short(*.largest)
)]
pub struct OutsideValidity {
    pub law: &'static str,
    /// δ_max reached, m.
    pub max_compression: f64,
    /// The limit as written (`R/2`).
    pub limit: &'static str,
    /// Its value, m.
    pub largest: f64,
    pub why: &'static str,
}

/// The verdict on a contact under law `law` with a ball of radius `radius`
/// that reached `max_compression`: within the law's validity, or not.
pub fn check(law: LawKind, radius: f64, max_compression: f64) -> Result<(), OutsideValidity> {
    let v = law.validity();
    let largest = v.compression_over_radius * radius;
    if max_compression <= largest {
        return Ok(());
    }
    Err(OutsideValidity { law: law.name(), max_compression, limit: v.limit, largest, why: v.why })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every selectable law states a region; the shell's is R/2 (its module
    /// docs), the others' R; the verdict changes exactly at the limit.
    #[test]
    fn every_law_states_where_it_holds() {
        for law in LawKind::SELECTABLE {
            let v = law.validity();
            let expected = if law == LawKind::Shell { 0.5 } else { 1.0 };
            assert_eq!(v.compression_over_radius, expected, "{law:?}");
            assert!(!v.why.is_empty() && !v.assumes.is_empty(), "{law:?}");
            assert_eq!(check(law, 0.11, expected * 0.11), Ok(()));
            let outside = check(law, 0.11, (expected * 0.11f64).next_up()).unwrap_err();
            assert_eq!((outside.law, outside.largest), (law.name(), expected * 0.11));
        }
        let text = check(LawKind::Shell, 0.11, 0.1136).unwrap_err().to_string();
        assert!(text.contains("law `shell`") && text.contains("0.1136 m exceeds R/2 = 0.055 m"), "{text}");
    }
}
