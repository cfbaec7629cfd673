//! χ across the FIFA rebound band (115–165 cm from 2 m), for SOURCES.md:
//! `cargo run -p kick-bounce --example fifa_band`.

fn main() {
    let v0 = (2.0 * kick_core::GRAVITY * 2.0_f64).sqrt();
    for h in [1.15, 1.20, 1.40, 1.65] {
        let e = (h / 2.0_f64).sqrt();
        println!("rebound {h} m: e = {e:.4}, χ = {:.4} s/m", kick_core::laws::exact_hysteresis(e) / v0);
    }
}
