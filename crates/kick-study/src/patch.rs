//! The contact patch against the point contact (issue 22, item 8): spin
//! against offset for the shell ball's point contact and its patch on a cap,
//! beside Asai et al. (2002), and the one off-center kick whose patch the 3D
//! page follows over time. What is solved and what it is compared with;
//! kick-store writes it (`kick_store::patch`), kick-paper draws it.

use crate::error::StudyError;
use kick_3d::{Kick3d, Kick3dError, Kick3dSpec, KickSpec};
use kick_core::measurements::Measurements;
use kick_core::{short, LawKind, Scenario};

/// The cap's radius of curvature, m: an assumption (no published instep
/// curvature was found, `kick_3d::patch`), of the order of the ball's
/// radius and at least the face's half-extents, as the instep requires.
pub const CAP_RADIUS: f64 = kick_3d::validation::ASSUMED_INSTEP_RADIUS;
/// Friction coefficients of the curves (Asai et al. compare 0 and 1).
pub const FRICTIONS: [f64; 3] = [0.0, 0.5, 1.0];
/// Offsets: 0 to 110 mm (the ball's radius) in 5 mm steps.
pub const OFFSET_STEP: f64 = 0.005;
pub const OFFSETS: usize = 23;
/// The history's kick: 5 cm off the swing line, μ = 0.5, patch on the cap.
pub const HISTORY_OFFSET: f64 = 0.05;
pub const HISTORY_FRICTION: f64 = 0.5;
/// Rows of the history: grip/slip shaded to 1/2000 of the contact.
pub const HISTORY_SAMPLES: usize = 2001;

/// One contact model of the spin figure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// Its group below `/curves`.
    pub key: &'static str,
    pub label: &'static str,
    pub patch: bool,
    /// r_i, m (None: the flat face).
    pub instep_radius: Option<f64>,
    /// ψ, degrees (None: asin(e/R), the knife edge).
    pub face_yaw_deg: Option<f64>,
}

/// The level below (the rigid sphere's point contact on the knife-edge
/// face, with the shell ball's law) and the patch on a cap square to the swing.
pub const CONTACTS: [Contact; 2] = [
    Contact { key: "point", label: "point contact (knife edge)", patch: false, instep_radius: None, face_yaw_deg: None },
    Contact { key: "patch_cap", label: "patch on a cap", patch: true, instep_radius: Some(CAP_RADIUS), face_yaw_deg: Some(0.0) },
];

/// The shell ball (FIFA-calibrated defaults) on Table 1's foot.
pub fn shell() -> Result<Scenario, StudyError> {
    Ok(Scenario::baseline().with_law(LawKind::Shell, None)?)
}

impl Contact {
    /// The kick's spec at offset `e`, friction `mu`.
    pub fn spec(&self, offset: f64, friction: f64) -> Kick3dSpec {
        Kick3dSpec {
            offset: Some(offset),
            friction: Some(friction),
            patch_contact: self.patch.then_some(true),
            instep_radius: self.instep_radius,
            face_yaw_deg: self.face_yaw_deg,
            ..Kick3dSpec::default()
        }
    }
    /// What the contact is, in words (the file's `contact` attribute).
    pub fn description(&self) -> String {
        match (self.patch, self.instep_radius) {
            (true, Some(r)) => format!(
                "normal force spread over the patch, instep a sphere cap of radius {} m (an assumption) square to the swing (face_yaw 0)",
                short(r)
            ),
            (true, None) => "normal force spread over the patch on the flat knife-edge face".into(),
            (false, _) => {
                "point contact (rigid sphere: the normal force through the centre), flat face tilted by asin(e/R) (knife edge)".into()
            }
        }
    }
}

/// The offsets asked for, m.
pub fn offsets() -> Vec<f64> {
    (0..OFFSETS).map(|i| OFFSET_STEP * i as f64).collect()
}

/// One curve: the kicks of one contact model and friction that were solved.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Index into [`CONTACTS`].
    pub contact: usize,
    pub friction: f64,
    pub offset: Vec<f64>,
    /// ω_z, rad/s (z up).
    pub spin_z: Vec<f64>,
    /// |ω|, rad/s.
    pub spin: Vec<f64>,
    pub speed: Vec<f64>,
    /// deg.
    pub launch_azimuth: Vec<f64>,
    pub contact_time: Vec<f64>,
    /// Offsets left out and why.
    pub refused: Vec<(f64, String)>,
}

/// The spin file's content.
#[derive(Debug, Clone, PartialEq)]
pub struct SpinData {
    pub offsets: Vec<f64>,
    pub curves: Vec<Curve>,
}

fn solve(base: Scenario, contact: &Contact, offset: f64, friction: f64) -> Result<kick_3d::Outcome3d, Kick3dError> {
    kick_3d::Accurate3d::default().solve(&Kick3d::new(base, &contact.spec(offset, friction))?)
}

/// Every kick of the figure, solved (accurate path); a refused kick is
/// left out of its curve with its reason. A numerical failure is an error.
pub fn compute() -> Result<SpinData, StudyError> {
    let offsets = offsets();
    let base = shell()?;
    let mut curves = Vec::new();
    for (c, contact) in CONTACTS.iter().enumerate() {
        for &friction in &FRICTIONS {
            let mut curve = Curve {
                contact: c,
                friction,
                offset: Vec::new(),
                spin_z: Vec::new(),
                spin: Vec::new(),
                speed: Vec::new(),
                launch_azimuth: Vec::new(),
                contact_time: Vec::new(),
                refused: Vec::new(),
            };
            for &e in &offsets {
                match solve(base, contact, e, friction) {
                    Ok(o) => {
                        let [x, y, z] = o.spin;
                        curve.offset.push(e);
                        curve.spin_z.push(z);
                        curve.spin.push((x * x + y * y + z * z).sqrt());
                        curve.speed.push(o.speed);
                        curve.launch_azimuth.push(o.launch_azimuth);
                        curve.contact_time.push(o.contact_time);
                    }
                    Err(err) if err.status() == kick_core::Status::Refused => curve.refused.push((e, err.to_string())),
                    Err(source) => {
                        return Err(StudyError::Kick3dRow { name: format!("{}, e = {e} m, μ = {friction}", contact.label), source })
                    }
                }
            }
            curves.push(curve);
        }
    }
    Ok(SpinData { offsets, curves })
}

impl SpinData {
    /// The curve of contact `c` at friction `mu`.
    pub fn curve(&self, contact: usize, friction: f64) -> Option<&Curve> {
        self.curves.iter().find(|k| k.contact == contact && k.friction == friction)
    }

    /// The sign of ω_z that friction gives (+1 or −1): that of the point
    /// contact's spin at the largest friction, where all of it is friction's.
    pub fn friction_sense(&self) -> f64 {
        let mu = FRICTIONS[FRICTIONS.len() - 1];
        let sum: f64 = self.curve(0, mu).map_or(0.0, |k| k.spin_z.iter().sum());
        if sum < 0.0 {
            -1.0
        } else {
            1.0
        }
    }
}

impl Curve {
    /// Sidespin in friction's sense, s ω_z (s = [`SpinData::friction_sense`]).
    pub fn sidespin(&self, sense: f64) -> Vec<f64> {
        self.spin_z.iter().map(|w| sense * w).collect()
    }

    /// The solved offset of the largest sidespin and that spin (on the grid).
    pub fn largest(&self, sense: f64) -> Option<(f64, f64)> {
        let s = self.sidespin(sense);
        (0..s.len()).max_by(|&a, &b| s[a].total_cmp(&s[b])).map(|i| (self.offset[i], s[i]))
    }

    /// The sidespin at offset `e`, if it was solved.
    pub fn at(&self, e: f64, sense: f64) -> Option<f64> {
        self.offset.iter().position(|&x| x == e).map(|i| sense * self.spin_z[i])
    }
}

/// Sidespin added by friction 0 → 1 for contact `c` at each offset solved
/// on both curves: (offsets, gains), friction's sense.
pub fn friction_gain(data: &SpinData, contact: usize) -> (Vec<f64>, Vec<f64>) {
    let sense = data.friction_sense();
    let (Some(zero), Some(one)) = (data.curve(contact, 0.0), data.curve(contact, 1.0)) else { return (Vec::new(), Vec::new()) };
    one.offset.iter().filter_map(|&e| Some((e, one.at(e, sense)? - zero.at(e, sense)?))).unzip()
}

/// Asai et al.'s (2002) abstract, as published in the measurement file:
/// the largest gain from friction 0 → 1 (rad/s) and the offset of largest spin (m).
#[derive(Debug, Clone, PartialEq)]
pub struct AsaiClaims {
    pub friction_gain: f64,
    pub peak_offset: f64,
    /// The measurement file and keys they were read from.
    pub source: String,
}

/// Asai et al.'s claims from the measurements (kick-store reads the file).
pub fn asai_claims(m: &Measurements) -> Result<AsaiClaims, StudyError> {
    use kick_3d::validation::keys;
    let needed = "the patch spin figure (kick_study::patch)";
    let gain = m.measured(keys::FRICTION_GAIN, needed)?;
    let peak = m.measured(keys::PEAK_OFFSET, needed)?;
    let lacks = |key: &str, what: &str| StudyError::File { path: m.file.clone().into(), message: format!("{key}: no {what}") };
    let friction_gain = gain.high.ok_or_else(|| lacks(keys::FRICTION_GAIN, "upper bound"))?;
    let peak_offset = peak.midpoint().ok_or_else(|| lacks(keys::PEAK_OFFSET, "value"))?;
    let source = format!("{}: {}, {}", m.file, keys::FRICTION_GAIN, keys::PEAK_OFFSET);
    Ok(AsaiClaims { friction_gain, peak_offset, source })
}

/// The history's kick as a spec.
pub fn history_spec() -> KickSpec {
    let mut spec = KickSpec::default();
    spec.scenario.law = Some(LawKind::Shell);
    spec.kick3d = CONTACTS[1].spec(HISTORY_OFFSET, HISTORY_FRICTION);
    spec
}

/// The parameters every kick of the spin figure shares, offset and friction
/// aside: (name, unit, values) of those equal in both contacts' kicks.
pub fn shared_fixed() -> Result<Vec<(String, String, Vec<f64>)>, StudyError> {
    let base = shell()?;
    let metas: Vec<_> = CONTACTS
        .iter()
        .map(|c| Kick3d::new(base, &c.spec(HISTORY_OFFSET, HISTORY_FRICTION)).map(|k| crate::simulate::meta_3d(&k).fixed))
        .collect::<Result<_, _>>()?;
    let mut shared = Vec::new();
    for (name, unit, values) in &metas[0] {
        let everywhere = metas[1..].iter().all(|m| m.iter().any(|(n, _, v)| n == name && v == values));
        if everywhere && name != "offset" && name != "friction" {
            shared.push((name.to_string(), unit.to_string(), values.clone()));
        }
    }
    Ok(shared)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curve(contact: usize, friction: f64, offset: &[f64], spin_z: &[f64]) -> Curve {
        let n = offset.len();
        Curve {
            contact,
            friction,
            offset: offset.to_vec(),
            spin_z: spin_z.to_vec(),
            spin: spin_z.iter().map(|w| w.abs()).collect(),
            speed: vec![20.0; n],
            launch_azimuth: vec![0.0; n],
            contact_time: vec![0.008; n],
            refused: Vec::new(),
        }
    }

    /// What the figure and page compute, on curves made up by hand:
    /// friction's sense is the point contact's sign at μ = 1, the largest
    /// sidespin and its offset, and the gain μ 0 → 1 only where both solved.
    #[test]
    fn sidespin_largest_and_gain_by_hand() {
        let e = [0.0, 0.01, 0.02, 0.03];
        let data = SpinData {
            offsets: e.to_vec(),
            curves: vec![
                curve(0, 0.0, &e, &[0.0, 0.0, 0.0, 0.0]),
                curve(0, 1.0, &e, &[0.0, -3.0, -7.0, -5.0]),
                // The patch: μ = 0 spins against friction; μ = 1 misses 0.02.
                curve(1, 0.0, &e, &[0.0, 1.0, 2.0, 4.0]),
                curve(1, 1.0, &[0.0, 0.01, 0.03], &[0.0, -2.0, -6.0]),
            ],
        };
        let s = data.friction_sense();
        assert_eq!(s, -1.0);
        assert_eq!(data.curves[1].largest(s), Some((0.02, 7.0)));
        assert_eq!(data.curves[2].largest(s), Some((0.0, 0.0)));
        assert_eq!(data.curves[3].largest(s), Some((0.03, 6.0)));
        // Gains: (2 − (−1)) at 0.01 and (6 − (−4)) at 0.03; 0.02 left out.
        assert_eq!(friction_gain(&data, 1), (vec![0.0, 0.01, 0.03], vec![0.0, 3.0, 10.0]));
        assert_eq!(friction_gain(&data, 0), (e.to_vec(), vec![0.0, 3.0, 7.0, 5.0]));
    }
}
