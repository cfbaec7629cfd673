//! Contact laws: a force F(δ, δ̇) and an elastic potential U(δ).

/// A constitutive law for the normal contact force.
///
/// `force` follows Eq. 20's convention: zero when `compression <= 0`.
pub trait ContactLaw {
    /// Compressive force F(δ, δ̇) in N (Eq. 20).
    fn force(&self, compression: f64, compression_rate: f64) -> f64;
    /// Elastic potential U(δ) in J (Eq. 22).
    fn potential(&self, compression: f64) -> f64;

    /// Force on the contact branch, continuous from the right at δ = 0.
    /// Integrators use it while contact is known to hold, so that the damping
    /// jump at first touch is not lost at the initial point.
    fn contact_force(&self, compression: f64, compression_rate: f64) -> f64 {
        self.force(compression.max(f64::MIN_POSITIVE), compression_rate)
    }
    /// Force at the instant of contact: lim δ→0⁺ F(δ, V0).
    fn onset_force(&self, approach_speed: f64) -> f64 {
        self.contact_force(0.0, approach_speed)
    }
    /// (elastic part F(δ, 0), total F(δ, δ̇)) on the contact branch; laws
    /// override it to share the costly power between the two.
    fn elastic_and_contact_force(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        let elastic = if compression > 0.0 { self.force(compression, 0.0) } else { 0.0 };
        (elastic, self.contact_force(compression, compression_rate))
    }
    /// Partial derivatives (∂F/∂δ, ∂F/∂δ̇) on the contact branch, used to
    /// locate the force peak dF/dt = ∂F/∂δ δ̇ + ∂F/∂δ̇ δ̈ = 0.
    /// The default uses central differences; laws should override it.
    fn force_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        let hd = 1e-7 * compression.abs().max(1e-9);
        let hr = 1e-7 * compression_rate.abs().max(1e-9);
        let d_delta = (self.contact_force(compression + hd, compression_rate)
            - self.contact_force((compression - hd).max(0.0), compression_rate))
            / (compression + hd - (compression - hd).max(0.0));
        let d_rate =
            (self.contact_force(compression, compression_rate + hr) - self.contact_force(compression, compression_rate - hr)) / (2.0 * hr);
        (d_delta, d_rate)
    }
    /// (F, ∂F/∂δ, ∂F/∂δ̇) on the contact branch in one call.
    fn force_and_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64, f64) {
        let (d_delta, d_rate) = self.force_gradient(compression, compression_rate);
        (self.contact_force(compression, compression_rate), d_delta, d_rate)
    }
    /// (elastic, total) force on one side of the compression/restitution
    /// switch, continued smoothly past δ̇ = 0. Integrators use it inside a
    /// phase, so no step straddles the kink of a law like Eq. 20's max(δ̇, 0).
    fn branch_force(&self, compression: f64, compression_rate: f64, _compressing: bool) -> (f64, f64) {
        self.elastic_and_contact_force(compression, compression_rate)
    }
    /// (F, ∂F/∂δ, ∂F/∂δ̇) on one side of the switch (see `branch_force`).
    fn branch_force_and_gradient(&self, compression: f64, compression_rate: f64, _compressing: bool) -> (f64, f64, f64) {
        self.force_and_gradient(compression, compression_rate)
    }
    /// (elastic part, force before any clamp at zero) on the contact branch:
    /// a law that would pull (Kelvin–Voigt, a hysteresis law at 1 + χ δ̇ < 0)
    /// is clamped to F = 0 where this is negative. Integrators that treat
    /// the clamp as a switch continue the law smoothly with it.
    fn unclamped_force(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        self.elastic_and_contact_force(compression, compression_rate)
    }
    /// (E, D) with F(δ, δ̇) = E + D δ̇ on one side of the switch, before any
    /// clamp: every law here is affine in the rate there. A layer in series
    /// (kick-core's `boot`) solves its force balance with it in closed form.
    /// One evaluation: the branch force at δ̇ = 1.
    #[inline]
    fn rate_affine(&self, compression: f64, compressing: bool) -> (f64, f64) {
        let (elastic, total) = self.branch_force(compression, 1.0, compressing);
        (elastic, total - elastic)
    }
    /// True when the law dissipates only while compressing (δ̇ > 0), so the
    /// restitution phase of a passive run is conservative.
    fn damps_compression_only(&self) -> bool {
        false
    }
}

/// The paper's law (Eq. 20): F = k δⁿ + c max(δ̇, 0) for δ > 0, else 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerLawContact {
    /// k, in N/mⁿ ("model units", Table 1).
    pub stiffness: f64,
    /// c, in N s/m.
    pub damping: f64,
    /// n, dimensionless.
    pub exponent: f64,
}

impl PowerLawContact {
    /// Elastic part k δⁿ (Eq. 21); zero for δ ≤ 0.
    #[inline]
    pub fn elastic_force(&self, compression: f64) -> f64 {
        if compression > 0.0 {
            self.stiffness * compression.powf(self.exponent)
        } else {
            0.0
        }
    }
    /// Compression at which the elastic potential equals `energy` (inverse of Eq. 23).
    #[inline]
    pub fn compression_for_energy(&self, energy: f64) -> f64 {
        ((self.exponent + 1.0) * energy / self.stiffness).powf(1.0 / (self.exponent + 1.0))
    }
}

impl ContactLaw for PowerLawContact {
    #[inline]
    fn force(&self, compression: f64, compression_rate: f64) -> f64 {
        if compression > 0.0 {
            // Eq. 20
            self.elastic_force(compression) + self.damping * compression_rate.max(0.0)
        } else {
            0.0
        }
    }
    #[inline]
    fn potential(&self, compression: f64) -> f64 {
        // Eq. 23
        let d = compression.max(0.0);
        self.stiffness * d.powf(self.exponent + 1.0) / (self.exponent + 1.0)
    }
    #[inline]
    fn contact_force(&self, compression: f64, compression_rate: f64) -> f64 {
        self.elastic_force(compression) + self.damping * compression_rate.max(0.0)
    }
    #[inline]
    fn elastic_and_contact_force(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        let elastic = self.elastic_force(compression);
        (elastic, elastic + self.damping * compression_rate.max(0.0))
    }
    #[inline]
    fn force_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        let d = compression.max(0.0);
        let stiffness = if d > 0.0 {
            self.exponent * self.stiffness * d.powf(self.exponent - 1.0)
        } else if self.exponent > 1.0 {
            0.0
        } else if self.exponent == 1.0 {
            self.stiffness
        } else {
            f64::INFINITY
        };
        let damping = if compression_rate > 0.0 { self.damping } else { 0.0 };
        (stiffness, damping)
    }
    #[inline]
    fn force_and_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64, f64) {
        if compression > 0.0 && self.exponent > 1.0 {
            // One power for both: k δⁿ and n k δⁿ⁻¹ = n (k δⁿ)/δ.
            let elastic = self.elastic_force(compression);
            let damping = if compression_rate > 0.0 { self.damping } else { 0.0 };
            (elastic + damping * compression_rate, self.exponent * elastic / compression, damping)
        } else {
            let (d_delta, d_rate) = self.force_gradient(compression, compression_rate);
            (self.contact_force(compression, compression_rate), d_delta, d_rate)
        }
    }
    #[inline]
    fn branch_force(&self, compression: f64, compression_rate: f64, compressing: bool) -> (f64, f64) {
        let elastic = self.elastic_force(compression);
        let damping = if compressing { self.damping * compression_rate } else { 0.0 };
        (elastic, elastic + damping)
    }
    #[inline]
    fn branch_force_and_gradient(&self, compression: f64, compression_rate: f64, compressing: bool) -> (f64, f64, f64) {
        let elastic = self.elastic_force(compression);
        let stiffness = if compression > 0.0 && self.exponent > 1.0 {
            self.exponent * elastic / compression
        } else {
            self.force_gradient(compression, 1.0).0
        };
        let damping = if compressing { self.damping } else { 0.0 };
        (elastic + damping * compression_rate, stiffness, damping)
    }
    fn damps_compression_only(&self) -> bool {
        true
    }
}
