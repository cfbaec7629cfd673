use kick_3d::models::{OffCenterBox, BENCH_SEED};
use kick_core::LawKind;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let law = LawKind::from_name(&a[1]).unwrap();
    let i: u64 = a[2].parse().unwrap();
    let k = OffCenterBox { seed: BENCH_SEED, law }.kick(i).unwrap();
    for r in [1e-11, 1e-12, 3e-13, 1e-13, 3e-14] {
        let o = kick_3d::Accurate3d::new(r).unwrap().solve(&k).unwrap();
        println!("accurate {r:.0e}: v {:?} t {:.15e} evals {}", o.launch_velocity, o.contact_time, o.evaluations);
    }
    let o = kick_3d::precision::reference().solve(&k).unwrap();
    println!("reference: v {:?} t {:.15e} evals {}", o.launch_velocity, o.contact_time, o.evaluations);
    for r in [1e-12, 1e-13, 1e-14] {
        let o = kick_3d::FullState3d::new(r, r * 1e-3).unwrap().solve(&k).unwrap();
        println!("full     {r:.0e}: v {:?} t {:.15e} evals {}", o.launch_velocity, o.contact_time, o.evaluations);
    }
}
