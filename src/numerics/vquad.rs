//! Adaptive Gauss–Legendre quadrature of a vector of integrands that share their expensive part
//! (several integrals of the same Green's function against different weights): one call of `f`
//! per node returns all `N` integrand values.
//!
//! The algorithm is that of [`crate::numerics::quadrature::integrate`] applied componentwise:
//! every panel is integrated by the n-point rule on its two halves, its error estimate per
//! component is the discrepancy with the one-panel rule, and the panel whose worst component
//! (relative to that component's threshold) is largest is split, until every component meets
//! `max(tol·|I_c|, 4ε·Σ|I_c,panel|)` or the evaluation cap is reached ([`Error::NoConvergence`]).
//!
//! No item of this module implements a formula of the paper: it is the adaptive vector quadrature
//! under the direct route's (46)–(47) and J0 of (32), to the relative tolerance stated above or a
//! typed error.

use crate::error::{Error, Result};
use crate::numerics::quadrature::{GaussLegendre, Limits};
use crate::scalar::{short, Real};

/// Values and error estimates of `N` integrals.
#[derive(Clone, Debug)]
pub struct VecQuadrature<T, const N: usize> {
    /// The integrals.
    pub values: [T; N],
    /// Absolute error estimates (panel discrepancies plus a rounding allowance ε·Σ|panel|).
    pub errors: [T; N],
    /// Calls of `f`.
    pub evaluations: usize,
}

struct Panel<T, const N: usize> {
    a: T,
    b: T,
    left: [T; N],
    right: [T; N],
    err: [T; N],
}

fn rule_on<T: Real, const N: usize, F: FnMut(&T) -> [T; N]>(
    rule: &GaussLegendre<T>,
    f: &mut F,
    a: &T,
    b: &T,
) -> Result<[T; N]> {
    let p = a.prec();
    let half = (b.clone() - a).mul_pow2(-1);
    let mid = (b.clone() + a).mul_pow2(-1);
    let mut acc: [T; N] = std::array::from_fn(|_| T::zero(p));
    for (x, w) in rule.nodes().iter().zip(rule.weights()) {
        let mut add = |v: [T; N]| {
            for (s, vi) in acc.iter_mut().zip(v) {
                *s += vi * w;
            }
        };
        if x.is_zero() {
            add(f(&mid));
        } else {
            let dx = half.clone() * x;
            add(f(&(mid.clone() - &dx)));
            add(f(&(mid.clone() + &dx)));
        }
    }
    for s in acc.iter_mut() {
        *s *= &half;
        if !s.is_finite() {
            return Err(Error::NotFinite {
                name: "integrand",
                value: short(s),
            });
        }
    }
    Ok(acc)
}

/// Integrates the `N` components of `f` over the breakpoints `points` (increasing) to relative
/// tolerance `tol` each (0: the precision's floor). See the module docs.
pub fn integrate_vec<T: Real, const N: usize, F: FnMut(&T) -> [T; N]>(
    f: F,
    points: &[T],
    tol: &T,
    limits: Limits,
) -> Result<VecQuadrature<T, N>> {
    let zero = std::array::from_fn(|_| T::zero(tol.prec()));
    integrate_vec_plus(f, points, &zero, tol, limits)
}

/// `c_c + ∫f_c` for each component, by [`integrate_vec`] with each threshold judged against the
/// sum, `max(tol·|c_c + I_c|, 4ε·(|c_c| + Σ|I_c,panel|))` (as
/// [`crate::numerics::quadrature::integrate_plus`]: for remainders after parts taken out in
/// closed form). The returned values include the `c_c`, the errors are the quadrature's.
pub fn integrate_vec_plus<T: Real, const N: usize, F: FnMut(&T) -> [T; N]>(
    mut f: F,
    points: &[T],
    offsets: &[T; N],
    tol: &T,
    limits: Limits,
) -> Result<VecQuadrature<T, N>> {
    let p = tol.prec();
    if points.len() < 2 || points.windows(2).any(|w| w[1] <= w[0]) {
        return Err(Error::Domain {
            name: "quadrature breakpoints",
            value: format!("{} points", points.len()),
            bound: "at least two, strictly increasing",
        });
    }
    let n = limits.gauss_order(T::bits(p));
    let rule = GaussLegendre::<T>::get(n, p)?;
    let eps = T::epsilon(p);
    let mut evals = 0usize;
    let mut make = |a: T, b: T, whole: Option<[T; N]>, evals: &mut usize| -> Result<Panel<T, N>> {
        let whole = match whole {
            Some(w) => w,
            None => {
                *evals += n;
                rule_on(&rule, &mut f, &a, &b)?
            }
        };
        let m = (a.clone() + &b).mul_pow2(-1);
        *evals += 2 * n;
        let left = rule_on(&rule, &mut f, &a, &m)?;
        let right = rule_on(&rule, &mut f, &m, &b)?;
        let err = std::array::from_fn(|c| (whole[c].clone() - &left[c] - &right[c]).abs());
        Ok(Panel {
            a,
            b,
            left,
            right,
            err,
        })
    };
    let mut panels: Vec<Panel<T, N>> = Vec::new();
    for w in points.windows(2) {
        panels.push(make(w[0].clone(), w[1].clone(), None, &mut evals)?);
    }
    loop {
        // Totals per component.
        let mut val: [T; N] = offsets.clone();
        let mut err: [T; N] = std::array::from_fn(|_| T::zero(p));
        let mut l1: [T; N] = std::array::from_fn(|c| offsets[c].clone().abs());
        for q in &panels {
            for c in 0..N {
                let v = q.left[c].clone() + &q.right[c];
                l1[c] += &v.clone().abs();
                val[c] += &v;
                err[c] += &q.err[c];
            }
        }
        let thr: [T; N] = std::array::from_fn(|c| {
            (tol.clone() * &val[c].clone().abs()).max_of(l1[c].clone().mul_i64(4) * &eps)
                + &T::min_positive(p)
        });
        if (0..N).all(|c| err[c] <= thr[c]) {
            let errors = std::array::from_fn(|c| {
                err[c].clone() + &((l1[c].clone() - &offsets[c].clone().abs()) * &eps)
            });
            return Ok(VecQuadrature {
                values: val,
                errors,
                evaluations: evals,
            });
        }
        // Split the panel with the largest error relative to the thresholds.
        let score = |q: &Panel<T, N>| -> T {
            (0..N)
                .map(|c| q.err[c].clone() / &thr[c])
                .fold(T::zero(p), |m, x| m.max_of(x))
        };
        let (idx, _) = panels.iter().enumerate().map(|(i, q)| (i, score(q))).fold(
            (0usize, T::zero(p)),
            |best, cur| if cur.1 > best.1 { cur } else { best },
        );
        let q = panels.swap_remove(idx);
        let m = (q.a.clone() + &q.b).mul_pow2(-1);
        if evals + 4 * n > limits.max_evals || !(m > q.a && m < q.b) {
            let worst = (0..N)
                .map(|c| err[c].clone() / &(val[c].clone().abs() + &T::min_positive(p)))
                .fold(T::zero(p), |m, x| m.max_of(x));
            return Err(Error::NoConvergence {
                what: "adaptive vector Gauss-Legendre quadrature",
                iterations: evals,
                reached: short(&worst),
            });
        }
        panels.push(make(q.a.clone(), m.clone(), Some(q.left), &mut evals)?);
        panels.push(make(m, q.b, Some(q.right), &mut evals)?);
    }
}
