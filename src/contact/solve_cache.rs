//! What the ellipse solves at one speed keep with it (`Speed::solve_cache`): the speed at the
//! precision ladder's lower stages, the ellipse solve's seed grid and k = 1 probe, and the
//! graded route's layouts. Each slot is filled on first use and never changes, so that what a solve returns
//! does not depend on the solves before it (`tests/solve_cache.rs`).

use crate::error::Result;
use crate::physics::Speed;
use crate::routes::graded::GradedSetup;
use crate::routes::{Evaluation, Method};
use crate::scalar::{Dd, Real};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, OnceLock};

/// What the ellipse solves at one speed keep, with the speed and shared by its clones: the speed
/// at `f64` and double-double (the lower ladder stages, whose set-ups then serve every solve),
/// the grid seed's nodes and the graded route's layouts.
#[derive(Clone, Debug)]
pub(crate) struct SolveCache<T: Real>(Arc<Kept<T>>);

/// The graded route's layouts, one slot for each cell of k in chunks of [`CHUNK`] made on
/// first use: a speed made for one solve touches a chunk or two, where making and dropping
/// a slot for each of the 183 cells cost it about 3,000 instructions.
type Layouts<T> = [OnceLock<Box<[OnceLock<Result<GradedSetup<T>>>; CHUNK]>>; LAYOUT_CHUNKS];

const CHUNK: usize = 8;

/// A node of the seed grid: F + ln(A1/B1) and F′ as `f64` bits, filled on first use, F′
/// stored last and read first, its bits 0 while empty (a node's F′ is positive; a node whose
/// evaluation fails is not kept). Atomics, not a `OnceLock`: nothing to drop, where dropping
/// 127 `OnceLock`s cost a speed made for one solve 1,000 instructions.
#[derive(Debug, Default)]
pub(crate) struct GridSlot([AtomicU64; 2]);

impl GridSlot {
    /// The node's values (`None`: not kept yet).
    #[inline]
    pub(crate) fn get(&self) -> Option<(f64, f64)> {
        let d = self.0[1].load(Ordering::Acquire);
        let value = || f64::from_bits(self.0[0].load(Ordering::Relaxed));
        (d != 0).then(|| (value(), f64::from_bits(d)))
    }

    /// Keeps `v` (a pure function of the node, so that a race between two threads stores the
    /// same bits twice) and returns it.
    #[cold]
    pub(crate) fn fill(&self, v: Option<(f64, f64)>) -> Option<(f64, f64)> {
        if let Some((g, d)) = v {
            self.0[0].store(g.to_bits(), Ordering::Relaxed);
            self.0[1].store(d.to_bits(), Ordering::Release);
        }
        v
    }
}

#[derive(Debug)]
struct Kept<T: Real> {
    at_f64: OnceLock<Option<Speed<f64>>>,
    at_dd: OnceLock<Option<Speed<Dd>>>,
    /// The k = 1 probe's evaluation by method (auto, fixed): it does not depend on A1/B1 (it
    /// still counts as an evaluation, so that a solve's steps do not depend on whether it was
    /// kept).
    probe: [OnceLock<Evaluation<T>>; 2],
    /// F + ln(A1/B1) and F′ at the nodes of the ellipse solve's grid seed, each on first use.
    grid: OnceLock<Box<[GridSlot]>>,
    /// The graded route's layouts by cell of k (`graded::layout_cell`), each on first use.
    layouts: OnceLock<Box<Layouts<T>>>,
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
        let c = cell.min(GRADED_CELLS - 1);
        let chunks = self.0.layouts.get_or_init(Default::default);
        let chunk = chunks[c / CHUNK].get_or_init(Default::default);
        chunk[c % CHUNK]
            .get_or_init(|| build(c))
            .as_ref()
            .map_err(Clone::clone)
    }

    /// The slots of the seed grid's `n` nodes.
    pub(crate) fn grid(&self, n: usize) -> &[GridSlot] {
        self.0
            .grid
            .get_or_init(|| (0..n).map(|_| Default::default()).collect())
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
const LAYOUT_CHUNKS: usize = GRADED_CELLS.div_ceil(CHUNK);
