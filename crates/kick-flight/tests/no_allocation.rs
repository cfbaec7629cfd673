//! The summary path allocates nothing: a counting global allocator around `solve`.
//! Only allocations made on the test's own thread while `solve` runs are
//! counted: the test harness's other threads may allocate at any time (CI
//! once saw 3 of theirs land in the window).

use kick_flight::{models, solve};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    // Const-initialised: reading it never allocates, so the allocator may.
    static COUNTING: Cell<bool> = const { Cell::new(false) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTING.with(Cell::get) {
            ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        }
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn solve_does_not_allocate() {
    let flights = [models::free_kick(), models::plain_kick()];
    COUNTING.with(|c| c.set(true));
    for f in &flights {
        std::hint::black_box(solve(f).expect("lands"));
    }
    COUNTING.with(|c| c.set(false));
    assert_eq!(ALLOCATIONS.load(Ordering::SeqCst), 0);
    // The counter counts: one allocation on this thread is seen.
    COUNTING.with(|c| c.set(true));
    std::hint::black_box(vec![1u8; 8]);
    COUNTING.with(|c| c.set(false));
    assert_eq!(ALLOCATIONS.load(Ordering::SeqCst), 1);
}
