//! Sweeps: many solves at once — the ellipse (33) over points of (ν, speed, A1/B1), full contact
//! solutions over a list of problems (or of problems some of which could not be formed:
//! [`try_contacts`]), and I1, I2 of (34) over a list of axis ratios — returned in input order,
//! each point with its own result or its own typed error (one bad point never fails the others).
//!
//! **What a sweep shares.** The points are cut into blocks of [`BLOCK`] consecutive points,
//! solved in parallel on `rayon`'s pool (the global one or the caller's; a sweep of one block on
//! the calling thread). Within a block, consecutive points at the same speed share the fixed
//! rules' set-up, and each root starts from the extrapolation of up to four earlier roots of the
//! block along its curve, or from the static ellipse. [`ellipses_at`] takes speeds the caller
//! formed once, whose set-ups serve every block. Why and at what cost: docs/design.md, "Many
//! cores", and docs/performance.md.
//!
//! **Reproducibility.** A point's result depends only on its block (never on the number of
//! threads): a sweep gives the same bits on one thread and on many, and a sweep split at
//! multiples of [`BLOCK`] gives the same bits as the whole.
//!
//! Accuracy: each point as [`crate::solve_ellipse`], [`crate::ContactProblem::solve`] or
//! [`crate::integrals`] gives it, with its error bound (`tests/sweep.rs` checks every point of
//! a grid against the independent solve of the same point).
//!
//! ```
//! use moving_hertz::sweep::{self, EllipsePoint, SpeedGiven};
//! use moving_hertz::Options;
//!
//! let ratios: Vec<f64> = (0..100).map(|j| 10f64.powf(-3.0 + 6.0 * j as f64 / 99.0)).collect();
//! let points = EllipsePoint::grid(&[0.25, 0.7], &[SpeedGiven::Mr(0.9)], &ratios);
//! let solved = sweep::ellipses(&points, &Options::default());
//! assert_eq!(solved.len(), 200);
//! assert!(solved[..100].iter().all(|r| r.as_ref().is_ok_and(|e| e.k().error.to_f64() < 1e-13)));
//! assert!(solved[100..].iter().all(|r| r.is_err())); // ν = 0.7 is outside (-1, 1/2]
//! # Ok::<(), moving_hertz::Error>(())
//! ```

use crate::contact::{
    check_ratio, checked_options, ContactProblem, ContactSolution, Ellipse, Options, ShapeSolver,
};
use crate::error::{Error, Result};
use crate::estimate::RelError;
use crate::physics::{Material, Moduli, Solid, Speed};
use crate::routes::{Evaluator, IntegralOptions, Integrals};
use crate::scalar::{Precision, Real};
use std::sync::{Mutex, PoisonError};

/// The points of one block: solved one after another, sharing set-ups and continuation (module
/// docs); blocks run in parallel.
pub const BLOCK: usize = 64;

/// How a point's speed is given.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SpeedGiven<T> {
    /// M_R = V/c_R ∈ [0, 1) ([`Material::speed`]).
    Mr(T),
    /// The gap 1 − M_R ∈ (0, 1] ([`Material::speed_from_gap`]), for speeds near c_R.
    Gap(T),
    /// M_R as decimal text, the gap 1 − M_R formed exactly from it
    /// ([`Material::parse_speed`]): `"0.9999999999"` keeps its gap 10⁻¹⁰ to within ε.
    Text(String),
    /// The velocity V (m/s) in the half-space of the point's ν with these moduli
    /// ([`Solid::new`], [`Solid::speed_from_velocity`]): M_R = V/c_R, refused (naming c_R)
    /// unless 0 ≤ V < c_R.
    Velocity {
        /// V (m/s).
        velocity: T,
        /// E or μ, and ρ.
        moduli: Moduli<T>,
    },
}

/// One point of an ellipse sweep: Poisson's ratio ν, the speed and the curvature ratio
/// A1/B1 = R2/R1, as the caller gives them (checked point by point).
#[derive(Clone, Debug, PartialEq)]
pub struct EllipsePoint<T> {
    /// Poisson's ratio ν ∈ (−1, 1/2].
    pub nu: T,
    /// The speed.
    pub speed: SpeedGiven<T>,
    /// A1/B1 = R2/R1 > 0.
    pub ratio: T,
}

impl<T: Clone> EllipsePoint<T> {
    /// Every (ν, speed, A1/B1) of the three lists, ν slowest and A1/B1 fastest: a curve of
    /// A1/B1 at each (ν, speed).
    /// The inputs of (33); exact.
    pub fn grid(nus: &[T], speeds: &[SpeedGiven<T>], ratios: &[T]) -> Vec<Self> {
        let mut out = Vec::with_capacity(nus.len() * speeds.len() * ratios.len());
        for nu in nus {
            for speed in speeds {
                for ratio in ratios {
                    out.push(EllipsePoint {
                        nu: nu.clone(),
                        speed: speed.clone(),
                        ratio: ratio.clone(),
                    });
                }
            }
        }
        out
    }
}

/// Solves the ellipse (33) at every point by the options' method and tolerance (their `seed`,
/// when given, starts each block's first point), in parallel blocks with shared set-ups and
/// continuation (module docs). Returns one result per point, in input order: the [`Ellipse`]
/// of [`crate::solve_ellipse`] or that point's typed error ([`crate::Error::Domain`] /
/// [`crate::Error::NotFinite`] for its ν, speed or ratio, or the solve's own).
pub fn ellipses<T>(points: &[EllipsePoint<T>], opts: &Options<T>) -> Vec<Result<Ellipse<T>>>
where
    T: Real + Send + Sync,
{
    let worth = points
        .first()
        .map_or(1, |pt| worth::<T>(points.len(), &pt.ratio));
    in_blocks(points, worth, |block, out| {
        let mut run = Run::new(opts);
        let mut material: Option<(&T, Result<Material<T>>)> = None;
        let mut last: Option<(&EllipsePoint<T>, Result<Speed<T>>)> = None;
        for (pt, slot) in block.iter().zip(out) {
            // The speed of the last point, kept (not cloned) while the points share it.
            let speed = match &mut last {
                Some((prev, sp)) if prev.nu == pt.nu && prev.speed == pt.speed => &*sp,
                last => {
                    if !material.as_ref().is_some_and(|(nu, _)| **nu == pt.nu) {
                        material = Some((&pt.nu, Material::new(pt.nu.clone())));
                    }
                    let speed = match material.as_ref().map(|(_, m)| m) {
                        Some(Ok(mat)) => pt.speed.speed_in(mat),
                        Some(Err(e)) => Err(e.clone()),
                        None => Material::new(pt.nu.clone()).and_then(|m| pt.speed.speed_in(&m)),
                    };
                    &last.insert((pt, speed)).1
                }
            };
            *slot = run.solve_at(speed, &pt.ratio);
        }
    })
}

/// One point of [`ellipses_at`]: A1/B1 at a speed the caller formed once for every point that
/// shares it, or the error of forming it (which becomes the point's result).
#[derive(Debug)]
pub struct AtSpeed<'s, T: Real> {
    /// The speed and its material ([`SpeedGiven::speed_in`]), or the error that forming them
    /// gave.
    pub speed: &'s Result<Speed<T>>,
    /// A1/B1 = R2/R1 > 0.
    pub ratio: &'s T,
}

/// [`ellipses`] at speeds the caller formed: the same blocks, continuation and results, bit for
/// bit, as [`ellipses`] gives for the same (ν, speed, A1/B1). A speed shared by many points (the
/// same one, or clones of it) serves them in every block and on every thread, its set-ups built
/// once (what a speed keeps depends on the speed alone, never on which block filled it). One
/// result per point, in input order.
/// Implements (33) per point, each within its own bound as [`crate::solve_ellipse`].
pub fn ellipses_at<T>(points: &[AtSpeed<'_, T>], opts: &Options<T>) -> Vec<Result<Ellipse<T>>>
where
    T: Real + Send + Sync,
{
    let worth = points
        .first()
        .map_or(1, |pt| worth::<T>(points.len(), pt.ratio));
    in_blocks(points, worth, |block, out| {
        let mut run = Run::new(opts);
        for (pt, slot) in block.iter().zip(out) {
            *slot = run.solve_at(pt.speed, pt.ratio);
        }
    })
}

/// Solves every contact problem ([`ContactProblem::solve`] with `opts`) in parallel blocks,
/// the ellipses with shared set-ups and continuation along consecutive problems (module docs).
/// One result per problem, in input order.
/// Implements (26)–(33) per problem, each within its own bound as [`ContactProblem::solve`].
pub fn contacts<T>(
    problems: &[ContactProblem<T>],
    opts: &Options<T>,
) -> Vec<Result<ContactSolution<T>>>
where
    T: Real + Send + Sync,
{
    contacts_by(problems, |pb| Ok(pb), opts)
}

/// [`contacts`] over problems the caller formed point by point, some of which could not be
/// formed (a velocity at or above c_R at one point of a grid, a modulus out of range): each
/// error is that point's result, unchanged, and the other problems are solved as [`contacts`]
/// solves them (the same blocks, shared set-ups and continuation: without errors, the same
/// bits). One result per entry, in input order.
/// Implements (26)–(33) per problem, each within its own bound as [`ContactProblem::solve`].
///
/// ```
/// use moving_hertz::sweep;
/// use moving_hertz::physics::{Moduli, Solid};
/// use moving_hertz::{ContactProblem, Loading, Options};
/// // Steel (E = 210 GPa, ν = 0.3, ρ = 7850 kg/m³) at 2000 and 3000 m/s (above c_R).
/// let moduli = Moduli::Youngs { youngs_modulus: "210e9", density: "7850" };
/// let steel = Solid::<f64>::parse("0.3", moduli, ())?;
/// let problems: Vec<_> = ["2000", "3000"]
///     .iter()
///     .map(|v| {
///         Ok(ContactProblem {
///             speed: steel.parse_velocity(v)?,
///             radius_along: 0.05,
///             radius_across: 0.02,
///             loading: Loading::Load(1000.0),
///             shear_modulus: *steel.shear_modulus().expect("given by E"),
///         })
///     })
///     .collect();
/// let solved = sweep::try_contacts(&problems, &Options::default());
/// assert!(solved[0].as_ref().is_ok_and(|s| s.p0().error.to_f64() < 1e-13));
/// assert!(solved[1].as_ref().is_err_and(|e| e.to_string().contains("c_R")));
/// # Ok::<(), moving_hertz::Error>(())
/// ```
pub fn try_contacts<T>(
    problems: &[Result<ContactProblem<T>>],
    opts: &Options<T>,
) -> Vec<Result<ContactSolution<T>>>
where
    T: Real + Send + Sync,
{
    contacts_by(problems, |r| r.as_ref().map_err(Error::clone), opts)
}

/// The one loop of [`contacts`] and [`try_contacts`]: the problem of each item (or its error,
/// which becomes its result) solved with the block's [`Run`].
fn contacts_by<T, I: Sync>(
    items: &[I],
    problem: impl for<'i> Fn(&'i I) -> Result<&'i ContactProblem<T>> + Sync + Send,
    opts: &Options<T>,
) -> Vec<Result<ContactSolution<T>>>
where
    T: Real + Send + Sync,
{
    let first = items.iter().find_map(|i| problem(i).ok());
    let worth = first.map_or(1, |pb| worth::<T>(items.len(), &pb.radius_along));
    in_blocks(items, worth, |block, out| {
        let mut run = Run::new(opts);
        for (item, slot) in block.iter().zip(out) {
            *slot =
                problem(item).and_then(|pb| pb.solve_by(|speed, ratio| run.solve(speed, ratio)));
        }
    })
}

/// I1, I2 of (34) (and what `opts` asks for) at every axis ratio of `ks` for one speed, as
/// [`crate::integrals`] gives them, in parallel blocks that each keep one [`Evaluator`] (the
/// fixed rules' set-up built once a block). One result per k, in input order; an options
/// error (a tolerance below the floor, a method that cannot give what is asked) is every
/// point's.
pub fn integrals<T>(speed: &Speed<T>, ks: &[T], opts: &IntegralOptions) -> Vec<Result<Integrals<T>>>
where
    T: Real + Send + Sync,
{
    in_blocks(ks, worth::<T>(ks.len(), speed.mr()), |block, out| {
        let ev = Evaluator::new(speed, *opts);
        for (k, slot) in block.iter().zip(out) {
            *slot = ev.as_ref().map_err(Error::clone).and_then(|ev| ev.at(k));
        }
    })
}

/// [`threads_worth`] for `points` points at the precision of `x`.
fn worth<T: Real>(points: usize, x: &T) -> usize {
    threads_worth(points, &Precision::of::<T>(x.prec()))
}

/// The least work, in nanoseconds, worth a thread of its own ([`threads_worth`]).
const WORK_PER_THREAD_NS: f64 = 2e6;

/// How many threads a job of `points` sweep points at `precision` keeps busy: its estimated
/// work over 2 ms (the least work worth a thread of its own: starting, waking and first touches
/// of memory cost tens to hundreds of microseconds a thread), at least 1 (callers take the
/// smaller of this and the pool's threads). A point's cost is a floor of what a sweep point costs (about 2 µs at `f64`, 20 µs
/// at double-double, 100 µs at 128 bits and more above: docs/precision.md). Implements no
/// equation of the paper.
pub fn threads_worth(points: usize, precision: &Precision) -> usize {
    let point_ns = match precision {
        Precision::F64 => 2e3,
        Precision::DoubleDouble => 2e4,
        Precision::Mpfr(_) => 1e5 * (f64::from(precision.bits()) / 128.0).max(1.0).powf(1.5),
    };
    let threads = points as f64 * point_ns / WORK_PER_THREAD_NS;
    threads.clamp(1.0, usize::MAX as f64) as usize
}

/// Runs `solve_block` on the blocks of `items` in parallel, each writing its results into its
/// share of the output. As many copies of the loop as the pool has threads (no more than the
/// job is `worth`, [`threads_worth`]) each take the next unsolved block until none is left, so
/// that the threads finish within one block of each other. A single block runs on the calling
/// thread, where its solves may share their node loops among the cores (above 448 bits,
/// `numerics::shares`).
fn in_blocks<I: Sync, R: Send>(
    items: &[I],
    worth: usize,
    solve_block: impl Fn(&[I], &mut [Result<R>]) + Sync + Send,
) -> Vec<Result<R>> {
    let mut out: Vec<Result<R>> = (0..items.len()).map(|_| Err(unsolved())).collect();
    if items.len() <= BLOCK {
        solve_block(items, &mut out);
        return out;
    }
    let copies = (rayon::current_num_threads().min(items.len().div_ceil(BLOCK))).min(worth);
    // The blocks with their shares of the output, handed out one pair at a time.
    let blocks = Mutex::new(items.chunks(BLOCK).zip(out.chunks_mut(BLOCK)));
    let take_blocks = || loop {
        let next = blocks.lock().unwrap_or_else(PoisonError::into_inner).next();
        let Some((block, share)) = next else {
            break;
        };
        solve_block(block, share);
    };
    rayon::scope(|scope| {
        for _ in 0..copies {
            scope.spawn(|_| take_blocks());
        }
    });
    out
}

/// Binds the calling thread to the `index`-th (from 0) of the CPUs it may run on now, and
/// returns whether it did: `false` when there is no such CPU, when the operating system refuses,
/// and on systems other than Linux. Meant for a pool's start handler, so that each thread of a
/// pool of at most as many threads as CPUs runs on a CPU of its own (module docs):
///
/// ```
/// let pool = rayon::ThreadPoolBuilder::new()
///     .num_threads(2)
///     .start_handler(|i| {
///         moving_hertz::sweep::bind_to_cpu(i);
///     })
///     .build()
///     .expect("a pool of two threads");
/// # let _ = pool;
/// ```
///
/// A thread keeps its binding for life, and threads it starts inherit it; a pool with more
/// threads than CPUs should not bind (its extra threads would find no CPU of their own).
/// Implements no equation of the paper.
pub fn bind_to_cpu(index: usize) -> bool {
    #[cfg(target_os = "linux")]
    {
        // SAFETY: `cpu_set_t` is a plain bit array, valid when zeroed; both calls read or write
        // exactly `size_of::<cpu_set_t>()` bytes of the set they are given, and pid 0 names the
        // calling thread.
        unsafe {
            let size = std::mem::size_of::<libc::cpu_set_t>();
            let mut allowed: libc::cpu_set_t = std::mem::zeroed();
            if libc::sched_getaffinity(0, size, &mut allowed) != 0 {
                return false;
            }
            let cpus = 0..libc::CPU_SETSIZE as usize;
            let Some(cpu) = cpus.filter(|&c| libc::CPU_ISSET(c, &allowed)).nth(index) else {
                return false;
            };
            let mut one: libc::cpu_set_t = std::mem::zeroed();
            libc::CPU_SET(cpu, &mut one);
            libc::sched_setaffinity(0, size, &one) == 0
        }
    }
    #[cfg(not(target_os = "linux"))]
    {
        let _ = index;
        false
    }
}

/// The placeholder of a result before its block writes it (every block writes each of its
/// slots; cheap to make: no allocation).
fn unsolved() -> Error {
    Error::Internal {
        what: "a sweep point left unsolved",
    }
}

impl<T: Real> SpeedGiven<T> {
    /// The speed in the material `mat` (of the point's ν), from its M_R, gap or velocity
    /// ([`Material::speed`], [`Material::speed_from_gap`], [`Material::parse_speed`],
    /// [`Solid::speed_from_velocity`], and their typed errors): what [`ellipses`] solves a
    /// point at, and what [`ellipses_at`] takes formed. Equations and accuracy (of M_R and its
    /// gap 1 − M_R) as those.
    pub fn speed_in(&self, mat: &Material<T>) -> Result<Speed<T>> {
        match self {
            SpeedGiven::Mr(mr) => mat.speed(mr.clone()),
            SpeedGiven::Gap(gap) => mat.speed_from_gap(gap.clone()),
            SpeedGiven::Text(mr) => mat.parse_speed(mr),
            SpeedGiven::Velocity { velocity, moduli } => {
                Solid::new(mat, moduli.clone())?.speed_from_velocity(velocity.clone())
            }
        }
    }
}

/// One block's solves: the solver of the current speed (its set-ups kept while the speed
/// stays) and the trail of the block's roots for the next start.
struct Run<'o, T: Real + 'static> {
    opts: &'o Options<T>,
    /// The solver of the current speed, with ν and ln(1 − M_R) of that speed for the trail's
    /// places.
    solver: Option<(ShapeSolver<T>, f64, f64)>,
    trail: Trail,
}

impl<'o, T: Real> Run<'o, T> {
    fn new(opts: &'o Options<T>) -> Self {
        Run {
            opts,
            solver: None,
            trail: Trail::default(),
        }
    }

    /// [`Run::solve`] at a speed that may have failed to form (its error is the result).
    #[inline]
    fn solve_at(&mut self, speed: &Result<Speed<T>>, ratio: &T) -> Result<Ellipse<T>> {
        match speed {
            Ok(sp) => self.solve(sp, ratio),
            Err(e) => Err(e.clone()),
        }
    }

    /// The ellipse at `speed` and `ratio`, as [`crate::solve_ellipse`] with the run's options,
    /// started from the trail's guess.
    fn solve(&mut self, speed: &Speed<T>, ratio: &T) -> Result<Ellipse<T>> {
        check_ratio(ratio)?;
        let tol = checked_options(self.opts, ratio.prec())?;
        if !self
            .solver
            .as_ref()
            .is_some_and(|(s, _, _)| same_speed(s.speed(), speed))
        {
            self.solver = None;
        }
        let (solver, nu, ln_gap) = match &mut self.solver {
            Some(s) => s,
            empty => empty.insert((
                ShapeSolver::new(speed, self.opts.method)?,
                speed.material().nu().to_f64(),
                // From the exponent: a gap below the f64 range (at MPFR) keeps its own value.
                RelError::of(speed.gap()).log2() * std::f64::consts::LN_2,
            )),
        };
        let at = Place {
            nu: *nu,
            ln_gap: *ln_gap,
            ln_ratio: ratio.to_f64().ln(),
        };
        let seed = self.opts.seed.as_ref().map(|s| s.to_f64());
        let guess = self.trail.guess(&at).or(seed);
        let shape = solver.solve(ratio, tol, None, guess)?;
        let ellipse = shape.publish()?;
        self.trail.push(at, ellipse.k.value.to_f64());
        Ok(ellipse)
    }
}

/// Whether two speeds are the same (material and M_R, bit for bit).
fn same_speed<T: Real>(a: &Speed<T>, b: &Speed<T>) -> bool {
    a.material().nu() == b.material().nu() && a.mr() == b.mr() && a.gap() == b.gap()
}

/// Where a point lies, for continuation: ν, ln(1 − M_R) and ln(A1/B1) in `f64`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Place {
    nu: f64,
    ln_gap: f64,
    ln_ratio: f64,
}

/// The roots a trail keeps: a cubic through four roots starts most points of a smooth curve
/// close enough for one evaluation (the evidence: docs/calibration.md).
const TRAIL: usize = 4;
// [`lagrange`] takes up to four points.
const _: () = assert!(TRAIL <= 4);

/// The last roots of a block (at most [`TRAIL`], oldest first), for the next point's start.
#[derive(Default)]
struct Trail {
    roots: [(Place, f64); TRAIL],
    len: usize,
}

impl Trail {
    /// A start for the point at `at`: ln k extrapolated (a polynomial through up to [`TRAIL`]
    /// earlier roots) along the coordinate that varies — ln(A1/B1) at one speed, ln(1 − M_R) at
    /// one A1/B1 — or the last root where neither holds; `None` for a block's first point.
    fn guess(&self, at: &Place) -> Option<f64> {
        let roots = &self.roots[..self.len];
        let &(last, ln_k) = roots.last()?;
        let by_ratio = last.ln_gap == at.ln_gap;
        // The abscissa along the curve, and the other coordinates that stay on it.
        let x = |p: &Place| match by_ratio {
            true => (p.ln_ratio, p.ln_gap),
            false => (p.ln_gap, p.ln_ratio),
        };
        let (t, at_fixed) = x(at);
        // The roots on the curve, most recent first.
        let (mut xs, mut ys, mut n) = ([0.0; TRAIL], [0.0; TRAIL], 0);
        for (p, y) in roots.iter().rev() {
            let (xp, fp) = x(p);
            if p.nu != at.nu || fp != at_fixed {
                break;
            }
            (xs[n], ys[n]) = (xp, *y);
            n += 1;
        }
        let predicted = lagrange(&xs[..n], &ys[..n], t).filter(|y| (y - ln_k).abs() <= 2.0);
        Some(predicted.unwrap_or(ln_k).exp())
    }

    fn push(&mut self, at: Place, k: f64) {
        if self.len == TRAIL {
            self.roots.rotate_left(1);
            self.len -= 1;
        }
        self.roots[self.len] = (at, k.ln());
        self.len += 1;
    }
}

/// The polynomial through (`xs`, `ys`) (distinct abscissae; `None` otherwise or when empty)
/// at `t`, in Lagrange's form (each weight the product of (t − x_j)/(x_i − x_j) in the order of
/// the points), by [`lagrange_n`] for the number of points (its loops unrolled).
fn lagrange(xs: &[f64], ys: &[f64], t: f64) -> Option<f64> {
    fn by<const N: usize>(xs: &[f64], ys: &[f64], t: f64) -> Option<f64> {
        lagrange_n::<N>(xs.first_chunk()?, ys.first_chunk()?, t)
    }
    match xs.len().min(ys.len()) {
        1 => by::<1>(xs, ys, t),
        2 => by::<2>(xs, ys, t),
        3 => by::<3>(xs, ys, t),
        4 => by::<4>(xs, ys, t),
        _ => None,
    }
}

/// [`lagrange`] through `N` points.
#[inline]
fn lagrange_n<const N: usize>(xs: &[f64; N], ys: &[f64; N], t: f64) -> Option<f64> {
    let dt = xs.map(|x| t - x);
    let mut sum = 0.0;
    for i in 0..N {
        let mut w = 1.0;
        for j in 0..N {
            if i != j {
                if xs[i] == xs[j] {
                    return None;
                }
                w *= dt[j] / (xs[i] - xs[j]);
            }
        }
        sum += w * ys[i];
    }
    sum.is_finite().then_some(sum)
}

#[cfg(test)]
#[path = "../tests/unit/sweep.rs"]
mod tests;
