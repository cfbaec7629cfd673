//! A serial chain of rigid bodies and the effective mass of a point on its
//! last body along a direction (Eq. 11).
//!
//! The chain is described at one configuration by its motion subspace: each
//! joint contributes a twist (a rotation axis through a point, or a
//! translation direction) that moves every body from `first_body` on. The
//! effective mass m_eff = (nᵀ J M⁻¹ Jᵀ n)⁻¹ does not depend on how the
//! generalized velocities are parametrised (q̇ = T u leaves J M⁻¹ Jᵀ
//! unchanged), so joint axes may be given in world coordinates at the current
//! pose; no joint-angle derivatives are needed.

use super::LegError;
use nalgebra::{DMatrix, DVector, Matrix3, Matrix6, Vector3};

/// A rigid body at the current pose, world coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    pub mass: f64,
    /// Centre of mass.
    pub centre: Vector3<f64>,
    /// Inertia tensor about the centre of mass, world axes.
    pub inertia: Matrix3<f64>,
}

/// One degree of freedom at the current pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Motion {
    /// Rotation about a unit `axis` through `point`.
    Revolute { axis: Vector3<f64>, point: Vector3<f64> },
    /// Translation along a unit direction.
    Prismatic { direction: Vector3<f64> },
}

impl Motion {
    /// (angular, linear velocity of the material point at `x`) per unit rate.
    fn twist_at(&self, x: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        match *self {
            Motion::Revolute { axis, point } => (axis, axis.cross(&(x - point))),
            Motion::Prismatic { direction } => (Vector3::zeros(), direction),
        }
    }
}

/// A joint degree of freedom that moves bodies `first_body..` of the chain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Joint {
    pub motion: Motion,
    pub first_body: usize,
}

/// A serial chain at one pose.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Chain {
    pub bodies: Vec<Body>,
    pub joints: Vec<Joint>,
}

impl Chain {
    /// Linear-velocity Jacobian (3 × dof) of the material point `x` of body `body`.
    pub fn point_jacobian(&self, body: usize, x: &Vector3<f64>) -> DMatrix<f64> {
        let mut j = DMatrix::zeros(3, self.joints.len());
        for (col, joint) in self.joints.iter().enumerate() {
            if joint.first_body <= body {
                let (_, v) = joint.motion.twist_at(x);
                j.fixed_view_mut::<3, 1>(0, col).copy_from(&v);
            }
        }
        j
    }

    fn angular_jacobian(&self, body: usize) -> DMatrix<f64> {
        let mut j = DMatrix::zeros(3, self.joints.len());
        for (col, joint) in self.joints.iter().enumerate() {
            if joint.first_body <= body {
                let (w, _) = joint.motion.twist_at(&Vector3::zeros());
                j.fixed_view_mut::<3, 1>(0, col).copy_from(&w);
            }
        }
        j
    }

    /// Generalized mass matrix M = Σ mᵢ J_vᵢᵀ J_vᵢ + J_ωᵢᵀ Iᵢ J_ωᵢ (kinetic energy ½ q̇ᵀ M q̇).
    pub fn mass_matrix(&self) -> DMatrix<f64> {
        let n = self.joints.len();
        let mut m = DMatrix::zeros(n, n);
        for (i, body) in self.bodies.iter().enumerate() {
            let jv = self.point_jacobian(i, &body.centre);
            let jw = self.angular_jacobian(i);
            let inertia = DMatrix::from_column_slice(3, 3, body.inertia.as_slice());
            m += jv.transpose() * &jv * body.mass + jw.transpose() * inertia * &jw;
        }
        m
    }

    /// Mobility nᵀ J M⁻¹ Jᵀ n of the point `x` on the last body along `n`
    /// (velocity per unit impulse, 1/kg).
    pub fn mobility(&self, x: &Vector3<f64>, direction: &Vector3<f64>) -> Result<f64, LegError> {
        let Some(last) = self.bodies.len().checked_sub(1) else {
            return Err(LegError::Degenerate("the chain has no bodies".into()));
        };
        let norm = direction.norm();
        if !(norm.is_finite() && norm > 0.0) {
            return Err(LegError::Degenerate("the impact direction has zero or non-finite length".into()));
        }
        let n = direction / norm;
        if self.joints.is_empty() {
            return Ok(0.0);
        }
        // Jᵀ n: generalized force of a unit impulse along n at x.
        let jtn: DVector<f64> = self.point_jacobian(last, x).transpose() * n;
        let cholesky = self
            .mass_matrix()
            .cholesky()
            .ok_or_else(|| LegError::Degenerate("the generalized mass matrix is not positive definite (a joint moves no mass)".into()))?;
        let y = cholesky.solve(&jtn);
        Ok(jtn.dot(&y))
    }

    /// The 6×6 mobility of the last body at its material point `x`: the
    /// twist [ω; v(x)] it takes per unit impulsive wrench [τ about x; F],
    /// Ω = J M⁻¹ Jᵀ with J = [J_ω; J_v(x)] (6 × dof). Eq. 11 is its
    /// projection nᵀ Ω_vv n; Ω is symmetric, positive semi-definite, of the
    /// rank of the chain's degrees of freedom (directions the chain cannot
    /// move in have zero mobility: infinite apparent inertia).
    pub fn spatial_mobility(&self, x: &Vector3<f64>) -> Result<Matrix6<f64>, LegError> {
        let Some(last) = self.bodies.len().checked_sub(1) else {
            return Err(LegError::Degenerate("the chain has no bodies".into()));
        };
        let dof = self.joints.len();
        let mut j = DMatrix::zeros(6, dof);
        j.rows_mut(0, 3).copy_from(&self.angular_jacobian(last));
        j.rows_mut(3, 3).copy_from(&self.point_jacobian(last, x));
        if dof == 0 {
            return Ok(Matrix6::zeros());
        }
        let cholesky = self
            .mass_matrix()
            .cholesky()
            .ok_or_else(|| LegError::Degenerate("the generalized mass matrix is not positive definite (a joint moves no mass)".into()))?;
        let solved = cholesky.solve(&j.transpose());
        let mobility = &j * solved;
        let mut out = Matrix6::zeros();
        for r in 0..6 {
            for c in 0..6 {
                // Symmetric by construction; average the rounding away.
                out[(r, c)] = 0.5 * (mobility[(r, c)] + mobility[(c, r)]);
            }
        }
        Ok(out)
    }

    /// m_eff = (nᵀ J M⁻¹ Jᵀ n)⁻¹ (Eq. 11), kg.
    pub fn effective_mass(&self, x: &Vector3<f64>, direction: &Vector3<f64>) -> Result<f64, LegError> {
        let mobility = self.mobility(x, direction)?;
        // A point that cannot move along n would need an infinite impulse to
        // change its velocity: refuse rather than return infinity.
        let scale: f64 = self.bodies.iter().map(|b| b.mass).sum();
        if !(mobility.is_finite() && mobility > 1e-12 / scale) {
            return Err(LegError::Degenerate(
                "the contact point cannot move along the impact direction: effective mass is unbounded".into(),
            ));
        }
        Ok(1.0 / mobility)
    }

    /// Total mass of the chain, kg.
    pub fn total_mass(&self) -> f64 {
        self.bodies.iter().map(|b| b.mass).sum()
    }
}
