//! The fast route allocates nothing per call at `f64` and double-double once its rule is built
//! (a counting allocator wraps the system one in this test binary; the count is per thread, so
//! tests running in parallel do not disturb each other).

use moving_hertz::physics::Material;
use moving_hertz::scalar::{Dd, Real};
use moving_hertz::{integrals, Evaluator, IntegralOptions, Method};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

// SAFETY: every call is forwarded unchanged to the system allocator; the thread-local counter
// is a const-initialised `Cell` and does not allocate.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations() -> usize {
    ALLOCATIONS.with(|c| c.get())
}

fn no_allocation<T: Real>(p: T::Prec) {
    let mat = Material::new(T::from_ratio(1, 4, p)).unwrap();
    let speed = mat.speed(T::from_ratio(99, 100, p)).unwrap();
    let fixed = |derivatives| IntegralOptions {
        method: Method::Fixed,
        derivatives,
        ..Default::default()
    };
    // The counter works: the speed's set-up (built on its first call) keeps its node values in
    // vectors.
    let before = allocations();
    let ev = Evaluator::new(&speed, fixed(true)).unwrap();
    ev.at(&T::one(p)).unwrap();
    assert!(allocations() > before);
    for q in [(1, 1_000_000), (3, 10), (1, 1)] {
        let k = T::from_ratio(q.0, q.1, p);
        // Warm up: builds and caches the rule (and the Gauss–Legendre nodes).
        integrals(&speed, &k, &fixed(true)).unwrap();
        let before = allocations();
        let a = integrals(&speed, &k, &fixed(false)).unwrap();
        let b = integrals(&speed, &k, &fixed(true)).unwrap();
        let c = ev.at(&k).unwrap();
        let after = allocations();
        assert_eq!(
            after - before,
            0,
            "k = {q:?}: {} allocations",
            after - before
        );
        let d2 = b.di2_dk.expect("dI2/dk").value;
        assert!(a.i1.value.is_finite() && d2.is_finite() && c.i2.value.is_finite());
    }
}

#[test]
fn no_allocation_per_call_at_f64_and_double_double() {
    no_allocation::<f64>(());
    no_allocation::<Dd>(());
}

/// A warm ellipse solve (33) allocates nothing per evaluation or for publishing its result, and
/// no fixed-rule set-up at its working precision (the speed keeps the one its first solve
/// built): nothing at `f64`; at double-double the `f64` stage of the precision ladder (a speed
/// made for it, with its set-up) and the ladder's small allocations.
#[test]
fn a_warm_ellipse_solve_allocates_only_its_set_ups() {
    fn count<T: Real>(p: T::Prec) -> usize {
        use moving_hertz::prelude::*;
        let mat = Material::new(T::from_ratio(1, 5, p)).unwrap();
        let speed = mat.speed(T::from_ratio(9, 10, p)).unwrap();
        let ratio = T::from_ratio(1, 2, p);
        let opts = Options::default();
        moving_hertz::solve_ellipse(&speed, &ratio, &opts).unwrap();
        let before = allocations();
        moving_hertz::solve_ellipse(&speed, &ratio, &opts).unwrap();
        allocations() - before
    }
    assert_eq!(count::<f64>(()), 0);
    let dd = count::<Dd>(());
    println!("allocations of a warm double-double solve: {dd}");
    assert!(dd <= 7);
}
