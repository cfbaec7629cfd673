//! The summary path allocates nothing: a counting global allocator around `solve`.

use kick_flight::{models, solve};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
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
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    for f in &flights {
        std::hint::black_box(solve(f).expect("lands"));
    }
    assert_eq!(ALLOCATIONS.load(Ordering::SeqCst) - before, 0);
}
