use kick_flight::{models, solve};
fn main() {
    for f in [models::plain_kick(), models::free_kick()] {
        let o = solve(&f).unwrap();
        println!("{}", serde_json::to_string_pretty(&o).unwrap());
        for rtol in [1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13] {
            let r = solve(&f.with_relative_tolerance(rtol).unwrap()).unwrap();
            let t = solve(&f.with_relative_tolerance(rtol / 100.0).unwrap()).unwrap();
            let rel = |a: f64, b: f64| ((a - b) / b).abs();
            let mut worst = rel(r.flight_time, t.flight_time).max(rel(r.landing_point[0], t.landing_point[0])).max(rel(r.apex_height, t.apex_height));
            if let (Some(a), Some(b)) = (r.crossing, t.crossing) { worst = worst.max(rel(a.time, b.time)).max(rel(a.height, b.height)).max(rel(a.lateral_offset, b.lateral_offset)); }
            println!("rtol {rtol:e}: steps {} evals {} worst rel vs rtol/100 {worst:.2e}", r.steps, r.evaluations);
        }
    }
}
