//! `kick sweep3d` end to end: the file read back with the hdf5 crate, each
//! row solved again from its stored parameters alone.

use crate::scratch;
use kick_3d::OBSERVABLES_3D;
use kick_3d::{KickSpec, Solver3d};
use kick_core::parameters::{self, Shape, Value};
use kick_core::{LawKind, SetParameter, Status};
use kick_store::h5::read_str_attr;
use kick_store::sweep3d::{sweep3d, SampledKicks, Sweep3dSettings};
use std::path::Path;

fn settings(samples: u64, seed: u64, out: &Path) -> Sweep3dSettings {
    let mut fixed = KickSpec::default();
    fixed.scenario.law = Some(LawKind::PowerLaw);
    Sweep3dSettings {
        ranges: Default::default(),
        flight: None,
        samples,
        seed,
        out: out.to_path_buf(),
        fixed,
        shard: None,
        threads: None,
        compress: Default::default(),
    }
}

/// A parameter's rows as [x, y, z]: a vector from its `_x`, `_y`, `_z`
/// columns (the one vector convention of result files), a scalar NaN-padded.
fn rows(file: &hdf5::File, name: &str, vector: bool) -> Vec<[f64; 3]> {
    let read = |path: &str| {
        let d = file.dataset(path).unwrap_or_else(|e| panic!("{path}: {e}"));
        assert_eq!(d.shape().len(), 1, "{path}: one value per row");
        d.read_raw::<f64>().unwrap()
    };
    if vector {
        let [x, y, z] = ["x", "y", "z"].map(|a| read(&format!("parameters/{name}_{a}")));
        (0..x.len()).map(|i| [x[i], y[i], z[i]]).collect()
    } else {
        read(&format!("parameters/{name}")).iter().map(|&x| [x, f64::NAN, f64::NAN]).collect()
    }
}

fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits()
}

/// Every row equals `simulate3d`'s solve (auto) of the parameters stored in
/// that row, bit for bit, in every outcome column (energy terms included); every
/// declared 1D and 3D parameter is stored under its name with its unit.
#[test]
fn each_row_is_the_solve_of_its_stored_parameters() {
    let dir = scratch("sweep3d-rows");
    let out = dir.join("s.h5");
    let report = sweep3d(&settings(48, 11, &out)).expect("sweep");
    assert_eq!(report.kicks, 48);
    let file = hdf5::File::open(&report.path).unwrap();
    let law = LawKind::from_name(&read_str_attr(&file, "law").unwrap()).unwrap();
    // The one table layout of every run, stamped with its version.
    assert_eq!(read_str_attr(&file, "layout").as_deref(), Some(kick_store::layouts::SWEEP.name));
    assert_eq!(kick_store::h5::read_u64_attr(&file, "layout_version"), Some(kick_store::layouts::SWEEP.version));
    // A file stores the parameters its law uses (no `restitution` under the paper's law).
    let declared: Vec<_> = parameters::at_levels(KickSpec::ROW_LEVELS).filter(|p| law.uses(p)).collect();
    let stored: Vec<Vec<[f64; 3]>> = declared
        .iter()
        .map(|p| {
            let vector = p.shape == Shape::Vector3;
            let first = if vector { format!("parameters/{}_x", p.name) } else { format!("parameters/{}", p.name) };
            let d = file.dataset(&first).unwrap();
            assert_eq!(read_str_attr(&d, "units").as_deref(), Some(p.unit), "{}", p.name);
            assert_eq!(read_str_attr(&d, "symbol").as_deref(), Some(p.symbol), "{}", p.name);
            rows(&file, p.name, vector)
        })
        .collect();
    let status = file.dataset("outcomes/status").unwrap().read_raw::<u8>().unwrap();
    let outcomes: Vec<Vec<f64>> =
        OBSERVABLES_3D.iter().map(|(name, _)| file.dataset(&format!("outcomes/{name}")).unwrap().read_raw::<f64>().unwrap()).collect();
    let mut refused = 0;
    for i in 0..48 {
        let mut spec = KickSpec::default();
        spec.scenario.law = Some(law);
        for (p, column) in declared.iter().zip(&stored) {
            let [x, y, z] = column[i];
            let value = match p.shape {
                Shape::Scalar if x.is_nan() => continue, // restitution under the paper's law
                Shape::Scalar => Value::Number(x),
                Shape::Vector3 => Value::Vector([x, y, z]),
                Shape::Switch => Value::Switch(x == 1.0),
            };
            spec.set_parameter(p, value).unwrap();
        }
        // A row the model refuses (a compression beyond the ball's radius) is
        // stored with the status of that refusal.
        let o = match Solver3d::Auto.solve(&spec.build().unwrap()) {
            Ok(o) => o,
            Err(e) => {
                assert_eq!(status[i], e.status().code(), "row {i}: {e}");
                refused += 1;
                continue;
            }
        };
        assert_eq!(status[i], Status::Separated.code(), "row {i}");
        for (k, ((name, _), column)) in OBSERVABLES_3D.iter().zip(&outcomes).enumerate() {
            assert!(same(column[i], o.observable_values()[k]), "row {i} {name}: {} vs {}", column[i], o.observable_values()[k]);
        }
        // The drawn kick is the stored one: the sampler's spec solves to the same row.
        assert_eq!(
            Solver3d::Auto
                .solve(
                    &SampledKicks { ranges: Default::default(), seed: 11, fixed: settings(1, 11, &out).fixed }
                        .spec(i as u64)
                        .build()
                        .unwrap()
                )
                .unwrap(),
            o
        );
    }
    println!("{refused} of 48 rows refused");
    assert!(refused * 8 < 48, "{refused} of 48 rows refused: the sampled box should mostly solve");
    // Inside the box and the declared ranges.
    let by_name = |name: &str| &stored[declared.iter().position(|p| p.name == name).unwrap()];
    for i in 0..48 {
        assert!((0.0..=0.09).contains(&by_name("offset")[i][0]));
        assert!((-20.0..=30.0).contains(&by_name("approach_angle")[i][0]));
        let mu = by_name("friction")[i][0];
        assert!(mu == f64::INFINITY || (0.2..=5.0).contains(&mu), "{mu}");
        assert!((1.0..=10.0).contains(&by_name("foot_mass")[i][0]));
        assert!((1e4..=1e7).contains(&by_name("stiffness")[i][0]));
        assert!((12.0..=35.0).contains(&by_name("foot_speed")[i][0]));
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Every dataset of the file, its values as bits (NaN-exact).
fn all_bits(path: &Path) -> Vec<(String, Vec<u64>)> {
    fn walk(group: &hdf5::Group, prefix: &str, out: &mut Vec<(String, Vec<u64>)>) {
        for name in group.member_names().unwrap() {
            let path = format!("{prefix}/{name}");
            if let Ok(d) = group.dataset(&name) {
                let bits = match d.read_raw::<f64>() {
                    Ok(v) => v.iter().map(|x| x.to_bits()).collect(),
                    Err(_) => match d.read_raw::<u8>() {
                        Ok(v) => v.iter().map(|&x| u64::from(x)).collect(),
                        Err(_) => vec![d.size() as u64],
                    },
                };
                out.push((path, bits));
            } else if let Ok(g) = group.group(&name) {
                walk(&g, &path, out);
            }
        }
    }
    let file = hdf5::File::open(path).unwrap();
    let mut out = Vec::new();
    walk(&file, "", &mut out);
    out
}

/// The same seed gives the same data on one thread and on three; another
/// seed gives other data.
#[test]
fn the_data_do_not_depend_on_the_thread_count() {
    let dir = scratch("sweep3d-threads");
    let run = |threads: usize, seed: u64, name: &str| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        let out = dir.join(name);
        pool.install(|| sweep3d(&settings(9000, seed, &out))).expect("sweep").path
    };
    // 9000 rows: more than one block of rows solved together.
    let one = all_bits(&run(1, 5, "one.h5"));
    let three = all_bits(&run(3, 5, "three.h5"));
    assert!(one.len() > 40, "{} datasets", one.len());
    assert_eq!(one, three);
    let other = all_bits(&run(2, 6, "other.h5"));
    assert_ne!(one, other);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A held parameter is held in every row and leaves the others' draws as they were.
#[test]
fn a_held_parameter_leaves_the_other_draws() {
    let free = SampledKicks { ranges: Default::default(), seed: 3, fixed: KickSpec::default() };
    let mut held = free.clone();
    held.fixed.kick3d.friction = Some(0.7);
    held.fixed.scenario.stiffness = Some(2e5);
    for i in 0..50 {
        let (a, b) = (free.spec(i), held.spec(i));
        assert_eq!((b.kick3d.friction, b.scenario.stiffness), (Some(0.7), Some(2e5)));
        let mut c = a;
        c.kick3d.friction = Some(0.7);
        c.scenario.stiffness = Some(2e5);
        assert_eq!(c, b);
    }
}

#[test]
fn bad_settings_are_refused_by_name() {
    let dir = scratch("sweep3d-bad");
    let error = sweep3d(&settings(0, 1, &dir.join("a.h5"))).unwrap_err().to_string();
    assert!(error.contains("--samples"), "{error}");
    let error = sweep3d(&settings(5, 1, &dir.join("a.csv"))).unwrap_err().to_string();
    assert!(error.contains("--out"), "{error}");
    let error = sweep3d(&settings(200_000_000, 1, &dir.join("a.h5"))).unwrap_err().to_string();
    assert!(error.contains("--samples"), "{error}");
    let mut s = settings(5, 1, &dir.join("a.h5"));
    s.fixed.kick3d.friction = Some(-1.0);
    let error = sweep3d(&s).unwrap_err().to_string();
    assert!(error.contains("`friction` = -1"), "{error}");
    let mut s = settings(5, 1, &dir.join("a.h5"));
    s.fixed.scenario.law = Some(LawKind::Flores);
    let error = sweep3d(&s).unwrap_err().to_string();
    assert!(error.contains("restitution"), "{error}");
    // A held damping under a law that takes its damping from a restitution.
    let mut s = settings(5, 1, &dir.join("a.h5"));
    s.fixed.scenario.law = Some(LawKind::Flores);
    s.fixed.scenario.restitution = Some(0.6);
    s.fixed.scenario.damping = Some(100.0);
    let error = sweep3d(&s).unwrap_err().to_string();
    assert!(error.contains("damping"), "{error}");
    for (given, says) in [("5/5", "numbered from 0 to 4"), ("2", "expected I/N")] {
        let mut s = settings(5, 1, &dir.join("a.h5"));
        s.shard = Some(given.into());
        let error = sweep3d(&s).unwrap_err().to_string();
        assert!(error.starts_with(&format!("`--shard` = `{given}`")) && error.contains(says), "{error}");
        let error = kick_store::sweep::sweep(&kick_store::sweep::SweepSettings {
            ranges: Default::default(),
            samples: 5,
            seed: 1,
            solver: "auto".into(),
            dt: None,
            out: dir.join("b.h5"),
            fixed: Default::default(),
            shard: Some(given.into()),
            threads: None,
            compress: Default::default(),
        })
        .unwrap_err()
        .to_string();
        assert!(error.starts_with(&format!("`--shard` = `{given}`")), "{error}");
    }
    // Nothing was written.
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    std::fs::remove_dir_all(&dir).unwrap();
}
