use kick_3d::models::{OffCenterBox, BENCH_SEED};
fn main() {
    let s = OffCenterBox::new(BENCH_SEED);
    let mut a = vec![];
    let mut b = vec![];
    for i in 0..200 {
        let k = s.kick(i).unwrap();
        a.push(kick_3d::FullState3d::default().solve(&k).unwrap().energy.relative_residual().abs());
        b.push(kick_3d::Accurate3d::default().solve(&k).unwrap().energy.relative_residual().abs());
    }
    a.sort_by(f64::total_cmp);
    b.sort_by(f64::total_cmp);
    println!("full-state max {:.2e} median {:.2e}; accurate max {:.2e} median {:.2e}", a[199], a[100], b[199], b[100]);
}
