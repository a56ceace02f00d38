//! The fast route allocates nothing per call at `f64` and double-double once its rule is built
//! (a counting allocator wraps the system one in this test binary; the count is per thread, so
//! tests running in parallel do not disturb each other).

use moving_hertz::physics::Material;
use moving_hertz::routes::fast::{self, FastSetup};
use moving_hertz::routes::AxisRatio;
use moving_hertz::scalar::{Dd, Real};
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
    // The counter works: the setup keeps its node values in vectors.
    let before = allocations();
    let setup = FastSetup::new(&speed).unwrap();
    assert!(allocations() > before);
    for k in [(1, 1_000_000), (3, 10), (1, 1)] {
        let axes = AxisRatio::new(T::from_ratio(k.0, k.1, p)).unwrap();
        // Warm up: builds and caches the rule (and the Gauss–Legendre nodes).
        fast::integrals_with_dk(&speed, &axes).unwrap();
        let before = allocations();
        let a = fast::integrals(&speed, &axes).unwrap();
        let b = fast::integrals_with_dk(&speed, &axes).unwrap();
        let c = setup.integrals_with_dk(&axes).unwrap();
        let after = allocations();
        assert_eq!(
            after - before,
            0,
            "k = {k:?}: {} allocations",
            after - before
        );
        assert!(a.i1.is_finite() && b.di2_dk().is_finite() && c.i2.is_finite());
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
