//! What the ellipse solves at one speed keep with it (`Speed::solve_cache`): the speed at the
//! precision ladder's lower stages, the ellipse solve's seed grid and k = 1 probe, and the
//! graded route's layouts. Each slot is filled on first use and never changes, so that what a solve returns
//! does not depend on the solves before it (`tests/solve_cache.rs`).

use crate::error::Result;
use crate::physics::Speed;
use crate::routes::graded::GradedSetup;
use crate::routes::{Evaluation, Method};
use crate::scalar::{Dd, Real};
use std::sync::{Arc, OnceLock};

/// What the ellipse solves at one speed keep, with the speed and shared by its clones: the speed
/// at `f64` and double-double (the lower ladder stages, whose set-ups then serve every solve),
/// the grid seed's nodes and the graded route's layouts.
#[derive(Clone, Debug)]
pub(crate) struct SolveCache<T: Real>(Arc<Kept<T>>);

/// Values kept on first use, one slot each.
type Slots<V> = Box<[OnceLock<V>]>;

#[derive(Debug)]
struct Kept<T: Real> {
    at_f64: OnceLock<Option<Speed<f64>>>,
    at_dd: OnceLock<Option<Speed<Dd>>>,
    /// F + ln(A1/B1) and F′ at the nodes of the ellipse solve's grid seed, each on first use.
    /// The k = 1 probe's evaluation by method (auto, fixed): it does not depend on A1/B1 (it
    /// still counts as an evaluation, so that a solve's steps do not depend on whether it was
    /// kept).
    probe: [OnceLock<Evaluation<T>>; 2],
    grid: OnceLock<Slots<Option<(f64, f64)>>>,
    /// The graded route's layouts by cell of k (`graded::layout_cell`), each on first use.
    layouts: OnceLock<Slots<Result<GradedSetup<T>>>>,
}

impl<T: Real> SolveCache<T> {
    /// An empty cache.
    pub(crate) fn new() -> Self {
        SolveCache(Arc::new(Kept {
            at_f64: OnceLock::new(),
            at_dd: OnceLock::new(),
            probe: [OnceLock::new(), OnceLock::new()],
            grid: OnceLock::new(),
            layouts: OnceLock::new(),
        }))
    }

    /// `speed` (the one holding this cache) at `f64`; `None` where it does not convert.
    pub(crate) fn at_f64(&self, speed: &Speed<T>) -> Option<&Speed<f64>> {
        self.0.at_f64.get_or_init(|| speed.at(()).ok()).as_ref()
    }

    /// `speed` at double-double; `None` where it does not convert.
    pub(crate) fn at_dd(&self, speed: &Speed<T>) -> Option<&Speed<Dd>> {
        self.0.at_dd.get_or_init(|| speed.at(()).ok()).as_ref()
    }

    /// The graded route's layout for cell `cell`, built by `build(cell)` on first use: a
    /// function of the cell alone, so that what it returns does not depend on the evaluations
    /// before (a cell beyond [`GRADED_CELLS`] gets the last, whose range then refuses its k).
    pub(crate) fn graded_layout(
        &self,
        cell: usize,
        build: impl FnOnce(usize) -> Result<GradedSetup<T>>,
    ) -> Result<&GradedSetup<T>> {
        let slots = self
            .0
            .layouts
            .get_or_init(|| (0..GRADED_CELLS).map(|_| OnceLock::new()).collect());
        let c = cell.min(GRADED_CELLS - 1);
        slots[c]
            .get_or_init(|| build(c))
            .as_ref()
            .map_err(Clone::clone)
    }

    /// The slots of the seed grid's `n` nodes.
    pub(crate) fn grid(&self, n: usize) -> &[OnceLock<Option<(f64, f64)>>] {
        self.0
            .grid
            .get_or_init(|| (0..n).map(|_| OnceLock::new()).collect())
    }

    /// The k = 1 probe's slot for `method` (`None`: not kept).
    pub(crate) fn probe(&self, method: Method) -> Option<&OnceLock<Evaluation<T>>> {
        match method {
            Method::Auto => Some(&self.0.probe[0]),
            Method::Fixed => Some(&self.0.probe[1]),
            _ => None,
        }
    }
}

/// The layout cells a speed keeps (`graded::layout_cell`: k ≤ 2^180 lies in cell 182 or below).
const GRADED_CELLS: usize = 183;
