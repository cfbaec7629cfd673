//! Dormand–Prince 8(5,3) with its 7th-order dense output, stepping one
//! accepted step at a time so the caller can look for events between steps.
//!
//! Method, error estimate, step-size controller and dense output follow
//! Hairer's DOP853 (E. Hairer, S. P. Nørsett, G. Wanner, *Solving Ordinary
//! Differential Equations I*, 2nd ed., Springer 1993, Sec. II.10, and the
//! authors' `dop853.f`), with its default controller (safety 0.9, step ratio
//! in [1/3, 6], no PI term). The coefficients are the published ones.
//!
//! Why not `ode_solvers::Dop853`: it integrates to a fixed end and collects
//! every step into vectors; a flight (kick-flight) and a contact (kick-3d)
//! need to stop at located events, and their summary paths must not allocate. The dense output costs three more
//! right-hand sides per step, so it is formed only for the steps that ask.

// The published coefficients keep all their digits.
#![allow(clippy::excessive_precision)]

use nalgebra::SVector;

/// A system y' = f(x, y) (x: the independent variable, usually time).
pub trait System<const N: usize> {
    fn derivative(&self, x: f64, y: &SVector<f64, N>) -> SVector<f64, N>;
    /// The derivative at an accepted step's end (k13, the next step's k1):
    /// the same value as [`System::derivative`]; a system that keeps what it
    /// computed there for its caller does it here, once per accepted step,
    /// instead of on every evaluation.
    #[inline(always)]
    fn derivative_at_step_end(&self, x: f64, y: &SVector<f64, N>) -> SVector<f64, N> {
        self.derivative(x, y)
    }
    /// How many components the error norm averages over: all N, unless a
    /// system carries components it leaves at zero (kick-3d's state keeps
    /// slots for a leg and a boot): those add nothing to the sum, and
    /// averaging over the others keeps a kick without them bit for bit.
    fn counted_components(&self) -> usize {
        N
    }
}

/// Why stepping stopped short.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepFailure {
    /// The step size fell below what the time can resolve.
    StepSizeUnderflow { time: f64 },
    /// Many rejections in a row: the right-hand side is not finite or not smooth.
    Rejections { time: f64 },
}

/// Most rejected tries for one step before giving up.
pub const MAX_REJECTIONS: u32 = 100;

/// Nodes c_i.
const C: [f64; 16] = [
    0.0,
    0.526001519587677318785587544488E-01,
    0.789002279381515978178381316732E-01,
    0.118350341907227396726757197510E+00,
    0.281649658092772603273242802490E+00,
    0.333333333333333333333333333333E+00,
    0.25E+00,
    0.307692307692307692307692307692E+00,
    0.651282051282051282051282051282E+00,
    0.6E+00,
    0.857142857142857142857142857142E+00,
    1.0,
    1.0,
    0.1E+00,
    0.2E+00,
    0.777777777777777777777777777778E+00,
];

/// a_ij of stages 2..12 (row i−2), zero-padded to 11 columns.
const A: [[f64; 11]; 11] = [
    [5.26001519587677318785587544488E-2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [1.97250569845378994544595329183E-2, 5.91751709536136983633785987549E-2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [2.95875854768068491816892993775E-2, 0.0, 8.87627564304205475450678981324E-2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [
        2.41365134159266685502369798665E-1,
        0.0,
        -8.84549479328286085344864962717E-1,
        9.24834003261792003115737966543E-1,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        3.7037037037037037037037037037E-2,
        0.0,
        0.0,
        1.70828608729473871279604482173E-1,
        1.25467687566822425016691814123E-1,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        3.7109375E-2,
        0.0,
        0.0,
        1.70252211019544039314978060272E-1,
        6.02165389804559606850219397283E-2,
        -1.7578125E-2,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        3.70920001185047927108779319836E-2,
        0.0,
        0.0,
        1.70383925712239993810214054705E-1,
        1.07262030446373284651809199168E-1,
        -1.53194377486244017527936158236E-2,
        8.27378916381402288758473766002E-3,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        6.24110958716075717114429577812E-1,
        0.0,
        0.0,
        -3.36089262944694129406857109825E0,
        -8.68219346841726006818189891453E-1,
        2.75920996994467083049415600797E1,
        2.01540675504778934086186788979E1,
        -4.34898841810699588477366255144E1,
        0.0,
        0.0,
        0.0,
    ],
    [
        4.77662536438264365890433908527E-1,
        0.0,
        0.0,
        -2.48811461997166764192642586468E0,
        -5.90290826836842996371446475743E-1,
        2.12300514481811942347288949897E1,
        1.52792336328824235832596922938E1,
        -3.32882109689848629194453265587E1,
        -2.03312017085086261358222928593E-2,
        0.0,
        0.0,
    ],
    [
        -9.3714243008598732571704021658E-1,
        0.0,
        0.0,
        5.18637242884406370830023853209E0,
        1.09143734899672957818500254654E0,
        -8.14978701074692612513997267357E0,
        -1.85200656599969598641566180701E1,
        2.27394870993505042818970056734E1,
        2.49360555267965238987089396762E0,
        -3.0467644718982195003823669022E0,
        0.0,
    ],
    [
        2.27331014751653820792359768449E0,
        0.0,
        0.0,
        -1.05344954667372501984066689879E1,
        -2.00087205822486249909675718444E0,
        -1.79589318631187989172765950534E1,
        2.79488845294199600508499808837E1,
        -2.85899827713502369474065508674E0,
        -8.87285693353062954433549289258E0,
        1.23605671757943030647266201528E1,
        6.43392746015763530355970484046E-1,
    ],
];

/// Weights of the 8th-order solution over k1..k12.
const B: [f64; 12] = [
    5.42937341165687622380535766363E-2,
    0.0,
    0.0,
    0.0,
    0.0,
    4.45031289275240888144113950566E0,
    1.89151789931450038304281599044E0,
    -5.8012039600105847814672114227E0,
    3.1116436695781989440891606237E-1,
    -1.52160949662516078556178806805E-1,
    2.01365400804030348374776537501E-1,
    4.47106157277725905176885569043E-2,
];

/// 3rd-order error weights on k1, k9, k12.
const BHH: [f64; 3] = [0.244094488188976377952755905512E+00, 0.733846688281611857341361741547E+00, 0.220588235294117647058823529412E-01];

/// 5th-order error weights over k1..k12.
const E: [f64; 12] = [
    0.1312004499419488073250102996E-01,
    0.0,
    0.0,
    0.0,
    0.0,
    -0.1225156446376204440720569753E+01,
    -0.4957589496572501915214079952E+00,
    0.1664377182454986536961530415E+01,
    -0.3503288487499736816886487290E+00,
    0.3341791187130174790297318841E+00,
    0.8192320648511571246570742613E-01,
    -0.2235530786388629525884427845E-01,
];

/// Stages 14–16 of the dense output over k1..k15 (k13 = f at the new point).
const A14: [f64; 13] = [
    5.61675022830479523392909219681E-2,
    0.0,
    0.0,
    0.0,
    0.0,
    0.0,
    2.53500210216624811088794765333E-1,
    -2.46239037470802489917441475441E-1,
    -1.24191423263816360469010140626E-1,
    1.5329179827876569731206322685E-1,
    8.20105229563468988491666602057E-3,
    7.56789766054569976138603589584E-3,
    -8.298E-3,
];
const A15: [f64; 14] = [
    3.18346481635021405060768473261E-2,
    0.0,
    0.0,
    0.0,
    0.0,
    2.83009096723667755288322961402E-2,
    5.35419883074385676223797384372E-2,
    -5.49237485713909884646569340306E-2,
    0.0,
    0.0,
    -1.08347328697249322858509316994E-4,
    3.82571090835658412954920192323E-4,
    -3.40465008687404560802977114492E-4,
    1.41312443674632500278074618366E-1,
];
const A16: [f64; 15] = [
    -4.28896301583791923408573538692E-1,
    0.0,
    0.0,
    0.0,
    0.0,
    -4.69762141536116384314449447206E0,
    7.68342119606259904184240953878E0,
    4.06898981839711007970213554331E0,
    3.56727187455281109270669543021E-1,
    0.0,
    0.0,
    0.0,
    -1.39902416515901462129418009734E-3,
    2.9475147891527723389556272149E0,
    -9.15095847217987001081870187138E0,
];

/// d_ij of the dense output's coefficients 4..7 over k1..k16.
const D: [[f64; 16]; 4] = [
    [
        -0.84289382761090128651353491142E+01,
        0.0,
        0.0,
        0.0,
        0.0,
        0.56671495351937776962531783590E+00,
        -0.30689499459498916912797304727E+01,
        0.23846676565120698287728149680E+01,
        0.21170345824450282767155149946E+01,
        -0.87139158377797299206789907490E+00,
        0.22404374302607882758541771650E+01,
        0.63157877876946881815570249290E+00,
        -0.88990336451333310820698117400E-01,
        0.18148505520854727256656404962E+02,
        -0.91946323924783554000451984436E+01,
        -0.44360363875948939664310572000E+01,
    ],
    [
        0.10427508642579134603413151009E+02,
        0.0,
        0.0,
        0.0,
        0.0,
        0.24228349177525818288430175319E+03,
        0.16520045171727028198505394887E+03,
        -0.37454675472269020279518312152E+03,
        -0.22113666853125306036270938578E+02,
        0.77334326684722638389603898808E+01,
        -0.30674084731089398182061213626E+02,
        -0.93321305264302278729567221706E+01,
        0.15697238121770843886131091075E+02,
        -0.31139403219565177677282850411E+02,
        -0.93529243588444783865713862664E+01,
        0.35816841486394083752465898540E+02,
    ],
    [
        0.19985053242002433820987653617E+02,
        0.0,
        0.0,
        0.0,
        0.0,
        -0.38703730874935176555105901742E+03,
        -0.18917813819516756882830838328E+03,
        0.52780815920542364900561016686E+03,
        -0.11573902539959630126141871134E+02,
        0.68812326946963000169666922661E+01,
        -0.10006050966910838403183860980E+01,
        0.77771377980534432092869265740E+00,
        -0.27782057523535084065932004339E+01,
        -0.60196695231264120758267380846E+02,
        0.84320405506677161018159903784E+02,
        0.11992291136182789328035130030E+02,
    ],
    [
        -0.25693933462703749003312586129E+02,
        0.0,
        0.0,
        0.0,
        0.0,
        -0.15418974869023643374053993627E+03,
        -0.23152937917604549567536039109E+03,
        0.35763911791061412378285349910E+03,
        0.93405324183624310003907691704E+02,
        -0.37458323136451633156875139351E+02,
        0.10409964950896230045147246184E+03,
        0.29840293426660503123344363579E+02,
        -0.43533456590011143754432175058E+02,
        0.96324553959188282948394950600E+02,
        -0.39177261675615439165231486172E+02,
        -0.14972683625798562581422125276E+03,
    ],
];

const SAFETY: f64 = 0.9;
/// Largest step shrink and growth per step (Hairer's fac1 = 0.333, fac2 = 6).
const SHRINK_LIMIT: f64 = 1.0 / 0.333;
const GROWTH_LIMIT: f64 = 1.0 / 6.0;

/// y + h Σ w_j k_j over the stages with a nonzero weight (one pass).
// Inlined (with `Stepper::step`) into a caller compiled for wider
// registers, so the sums run on them: they were a quarter of a 3D kick's
// time as a baseline-x86-64 function (the same arithmetic, bit for bit).
#[inline(always)]
fn combine_from<const N: usize, const M: usize>(y: &SVector<f64, N>, h: f64, weights: &[f64; M], k: &[SVector<f64, N>]) -> SVector<f64, N> {
    let mut sum = *y;
    for (w, kj) in weights.iter().zip(k) {
        if *w != 0.0 {
            sum.axpy(*w * h, kj, 1.0);
        }
    }
    sum
}

/// Σ w_j k_j over the stages with a nonzero weight.
#[inline(always)]
fn combine<const N: usize, const M: usize>(weights: &[f64; M], k: &[SVector<f64, N>]) -> SVector<f64, N> {
    let mut sum = SVector::<f64, N>::zeros();
    for (w, kj) in weights.iter().zip(k) {
        if *w != 0.0 {
            sum.axpy(*w, kj, 1.0);
        }
    }
    sum
}

/// The stepper's state between accepted steps, and the stages of the last one.
#[derive(Debug, Clone)]
pub struct Stepper<const N: usize> {
    t: f64,
    y: SVector<f64, N>,
    h: f64,
    h_max: f64,
    relative_tolerance: f64,
    /// Absolute tolerance per component.
    absolute_tolerance: SVector<f64, N>,
    /// k1..k13 of the last accepted step (k13 = f at its end = next k1).
    k: [SVector<f64, N>; 13],
    /// Start and size of the last accepted step, and its start value.
    last_t: f64,
    last_h: f64,
    last_y: SVector<f64, N>,
    rejected_last: bool,
    /// Gustafsson's predictive step control (opt-in, [`Stepper::set_predictive`]).
    predictive: bool,
    /// Size and error of the last accepted step since the last restart, for
    /// the predictive control.
    previous: Option<(f64, f64)>,
    pub evaluations: u64,
    pub accepted: u64,
    pub rejected: u64,
}

impl<const N: usize> Stepper<N> {
    /// Start at (t, y). The first step is chosen as in Hairer's `hinit`
    /// (one more evaluation).
    pub fn new<S: System<N>>(
        system: &S,
        t: f64,
        y: SVector<f64, N>,
        relative_tolerance: f64,
        absolute_tolerance: SVector<f64, N>,
        h_max: f64,
    ) -> Self {
        let mut stepper = Stepper::starting_with(system, t, y, relative_tolerance, absolute_tolerance, h_max, h_max);
        stepper.h = stepper.initial_step(system);
        stepper
    }

    /// Start at (t, y) with a first step `h0` known to the caller (bounded
    /// by `h_max`): one evaluation, none spent on `hinit`'s guess.
    pub fn starting_with<S: System<N>>(
        system: &S,
        t: f64,
        y: SVector<f64, N>,
        relative_tolerance: f64,
        absolute_tolerance: SVector<f64, N>,
        h_max: f64,
        h0: f64,
    ) -> Self {
        let f0 = system.derivative(t, &y);
        let mut k = [SVector::<f64, N>::zeros(); 13];
        k[0] = f0;
        Stepper {
            t,
            y,
            h: h0.min(h_max),
            h_max,
            relative_tolerance,
            absolute_tolerance,
            k,
            last_t: t,
            last_h: 0.0,
            last_y: y,
            rejected_last: false,
            predictive: false,
            previous: None,
            evaluations: 1,
            accepted: 0,
            rejected: 0,
        }
    }

    fn scale(&self, i: usize, a: f64, b: f64) -> f64 {
        self.absolute_tolerance[i] + self.relative_tolerance * a.abs().max(b.abs())
    }

    fn initial_step<S: System<N>>(&mut self, system: &S) -> f64 {
        let f0 = self.k[0];
        let (mut d0, mut d1) = (0.0, 0.0);
        for i in 0..N {
            let sc = self.scale(i, self.y[i], 0.0);
            d0 += (self.y[i] / sc).powi(2);
            d1 += (f0[i] / sc).powi(2);
        }
        let mut h0 = if d0 < 1e-10 || d1 < 1e-10 { 1e-6 } else { 0.01 * (d0 / d1).sqrt() };
        h0 = h0.min(self.h_max);
        let f1 = system.derivative(self.t + h0, &(self.y + f0 * h0));
        self.evaluations += 1;
        let mut d2 = 0.0;
        for i in 0..N {
            let sc = self.scale(i, self.y[i], 0.0);
            d2 += ((f1[i] - f0[i]) / sc).powi(2);
        }
        let d2 = d2.sqrt() / h0;
        let der = d1.sqrt().max(d2);
        let h1 = if der <= 1e-15 { (h0 * 1e-3).max(1e-6) } else { (0.01 / der).powf(1.0 / 8.0) };
        (100.0 * h0).min(h1).min(self.h_max)
    }

    pub fn time(&self) -> f64 {
        self.t
    }
    pub fn state(&self) -> &SVector<f64, N> {
        &self.y
    }
    /// Start, size and start value of the last accepted step.
    pub fn last_step(&self) -> (f64, f64, &SVector<f64, N>) {
        (self.last_t, self.last_h, &self.last_y)
    }

    /// Take one accepted step (retrying rejected sizes).
    // Inlined into its caller, so a caller compiled for wider registers
    // (kick-3d's AVX2 run) compiles the step's stage sums with them too.
    #[inline(always)]
    pub fn step<S: System<N>>(&mut self, system: &S) -> Result<(), StepFailure> {
        let mut tries = 0;
        loop {
            let h = self.h.min(self.h_max);
            if 0.1 * h <= f64::EPSILON * self.t.abs() || h <= f64::MIN_POSITIVE {
                return Err(StepFailure::StepSizeUnderflow { time: self.t });
            }
            let k = &mut self.k;
            for s in 1..12 {
                let stage = combine_from(&self.y, h, &A[s - 1], &k[..s]);
                k[s] = system.derivative(self.t + C[s] * h, &stage);
            }
            self.evaluations += 11;
            let b_sum = combine(&B, &k[..12]);
            let y_new = self.y + b_sum * h;
            let err5 = combine(&E, &k[..12]);
            let err3 = b_sum - k[0] * BHH[0] - k[8] * BHH[1] - k[11] * BHH[2];
            let (mut e5, mut e3) = (0.0, 0.0);
            for i in 0..N {
                let sc = self.scale(i, self.y[i], y_new[i]);
                e5 += (err5[i] / sc).powi(2);
                e3 += (err3[i] / sc).powi(2);
            }
            let mut denominator = e5 + 0.01 * e3;
            if denominator <= 0.0 {
                denominator = 1.0;
            }
            let err = h * e5 / (system.counted_components() as f64 * denominator).sqrt();
            if !err.is_finite() || !y_new.iter().all(|v| v.is_finite()) {
                // A non-finite trial is a step too large, never physics.
                self.rejected += 1;
                tries += 1;
                if tries >= MAX_REJECTIONS {
                    return Err(StepFailure::Rejections { time: self.t });
                }
                self.h = h * 0.1;
                self.rejected_last = true;
                continue;
            }
            let fac11 = err.powf(1.0 / 8.0);
            let fac = (fac11 / SAFETY).clamp(GROWTH_LIMIT, SHRINK_LIMIT);
            let mut h_new = h / fac;
            if err <= 1.0 {
                if self.predictive {
                    // Gustafsson's predictive controller (Hairer & Wanner,
                    // Solving ODEs II, IV.8, as RADAU5 has it): the error
                    // coefficient extrapolated from the last two accepted
                    // steps, so one that keeps growing does not make every
                    // proposed step too large by the same share.
                    if let Some((h_previous, err_previous)) = self.previous {
                        let predicted = (h_previous / h) * (err * err / err_previous).powf(1.0 / 8.0) / SAFETY;
                        h_new = h / fac.max(predicted.clamp(GROWTH_LIMIT, SHRINK_LIMIT));
                    }
                    self.previous = Some((h, err.max(1e-2)));
                }
                self.k[12] = system.derivative_at_step_end(self.t + h, &y_new);
                self.evaluations += 1;
                if self.rejected_last {
                    h_new = h_new.min(h);
                }
                self.rejected_last = false;
                self.last_t = self.t;
                self.last_h = h;
                self.last_y = self.y;
                self.t += h;
                self.y = y_new;
                self.h = h_new.min(self.h_max);
                self.accepted += 1;
                return Ok(());
            }
            h_new = h / (fac11 / SAFETY).min(SHRINK_LIMIT);
            self.rejected_last = true;
            self.rejected += 1;
            tries += 1;
            if tries >= MAX_REJECTIONS {
                return Err(StepFailure::Rejections { time: self.t });
            }
            self.h = h_new;
        }
    }

    /// y' at the end of the last accepted step (k13; call before `advance`).
    pub fn end_derivative(&self) -> &SVector<f64, N> {
        &self.k[12]
    }

    /// y' at the start of the next step (k1: after `advance` or `restart`).
    pub fn start_derivative(&self) -> &SVector<f64, N> {
        &self.k[0]
    }

    /// Go on from (t, y) with `system` (a new right-hand side after a
    /// located switch), keeping the step size: one evaluation.
    pub fn restart<S: System<N>>(&mut self, system: &S, t: f64, y: SVector<f64, N>) {
        self.t = t;
        self.y = y;
        self.k[0] = system.derivative(t, &y);
        self.evaluations += 1;
        self.rejected_last = false;
        self.previous = None;
    }

    /// Choose later steps by Gustafsson's predictive controller, which
    /// follows an error coefficient that changes from step to step. Only
    /// the proposed sizes change: every step passes the same error test.
    pub fn set_predictive(&mut self, on: bool) {
        if on != self.predictive {
            self.predictive = on;
            self.previous = None;
        }
    }

    /// The size the next step will try.
    pub fn next_step(&self) -> f64 {
        self.h
    }
    /// Try `h` next (after a change of independent variable).
    pub fn set_next_step(&mut self, h: f64) {
        self.h = h;
    }

    /// Absolute tolerance per component from the next step on (a component
    /// whose meaning changes with the phase).
    pub fn set_absolute_tolerance(&mut self, absolute_tolerance: SVector<f64, N>) {
        self.absolute_tolerance = absolute_tolerance;
    }

    /// Bound later steps to `h_max` (to land on a known end of the independent variable).
    pub fn set_max_step(&mut self, h_max: f64) {
        self.h_max = h_max;
    }

    /// Set k1 of the next step: after `step`, k13 of this one.
    /// (Kept apart so `dense` can still read this step's stages.)
    pub fn advance(&mut self) {
        self.k[0] = self.k[12];
    }

    /// The dense output of the last accepted step (three more evaluations).
    /// Call between `step` and `advance`.
    pub fn dense<S: System<N>>(&mut self, system: &S) -> Dense<N> {
        let h = self.last_h;
        let y0 = self.last_y;
        let k = &self.k;
        let mut all = [SVector::<f64, N>::zeros(); 16];
        all[..13].copy_from_slice(k);
        all[13] = system.derivative(self.last_t + C[13] * h, &(y0 + combine(&A14, &all[..13]) * h));
        all[14] = system.derivative(self.last_t + C[14] * h, &(y0 + combine(&A15, &all[..14]) * h));
        all[15] = system.derivative(self.last_t + C[15] * h, &(y0 + combine(&A16, &all[..15]) * h));
        self.evaluations += 3;
        let y_diff = self.y - y0;
        let bspl = k[0] * h - y_diff;
        let coefficients = [
            y0,
            y_diff,
            bspl,
            y_diff - k[12] * h - bspl,
            combine(&D[0], &all) * h,
            combine(&D[1], &all) * h,
            combine(&D[2], &all) * h,
            combine(&D[3], &all) * h,
        ];
        Dense { t0: self.last_t, h, end: self.y, coefficients }
    }
}

/// The 7th-order interpolant over one accepted step [t0, t0 + h].
#[derive(Debug, Clone, Copy)]
pub struct Dense<const N: usize> {
    pub t0: f64,
    pub h: f64,
    /// The step's end value (the interpolant reaches it only to rounding).
    pub end: SVector<f64, N>,
    coefficients: [SVector<f64, N>; 8],
}

impl<const N: usize> Dense<N> {
    pub fn t1(&self) -> f64 {
        self.t0 + self.h
    }

    /// y(t) for t in [t0, t0 + h].
    pub fn at(&self, t: f64) -> SVector<f64, N> {
        let theta = (t - self.t0) / self.h;
        let theta1 = 1.0 - theta;
        let r = &self.coefficients;
        r[0] + (r[1] + (r[2] + (r[3] + (r[4] + (r[5] + (r[6] + r[7] * theta) * theta1) * theta) * theta1) * theta) * theta1) * theta
    }

    /// y'(t) of the interpolant (its error is a power of h lower than y's).
    pub fn derivative_at(&self, t: f64) -> SVector<f64, N> {
        let theta = (t - self.t0) / self.h;
        let theta1 = 1.0 - theta;
        let r = &self.coefficients;
        // Horner on the nested form of `at`, carrying d/dθ along.
        let p6 = r[6] + r[7] * theta;
        let d6 = r[7];
        let p5 = r[5] + p6 * theta1;
        let d5 = d6 * theta1 - p6;
        let p4 = r[4] + p5 * theta;
        let d4 = d5 * theta + p5;
        let p3 = r[3] + p4 * theta1;
        let d3 = d4 * theta1 - p4;
        let p2 = r[2] + p3 * theta;
        let d2 = d3 * theta + p3;
        let p1 = r[1] + p2 * theta1;
        let d1 = d2 * theta1 - p2;
        (d1 * theta + p1) / self.h
    }

    /// Component i of y(t).
    pub fn component(&self, i: usize, t: f64) -> f64 {
        let theta = (t - self.t0) / self.h;
        let theta1 = 1.0 - theta;
        let r = |j: usize| self.coefficients[j][i];
        r(0) + (r(1) + (r(2) + (r(3) + (r(4) + (r(5) + (r(6) + r(7) * theta) * theta1) * theta) * theta1) * theta) * theta1) * theta
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    /// Harmonic oscillator y'' = −y: exact solution (cos t, −sin t).
    struct Oscillator;
    impl System<2> for Oscillator {
        fn derivative(&self, _t: f64, y: &Vector2<f64>) -> Vector2<f64> {
            Vector2::new(y[1], -y[0])
        }
    }

    fn run(rtol: f64, end: f64) -> (Stepper<2>, f64) {
        let mut s = Stepper::new(&Oscillator, 0.0, Vector2::new(1.0, 0.0), rtol, Vector2::repeat(rtol), f64::INFINITY);
        let mut worst_dense: f64 = 0.0;
        while s.time() < end {
            s.step(&Oscillator).unwrap();
            let d = s.dense(&Oscillator);
            for j in 1..8 {
                let t = d.t0 + d.h * j as f64 / 8.0;
                worst_dense = worst_dense.max((d.component(0, t) - t.cos()).abs());
            }
            s.advance();
        }
        (s, worst_dense)
    }

    /// A first step the caller knows spares `hinit`'s evaluation, is the
    /// step taken (bounded by h_max), and gives `new`'s run when it is
    /// `new`'s step.
    #[test]
    fn a_known_first_step_spares_hinit() {
        let (y0, atol) = (Vector2::new(1.0, 0.0), Vector2::repeat(1e-12));
        let mut guessed = Stepper::new(&Oscillator, 0.0, y0, 1e-10, atol, 1.0);
        let mut known = Stepper::starting_with(&Oscillator, 0.0, y0, 1e-10, atol, 1.0, guessed.next_step());
        assert_eq!(known.evaluations + 1, guessed.evaluations);
        guessed.step(&Oscillator).unwrap();
        known.step(&Oscillator).unwrap();
        assert_eq!((known.time(), known.state()), (guessed.time(), guessed.state()));
        assert_eq!(Stepper::starting_with(&Oscillator, 0.0, y0, 1e-10, atol, 0.5, 2.0).next_step(), 0.5);
    }

    #[test]
    fn dense_derivative_is_the_interpolant_s() {
        let mut s = Stepper::new(&Oscillator, 0.0, Vector2::new(1.0, 0.0), 1e-10, Vector2::new(1e-12, 1e-12), 0.5);
        s.step(&Oscillator).unwrap();
        let d = s.dense(&Oscillator);
        let t = d.t0 + 0.37 * d.h;
        let e = 1e-6 * d.h;
        let difference = (d.at(t + e) - d.at(t - e)) / (2.0 * e);
        assert!((d.derivative_at(t) - difference).norm() < 1e-7, "{} vs {}", d.derivative_at(t), difference);
        // y' = (y1, −y0) up to the interpolant's error.
        let y = d.at(t);
        assert!((d.derivative_at(t) - Vector2::new(y[1], -y[0])).norm() < 1e-8);
    }

    #[test]
    fn oscillator_global_and_dense_error_follow_the_tolerance() {
        for rtol in [1e-8, 1e-11] {
            let (s, dense) = run(rtol, 20.0);
            let t = s.time();
            let err = (s.state()[0] - t.cos()).abs().max((s.state()[1] + t.sin()).abs());
            // Global error over ~3 periods stays within a small multiple of the tolerance.
            assert!(err < 20.0 * rtol, "rtol {rtol}: end error {err:.2e}");
            assert!(dense < 20.0 * rtol, "rtol {rtol}: dense error {dense:.2e}");
        }
    }

    /// y' = y² from y(0) = 1: y = 1/(1 − t), whose error coefficient grows
    /// without bound towards t = 1, as a slip's turning does towards
    /// separation in kick-3d.
    struct BlowUp;
    impl System<1> for BlowUp {
        fn derivative(&self, _t: f64, y: &nalgebra::Vector1<f64>) -> nalgebra::Vector1<f64> {
            nalgebra::Vector1::new(y[0] * y[0])
        }
    }

    /// The predictive control follows a growing error coefficient: towards
    /// the blow-up the standard control proposes nearly every step too large
    /// by the same share and has it rejected (75 rejected against 80
    /// accepted); the predictive one rejects one, and both keep the error the
    /// tolerance asks for.
    #[test]
    fn the_predictive_control_follows_a_growing_error_coefficient() {
        let end = 1.0 - 1e-4;
        let run = |predictive: bool| {
            let y0 = nalgebra::Vector1::new(1.0);
            let mut s = Stepper::starting_with(&BlowUp, 0.0, y0, 1e-10, nalgebra::Vector1::new(1e-10), end, 1e-3);
            s.set_predictive(predictive);
            while s.time() < end {
                s.set_max_step(end - s.time());
                s.step(&BlowUp).unwrap();
                s.advance();
            }
            let exact = 1.0 / (1.0 - s.time());
            (s.accepted, s.rejected, ((s.state()[0] - exact) / exact).abs())
        };
        let (standard, predictive) = (run(false), run(true));
        // A perturbation grows as y² here, so the relative error as y: the
        // tolerance times y(end) = 1e4 bounds both.
        let bound = 1e-10 / (1.0 - end);
        assert!(standard.2 < bound && predictive.2 < bound, "{standard:?} {predictive:?}");
        assert!(predictive.1 * 4 <= standard.1, "{standard:?} {predictive:?}");
        assert!(predictive.0 + predictive.1 < standard.0 + standard.1, "{standard:?} {predictive:?}");
    }

    #[test]
    fn tableau_rows_sum_to_their_nodes() {
        // Σ_j a_ij = c_i for every stage and Σ b = 1: catches a mistyped coefficient.
        for (i, row) in A.iter().enumerate() {
            assert!((row.iter().sum::<f64>() - C[i + 1]).abs() < 1e-14, "stage {}", i + 2);
        }
        assert!((A14.iter().sum::<f64>() - C[13]).abs() < 1e-14);
        assert!((A15.iter().sum::<f64>() - C[14]).abs() < 1e-14);
        assert!((A16.iter().sum::<f64>() - C[15]).abs() < 1e-14);
        assert!((B.iter().sum::<f64>() - 1.0).abs() < 1e-14);
        assert!(E.iter().sum::<f64>().abs() < 1e-14);
    }

    #[test]
    fn eighth_order_convergence() {
        // Halving the step multiplies the error by about 2^-8 = 1/256: fixed steps via h_max
        // and a tolerance too loose to reject anything.
        let err_at = |h: f64| {
            let mut s = Stepper::new(&Oscillator, 0.0, Vector2::new(1.0, 0.0), 1.0, Vector2::repeat(1.0), h);
            while s.time() < 4.0 - 1e-12 {
                s.step(&Oscillator).unwrap();
                s.advance();
            }
            (s.state()[0] - s.time().cos()).abs()
        };
        let ratio = err_at(0.5) / err_at(0.25);
        assert!(ratio > 150.0 && ratio < 500.0, "ratio {ratio}");
    }
}
