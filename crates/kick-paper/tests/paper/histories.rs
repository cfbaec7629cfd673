//! Histories of a run are streamed to the file (issue 13): a fine sampling
//! interval changes neither the outcome nor the step budget, and the run's
//! memory does not grow with the histories' length.
//!
//! The heap is measured by a counting allocator, so this file holds one test
//! (another running beside it would count too). HDF5's own buffers are C
//! allocations outside it; their size is fixed by the chunk caches.

use kick_compliant::Accurate;
use kick_core::{RecordingSolver, Scenario, Solver, Spacing, HISTORY_COLUMNS, OBSERVABLES};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static CURRENT: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: forwards to the system allocator, only counting sizes.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let pointer = unsafe { System.alloc(layout) };
        if !pointer.is_null() {
            let now = CURRENT.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            PEAK.fetch_max(now, Ordering::Relaxed);
        }
        pointer
    }
    unsafe fn dealloc(&self, pointer: *mut u8, layout: Layout) {
        unsafe { System.dealloc(pointer, layout) };
        CURRENT.fetch_sub(layout.size(), Ordering::Relaxed);
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

const INTERVAL: f64 = 2e-8;

#[test]
fn fine_histories_are_streamed_with_bounded_memory_and_unchanged_outcomes() {
    let dir = crate::scratch("histories");
    let file = dir.join("fine.toml");
    std::fs::write(
        &file,
        format!(
            "solver = \"accurate\"\n[[sweep]]\nparameter = \"stiffness\"\nvalues = [2e5, 4.2e5, 1e6, 2e6]\n\
             [output]\nmode = \"history\"\ninterval = {INTERVAL:e}\n"
        ),
    )
    .unwrap();
    let experiment = kick_study::experiment::load(&file).unwrap();

    let before = CURRENT.load(Ordering::Relaxed);
    PEAK.store(before, Ordering::Relaxed);
    let summary = kick_store::run(&experiment, &dir, false).unwrap();
    let peak = PEAK.load(Ordering::Relaxed) - before;
    // A few blocks of 4096 samples per thread, not the histories (~90 MB, checked below).
    assert!(peak < 16_000_000, "peak heap {peak} bytes");

    let data = kick_store::SweepData::read(&summary.path).unwrap();
    let set = &data.sets[0];
    assert!(set.status.iter().all(|&s| s == 0), "every row solved: {:?}", set.status);
    let mut samples = 0;
    for row in 0..data.rows() {
        let scenario: Scenario = experiment.one_d().unwrap().scenarios.scenario(row as u64).unwrap();
        // The outcome is the one without a history, bit for bit.
        let outcome = Accurate::default().solve(&scenario).unwrap();
        for ((name, _), value) in OBSERVABLES.iter().zip(outcome.observable_values()) {
            assert_eq!(set.column(name).unwrap()[row].to_bits(), value.to_bits(), "row {row}: {name}");
        }
        let history = kick_store::h5::read_history(&summary.path, "", row).unwrap();
        let column = |name: &str| &history.iter().find(|(c, _)| c.name == name).unwrap().1;
        let time = column("time");
        // Grid t_k = k Δ strictly before the contact's end, then the separation row.
        let expected = kick_core::Spacing::Interval(INTERVAL).grid(outcome.contact_time).samples_until(outcome.contact_time);
        assert_eq!(time.len() as u64, expected, "row {row}");
        for (k, t) in time[..time.len() - 1].iter().enumerate() {
            assert_eq!(*t, k as f64 * INTERVAL, "row {row}, sample {k}");
        }
        assert_eq!(*time.last().unwrap(), outcome.contact_time);
        assert_eq!(history.len(), HISTORY_COLUMNS.len());
        if row == 0 {
            // Every column as the collecting form records it.
            let (_, recorded) = Accurate::default().solve_sampled(&scenario, Spacing::Interval(INTERVAL), usize::MAX).unwrap();
            for (i, (name, _)) in HISTORY_COLUMNS.iter().enumerate() {
                let values = column(name);
                assert!(recorded.samples.iter().zip(values).all(|(s, v)| s.values()[i].to_bits() == v.to_bits()), "{name}");
            }
        }
        samples += time.len();
    }
    let history_bytes = samples * HISTORY_COLUMNS.len() * 8;
    assert!(history_bytes > 80_000_000, "the histories should be large: {history_bytes} bytes");
    println!("peak heap {:.1} MB for {:.1} MB of histories", peak as f64 / 1e6, history_bytes as f64 / 1e6);
    let _ = std::fs::remove_dir_all(&dir);
}
