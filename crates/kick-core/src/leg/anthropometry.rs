//! Segment parameters of the leg from de Leva (1996).
//!
//! de Leva, P. (1996). Adjustments to Zatsiorsky–Seluyanov's segment inertia
//! parameters. Journal of Biomechanics 29(9), 1223–1230. Table 4, male
//! values: segment mass as a fraction of body mass, centre-of-mass position
//! and radii of gyration as fractions of the segment length, and segment
//! lengths of the reference subject (stature 1.741 m, body mass 73.0 kg).
//!
//! Segment endpoints in the table: thigh hip joint centre → knee joint
//! centre; shank knee joint centre → lateral malleolus; foot heel → tip of
//! the longest toe. Lengths are scaled with stature (lengthᵢ · H / 1.741 m),
//! masses with body mass.
//!
//! Which radius belongs to which axis: the table's "sagittal" column is used
//! for rotation about the mediolateral axis (flexion–extension, the only one
//! the planar model needs), "transverse" for the anteroposterior axis and
//! "longitudinal" for the segment's long axis. For thigh and shank the two
//! transverse radii differ by at most 0.006 of the length, so the assignment
//! matters little.

use super::LegError;

/// One row of de Leva's Table 4 (male).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SegmentRow {
    pub name: &'static str,
    /// Reference segment length, m (stature 1.741 m).
    pub length: f64,
    /// Mass / body mass.
    pub mass_fraction: f64,
    /// Distance of the centre of mass from the proximal endpoint / length.
    pub centre_fraction: f64,
    /// Radii of gyration / length: sagittal, transverse, longitudinal.
    pub radius_sagittal: f64,
    pub radius_transverse: f64,
    pub radius_longitudinal: f64,
}

/// Stature of de Leva's male reference subject, m.
pub const DE_LEVA_STATURE: f64 = 1.741;
/// Body mass of de Leva's male reference subject, kg.
pub const DE_LEVA_BODY_MASS: f64 = 73.0;

/// Thigh, shank and foot, de Leva (1996) Table 4, males.
pub const DE_LEVA_MALE: [SegmentRow; 3] = [
    SegmentRow {
        name: "thigh",
        length: 0.4222,
        mass_fraction: 0.1416,
        centre_fraction: 0.4095,
        radius_sagittal: 0.329,
        radius_transverse: 0.329,
        radius_longitudinal: 0.149,
    },
    SegmentRow {
        name: "shank",
        length: 0.4340,
        mass_fraction: 0.0433,
        centre_fraction: 0.4459,
        radius_sagittal: 0.255,
        radius_transverse: 0.249,
        radius_longitudinal: 0.103,
    },
    SegmentRow {
        name: "foot",
        length: 0.2581,
        mass_fraction: 0.0137,
        centre_fraction: 0.4415,
        radius_sagittal: 0.257,
        radius_transverse: 0.245,
        radius_longitudinal: 0.124,
    },
];

/// A segment of a particular subject, SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    pub mass: f64,
    pub length: f64,
    /// Distance of the centre of mass from the proximal end along the long axis.
    pub centre: f64,
    /// Moments of inertia about the centre of mass, kg m²: mediolateral
    /// (flexion) axis, anteroposterior axis, long axis.
    pub inertia_flexion: f64,
    pub inertia_abduction: f64,
    pub inertia_long: f64,
}

impl Segment {
    pub fn from_row(row: &SegmentRow, body_mass: f64, stature: f64) -> Segment {
        let mass = row.mass_fraction * body_mass;
        let length = row.length * stature / DE_LEVA_STATURE;
        let inertia = |r: f64| mass * (r * length).powi(2);
        Segment {
            mass,
            length,
            centre: row.centre_fraction * length,
            inertia_flexion: inertia(row.radius_sagittal),
            inertia_abduction: inertia(row.radius_transverse),
            inertia_long: inertia(row.radius_longitudinal),
        }
    }
}

/// Thigh, shank and foot of one subject.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Anthropometry {
    pub thigh: Segment,
    pub shank: Segment,
    pub foot: Segment,
}

impl Anthropometry {
    /// de Leva's male table scaled to `body_mass` (kg) and `stature` (m).
    pub fn de_leva_male(body_mass: f64, stature: f64) -> Result<Anthropometry, LegError> {
        // Bounds wide enough for any adult, narrow enough to catch unit slips
        // (grams, centimetres).
        super::check_range("body_mass", body_mass, 20.0, 250.0, "kg")?;
        super::check_range("height", stature, 1.0, 2.5, "m")?;
        let [thigh, shank, foot] = DE_LEVA_MALE.map(|row| Segment::from_row(&row, body_mass, stature));
        Ok(Anthropometry { thigh, shank, foot })
    }

    /// The reference subject of the table (73 kg, 1.741 m).
    pub fn reference() -> Anthropometry {
        let [thigh, shank, foot] = DE_LEVA_MALE.map(|row| Segment::from_row(&row, DE_LEVA_BODY_MASS, DE_LEVA_STATURE));
        Anthropometry { thigh, shank, foot }
    }

    pub fn total_mass(&self) -> f64 {
        self.thigh.mass + self.shank.mass + self.foot.mass
    }
}
