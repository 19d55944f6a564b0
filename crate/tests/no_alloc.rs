//! The closed loop (plant + EKF + controller + recording) allocates nothing per step.

// A counting global allocator needs `unsafe impl GlobalAlloc`; only this test binary has it.
#![allow(unsafe_code)]

use imlab::scenario::PRESETS;
use imlab::sim::Simulation;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    // Per thread, so the test harness's own threads do not count.
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

fn count() {
    ALLOCATIONS.with(|c| c.set(c.get() + 1));
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn closed_loop_steps_do_not_allocate() {
    for p in PRESETS {
        let s = imlab::scenario::preset(p.name).unwrap();
        let mut sim = Simulation::new(&s, 1).unwrap();
        let before = allocations();
        let result = sim.advance(2000);
        let after = allocations();
        assert!(result.is_ok(), "{}: {:?}", p.name, result);
        assert_eq!(
            after - before,
            0,
            "{}: {} allocations in 2000 steps",
            p.name,
            after - before
        );
    }
}

#[test]
fn traced_steps_do_not_allocate() {
    // Checkpoints go into room made when the run is prepared; the overview's envelopes and the
    // kept overlay column too.
    let groups: Vec<Vec<String>> = [&["omega", "omega_hat", "omega_ref"][..], &["i_sa", "nis"]]
        .iter()
        .map(|g| g.iter().map(|n| n.to_string()).collect())
        .collect();
    for p in PRESETS {
        let s = imlab::scenario::preset(p.name).unwrap();
        let mut sim = Simulation::traced(&s).unwrap();
        sim.keep_overview(&groups, 1000).unwrap();
        sim.keep_column("omega").unwrap();
        let before = allocations();
        let result = sim.advance(5000);
        let after = allocations();
        assert!(result.is_ok(), "{}: {:?}", p.name, result);
        assert_eq!(
            after - before,
            0,
            "{}: {} allocations in 5000 steps",
            p.name,
            after - before
        );
    }
}
