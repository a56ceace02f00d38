//! The one evaluator of I1, I2 (and, on request, their k-derivatives and J0) at the working
//! precision: [`integrals`] for one k, [`Evaluator`] for many k at one speed (the fixed rules'
//! k-independent set-up kept between calls).
//!
//! **Which route runs.** One table (`Evaluator::route_for`) serves users and the ellipse
//! solve alike. [`Method::Auto`] picks, for the axis ratio k and the tolerance t asked for
//! (none: the working precision's floor), the first row that applies:
//!
//! | k | t | derivatives | route |
//! |---|---|---|---|
//! | k ≤ 1 | none, or ≥ 16ε | either | [`Route::FixedRule`] (a-priori bound 16ε) |
//! | 1 < k ≤ 2¹⁸⁰ | none, or ≥ 32ε | either | [`Route::GradedRule`] (32ε) |
//! | k ≤ 1 | (so 12ε ≤ t < 16ε) | no | [`Route::AdaptiveSubtracted`] ((48), its estimate) |
//! | any | any | either | [`Route::Adaptive`] (its estimate) |
//!
//! A route that fails returns its error; no other route is tried. J0 comes with the
//! derivatives from [`Route::Adaptive`] (one evaluation of G serves all five integrals), and
//! otherwise as k² I1 + I2 from the route's I1, I2 (their integrands add up to J0's), so that
//! I1 and I2 do not depend on whether J0 is asked for. A named method runs that route, and a
//! request it cannot serve is refused before any work: the series and the adaptive subtracted
//! route give no derivatives, the subtracted one and the fixed rules have a range of k, and no
//! route goes below [`FLOOR_EPS`]·ε of the working precision.

use super::fast;
use super::graded::{self, GradedSetup};
use super::series::{self, SeriesOptions};
use super::{
    beyond_exponent_range, direct, j0_from_pair, AxisRatio, Evaluation, Integrals, Method, Route,
};
use crate::error::{Error, Result};
use crate::estimate::RelError;
use crate::numerics::quadrature::name_the_input;
use crate::physics::Speed;
use crate::scalar::{short, Precision, Real};

/// Options of [`integrals`] and [`Evaluator`]; every field has a default.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct IntegralOptions {
    /// The route ([`Method::Auto`] by default).
    pub method: Method,
    /// The relative accuracy wanted for I1 and I2; `None` (the default) asks for the working
    /// precision's floor. Below [`FLOOR_EPS`]·ε of the working precision: [`Error::Unreachable`] before any
    /// work (a higher precision reaches it: [`crate::integrals_to_tolerance`] picks one).
    pub tolerance: Option<RelError>,
    /// Also ∂I1/∂k and ∂I2/∂k (differentiated under the integral sign on the same nodes).
    pub derivatives: bool,
    /// Also J0 of (32) (the approach integral): with the derivatives by the adaptive route,
    /// otherwise as k² I1 + I2 from the route's I1, I2, with their bound and three roundings.
    pub j0: bool,
}

/// The smallest tolerance any route meets, in units of ε of the working precision.
pub const FLOOR_EPS: u32 = 12;

/// Evaluates I1, I2 at many axis ratios for one speed: the fixed rules' k-independent part
/// (G at every node) is built on first use and kept with the speed (shared by its clones, so that
/// every evaluator and ellipse solve at that speed reuses it), so that a further k costs a square
/// root and a division a node. The evaluator keeps its own copy of the speed.
///
/// ```
/// use moving_hertz::{Evaluator, IntegralOptions, Material};
/// let speed = Material::new(0.25)?.speed(0.5)?;
/// let ev = Evaluator::new(&speed, IntegralOptions::default())?;
/// for k in [0.25, 0.5, 1.0, 2.0] {
///     let r = ev.at(&k)?;
///     assert!(r.i1.error.to_f64() < 1e-14);
/// }
/// # Ok::<(), moving_hertz::Error>(())
/// ```
pub struct Evaluator<T: Real + 'static> {
    speed: Speed<T>,
    opts: IntegralOptions,
    /// The tolerance at the working precision (`None`: its floor).
    tol: Option<T>,
}

/// I1, I2 of (34) (normalisation of (37)) at the axis ratio `k` = b/a for the speed (and
/// material) `speed`, by the route of `opts` (module docs).
///
/// Accuracy: relative error of each returned quantity below its bound (fixed rules: 16ε, 32ε,
/// derivatives 128ε, 32ε; adaptive routes: their estimate, a few ε; series: its tail bound),
/// and within `opts.tolerance` when one is given.
///
/// ```
/// use moving_hertz::{integrals, IntegralOptions, Material, Method, Route};
/// let speed = Material::new(0.25)?.parse_speed("0.999")?;
/// let opts = IntegralOptions { method: Method::Adaptive, j0: true, ..Default::default() };
/// let r = integrals(&speed, &0.5, &opts)?;
/// assert_eq!(r.route, Route::Adaptive);
/// assert!(r.j0.is_some() && r.i2.value > r.i1.value);
/// # Ok::<(), moving_hertz::Error>(())
/// ```
pub fn integrals<T: Real>(speed: &Speed<T>, k: &T, opts: &IntegralOptions) -> Result<Integrals<T>> {
    Evaluator::new(speed, *opts)?.at(k)
}

impl<T: Real> Evaluator<T> {
    /// The evaluator for `speed` with `opts`; [`Error::Unreachable`] for a tolerance below
    /// [`FLOOR_EPS`]·ε, [`Error::Unsupported`] for a method that cannot give what `opts` asks for.
    /// Evaluates (34) (normalisation of (37)) by the routes of the module docs.
    pub fn new(speed: &Speed<T>, opts: IntegralOptions) -> Result<Self> {
        let p = speed.mr().prec();
        check_method(&opts)?;
        let tol = match opts.tolerance {
            Some(t) => {
                let floor = RelError::eps::<T>(FLOOR_EPS, p);
                if t < floor {
                    return Err(Error::Unreachable {
                        what: "I1, I2",
                        tolerance: t.to_string(),
                        reason: format!(
                            "below {FLOOR_EPS} eps = {floor} at {}; a higher precision reaches it",
                            Precision::of::<T>(p)
                        ),
                    });
                }
                Some(t.to_real::<T>(p))
            }
            None => None,
        };
        Ok(Evaluator {
            speed: speed.clone(),
            opts,
            tol,
        })
    }

    /// I1, I2 (and what the options ask for) at the axis ratio `k` = b/a > 0.
    /// I1, I2 of (34) in the normalisation of (37), k-derivatives of (34) and J0 of (32); each with
    /// the route's bound (16ε fixed rule, 32ε graded rule, the tolerance for the adaptive routes).
    pub fn at(&self, k: &T) -> Result<Integrals<T>> {
        let axes = AxisRatio::new(k.clone())?;
        let route = self.route_for(&axes, self.opts.derivatives)?;
        let r = self.run(route, &axes, self.opts.derivatives)?;
        self.check_tolerance(&r)?;
        self.with_j0(r, &axes).publish(&axes.k)
    }

    /// J0 of (32) added to a route's result that lacks it, when asked for: k² I1 + I2 from the
    /// route's own I1, I2 ([`j0_from_pair`]: their bound and three roundings), which joins the
    /// k-derivatives' bound (`extra_error`, the larger of the two). Dropped when not asked for
    /// (the adaptive route computes it with the derivatives, on its own nodes).
    fn with_j0(&self, mut r: Evaluation<T>, axes: &AxisRatio<T>) -> Evaluation<T> {
        if !self.opts.j0 {
            r.j0 = None;
            return r;
        }
        if r.j0.is_some() {
            return r;
        }
        let p = axes.k.prec();
        let pair_error = RelError::of(&r.error_estimate);
        let j = j0_from_pair(&axes.k, &r.i1, &r.i2, pair_error);
        r.extra_error = r.extra_error.max_of(j.error.to_real::<T>(p));
        r.j0 = Some(j.value);
        r
    }

    /// The route for `axes`, with k-derivatives when `dk` asks for them: the one routing
    /// table, for users ([`Evaluator::at`]) and the ellipse solve ([`Evaluator::for_newton`])
    /// alike (the rule for [`Method::Auto`]: module docs). Checked against the method's domain
    /// before any work.
    #[inline]
    fn route_for(&self, axes: &AxisRatio<T>, dk: bool) -> Result<Route> {
        let p = axes.k.prec();
        let one = T::one(p);
        let below = axes.k <= one;
        let fixed_range = below || in_fixed_range(&axes.k);
        let bound_ok = |eps: i64| {
            self.tol
                .as_ref()
                .is_none_or(|t| T::epsilon(p).mul_i64(eps) <= *t)
        };
        Ok(match self.opts.method {
            Method::Auto if fixed_range && below && bound_ok(fast::BOUND_EPS) => Route::FixedRule,
            Method::Auto if fixed_range && !below && bound_ok(graded::BOUND_EPS) => {
                Route::GradedRule
            }
            Method::Auto if below && !dk => Route::AdaptiveSubtracted,
            Method::Auto | Method::Adaptive => Route::Adaptive,
            Method::Series => Route::Series,
            Method::AdaptiveSubtracted if below => Route::AdaptiveSubtracted,
            Method::AdaptiveSubtracted => {
                return Err(domain(axes, "(0, 1] for adaptive-subtracted"))
            }
            Method::Fixed if !fixed_range => return Err(domain(axes, "(0, 2^180] for fixed")),
            Method::Fixed => {
                let (r, bound) = if below {
                    (Route::FixedRule, fast::BOUND_EPS)
                } else {
                    (Route::GradedRule, graded::BOUND_EPS)
                };
                if !bound_ok(bound) {
                    return Err(self.unreachable(bound));
                }
                r
            }
        })
    }

    /// The tolerance is below a fixed rule's bound.
    fn unreachable(&self, bound: i64) -> Error {
        Error::Unreachable {
            what: "I1, I2 by the fixed rules",
            tolerance: self.opts.tolerance.unwrap_or(RelError::ZERO).to_string(),
            reason: format!("the rules' bound is {bound} eps of the working precision"),
        }
    }

    /// Runs `route` at `axes`, with k-derivatives when `dk` asks for them.
    #[inline]
    fn run(&self, route: Route, axes: &AxisRatio<T>, dk: bool) -> Result<Evaluation<T>> {
        let sp = &self.speed;
        let p = axes.k.prec();
        // The adaptive routes aim at half the tolerance (their estimate must meet it).
        let tol = self
            .tol
            .clone()
            .map_or_else(|| T::zero(p), |t| t.mul_pow2(-1));
        let r = match route {
            Route::FixedRule => self.fixed(axes, dk),
            Route::GradedRule => self.graded(axes, dk),
            Route::Adaptive if dk => direct::contact_integrals(sp, axes, &tol),
            Route::Adaptive => direct::quadrature(sp, axes, &tol),
            Route::AdaptiveSubtracted => direct::subtracted(sp, axes, &tol),
            Route::Series => {
                let opts = SeriesOptions {
                    rel_tol: self.tol.is_some().then_some(tol),
                    ..Default::default()
                };
                series::integrals(sp, axes, &opts)
            }
        };
        // An integrand that left the exponent range: the refusal of k, as the user gave it.
        r.map_err(|e| name_the_input(e, || beyond_exponent_range(&axes.k)))
    }

    /// [`Error::Unreachable`] when a result's estimate misses the tolerance asked for.
    fn check_tolerance(&self, r: &Evaluation<T>) -> Result<()> {
        match (&self.tol, self.opts.tolerance) {
            (Some(t), Some(tol)) if r.error_estimate > *t => Err(Error::Unreachable {
                what: "I1, I2",
                tolerance: tol.to_string(),
                reason: format!(
                    "the {} route's estimate is {}",
                    r.route,
                    RelError::of(&r.error_estimate)
                ),
            }),
            _ => Ok(()),
        }
    }

    /// The fixed rule at k ≤ 1 from the speed's k-independent part, built on first use and kept
    /// with the speed ([`Speed`]'s set-up cache, shared by its clones).
    #[inline]
    pub(crate) fn fixed(&self, axes: &AxisRatio<T>, dk: bool) -> Result<Evaluation<T>> {
        self.speed
            .fast_setup()
            .as_ref()
            .map_err(Clone::clone)?
            .run(axes, dk)
    }

    /// The graded rule at k > 1 on the layout of k's cell ([`graded::layout_cell`]), built on
    /// first use and kept with the speed (shared by its clones): a function of k alone.
    #[inline(never)]
    pub(crate) fn graded(&self, axes: &AxisRatio<T>, dk: bool) -> Result<Evaluation<T>> {
        let cell = graded::layout_cell(&axes.k)?;
        let sp = &self.speed;
        let g = sp
            .solve_cache()
            .graded_layout(cell, |c| GradedSetup::for_cell(sp, c))?;
        g.eval(axes, dk)
    }

    /// The ellipse solve's evaluation at a Newton iterate: I1, I2 and, with `dk`, their
    /// k-derivatives, by the route [`Evaluator::route_for`] gives (an error of that route is
    /// returned). The adaptive route forms the k-derivatives from the same evaluation of G as
    /// the integrals, and gives them always.
    #[inline]
    pub(crate) fn for_newton(&self, axes: &AxisRatio<T>, dk: bool) -> Result<Evaluation<T>> {
        let route = self.route_for(axes, dk)?;
        self.run(route, axes, dk || route == Route::Adaptive)
    }

    /// The method the options name.
    pub(crate) fn method(&self) -> Method {
        self.opts.method
    }

    /// The speed this evaluator serves.
    /// The M_R of (34); exact.
    pub fn speed(&self) -> &Speed<T> {
        &self.speed
    }
}

/// Whether k lies in the fixed rules' range k ≤ 2^180 ([`graded::K_MAX_LOG2`]; the fixed rule
/// serves every k ≤ 1 that [`AxisRatio`] admits).
pub(crate) fn in_fixed_range<T: Real>(k: &T) -> bool {
    *k <= T::one(k.prec()).mul_pow2(graded::K_MAX_LOG2)
}

fn domain<T: Real>(axes: &AxisRatio<T>, bound: &'static str) -> Error {
    Error::domain("axis ratio k for the method", short(&axes.k), bound)
}

/// What each method can give: the series and the adaptive subtracted route no derivatives
/// ([`Error::Unsupported`]; every method gives J0: [`Evaluator::with_j0`]).
fn check_method(opts: &IntegralOptions) -> Result<()> {
    match opts.method {
        Method::Series | Method::AdaptiveSubtracted if opts.derivatives => {
            Err(Error::Unsupported {
                what: "the k-derivatives of I1, I2",
                method: opts.method.label(),
                reason: "auto, adaptive and fixed give them",
            })
        }
        _ => Ok(()),
    }
}
