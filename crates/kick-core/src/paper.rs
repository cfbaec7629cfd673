//! Numbers printed in the paper, kept as the reference they are.

/// One row of Table 2 as printed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedRow {
    pub name: &'static str,
    /// v_b⁺, m/s, printed with 2 decimals.
    pub v_ball_out: f64,
    /// v_b⁺/v_f⁻, 2 decimals.
    pub speed_ratio: f64,
    /// N, 0 decimals.
    pub peak_force: f64,
    /// ms, 2 decimals.
    pub contact_time_ms: f64,
    /// mm, 2 decimals.
    pub max_compression_mm: f64,
}

/// Table 2 of the paper.
pub const TABLE2: [PrintedRow; 8] = [
    row("Baseline", 31.98, 1.45, 3804.0, 5.29, 27.95),
    row("Light effective foot", 20.55, 0.93, 2962.0, 4.43, 21.71),
    row("Heavy effective foot", 34.94, 1.59, 4014.0, 5.48, 29.35),
    row("Very soft ball", 29.28, 1.33, 2637.0, 8.91, 38.87),
    row("Very stiff ball", 34.47, 1.57, 7905.0, 2.87, 17.51),
    row("Highly damped", 25.13, 1.14, 9853.0, 5.10, 14.49),
    row("Ball approaching foot", 35.90, 1.63, 5469.0, 5.05, 36.90),
    row("Ball already moving", 27.21, 1.24, 1876.0, 5.78, 16.20),
];

const fn row(
    name: &'static str,
    v_ball_out: f64,
    speed_ratio: f64,
    peak_force: f64,
    contact_time_ms: f64,
    max_compression_mm: f64,
) -> PrintedRow {
    PrintedRow { name, v_ball_out, speed_ratio, peak_force, contact_time_ms, max_compression_mm }
}

/// Decimal places printed per column: v_b⁺, ratio, peak force, contact (ms), compression (mm).
pub const TABLE2_DECIMALS: [i32; 5] = [2, 2, 0, 2, 2];

/// Baseline values quoted in Section 13 (Eqs. 49–53).
pub const BASELINE_TEXT: PrintedRow = row("Baseline (Section 13)", 31.98, 1.45, 3800.0, 5.29, 27.9);
