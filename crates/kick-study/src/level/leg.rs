//! The articulated leg (kick-leg) as [`Level`]s: the effective mass at the
//! instep over a knee × ankle grid (Eq. 11; locked and free ankle), and the
//! 1D exit speed over an axis of effective foot masses (Section 14.1), each
//! row a pure function of its index.

use super::{Level, Row};
use crate::columns::{Column, OutcomeSet, Setting};
use kick_core::Scenario;
use kick_leg::{exit_outcome, AnkleJoint, Impact, Leg, LegError, Pose};

/// The leg's outcome set `name` with `columns`: how m_eff and the exit speed were computed.
fn leg_set(name: &str, columns: Vec<Column>) -> OutcomeSet {
    OutcomeSet {
        solver: name.into(),
        settings: vec![
            ("effective_mass".into(), Setting::Text("Eq. 11, de Leva (1996) segments".into())),
            ("exit_solver".into(), Setting::Text("accurate".into())),
        ],
        columns,
    }
}

fn failure(e: LegError) -> super::Failure {
    super::Failure::new(e.status(), e.to_string())
}

/// Effective mass and exit speed over knee flexion × ankle plantarflexion
/// (degrees, ankle fastest); sets `locked-ankle` and `free-ankle`.
#[derive(Debug, Clone, PartialEq)]
pub struct LegPoseGrid {
    pub leg: Leg,
    /// The pose whose knee and ankle angles the grid replaces.
    pub pose: Pose,
    pub impact: Impact,
    /// The 1D contact the exit speed is solved with (m_f = m_eff).
    pub base: Scenario,
    pub knees: Vec<f64>,
    pub ankles: Vec<f64>,
}

impl Level for LegPoseGrid {
    fn rows(&self) -> u64 {
        (self.knees.len() * self.ankles.len()) as u64
    }

    fn parameter_columns(&self) -> Vec<Column> {
        vec![Column::new("knee", "deg"), Column::new("ankle", "deg")]
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        let m_and_v = || vec![Column::new("effective_mass", "kg"), Column::new("v_ball_out", "m/s")];
        vec![leg_set("locked-ankle", m_and_v()), leg_set("free-ankle", m_and_v())]
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        let mut position = [0usize; 2];
        crate::grid::decode([self.knees.len(), self.ankles.len()].into_iter(), index, |k, p| position[k] = p);
        let (knee, ankle) = (self.knees[position[0]], self.ankles[position[1]]);
        row.parameters.copy_from_slice(&[knee, ankle]);
        let pose = Pose { knee_flexion: knee, plantarflexion: ankle, ..self.pose };
        for (set, joint) in [AnkleJoint::Locked, AnkleJoint::Free].into_iter().enumerate() {
            let values = self
                .leg
                .effective_mass(&pose, &self.impact, joint)
                .and_then(|m| Ok([m.effective_mass, exit_outcome(m.effective_mass, &self.base)?.v_ball_out]));
            match values {
                Ok(v) => row.set(set, &v),
                Err(e) => row.fail(set, failure(e)),
            }
        }
    }
}

/// The 1D exit speed over effective foot masses (kg), beside the perfectly
/// elastic bound (Eq. 38 with e = 1); set `accurate`.
#[derive(Debug, Clone, PartialEq)]
pub struct LegMassAxis {
    pub base: Scenario,
    pub masses: Vec<f64>,
}

impl Level for LegMassAxis {
    fn rows(&self) -> u64 {
        self.masses.len() as u64
    }

    fn parameter_columns(&self) -> Vec<Column> {
        vec![Column::new("foot_mass", "kg")]
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        vec![leg_set(
            "accurate",
            vec![
                Column::new("v_ball_out", "m/s"),
                Column::new("speed_ratio", "1"),
                // Eq. 38 with e = 1: the perfectly elastic bound.
                Column::new("elastic_bound_v_ball_out", "m/s"),
            ],
        )]
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        let m = self.masses[index as usize];
        row.parameters[0] = m;
        let bound = kick_restitution::speed_ratio_ball_at_rest(1.0, m, self.base.ball_mass()) * self.base.foot_speed();
        match exit_outcome(m, &self.base) {
            Ok(o) => row.set(0, &[o.v_ball_out, o.speed_ratio.unwrap_or(f64::NAN), bound]),
            Err(e) => row.fail(0, failure(e)),
        }
    }
}
