//! Symbolic mode: the paper's coefficients as exact rational functions, derived by the same
//! generic code that runs the recurrences at `f64`, double-double and MPFR, here over
//! [`RatFunc`] (a rational function of one variable over ℚ in lowest terms, a [`FieldOps`]
//! backend; design: `docs/design.md`, "Symbolic mode"): [`GreenSeries`] (36) gives F_n(ν)
//! ([`green_coefficients`]), [`KeForm`] (40), (42) gives α_n … δ_n(e²) ([`moment_forms`]).
//!
//! Both are exact: substituting a rational ν (or e²) gives, bit for bit, the `Rational` run of the
//! same recurrence (`tests/symbolic.rs`), and `tools/gen_symbolic.py` derives the same functions
//! independently with sympy. [`printed_f1`], [`printed_f2`] are the paper's starting values as
//! printed (`docs/errata.md` #2); [`render`] writes text, LaTeX, sympy input or JSON;
//! [`ke_condition`] and [`pole_terms`] say what the closed forms imply for the K, E basis. The
//! work grows about as n³ (`benches/symbolic.rs`), hence [`MAX_COEFFICIENT_INDEX`] and
//! [`MAX_MOMENT_INDEX`].

mod poly;
mod ratfunc;
mod render;

pub use poly::Poly;
pub use ratfunc::RatFunc;
pub use render::{coefficient_items, expression, moment_items, render, Named, Style, Variable};

use crate::error::{Error, Result};
use crate::numerics::elliptic::ellipke_mc;
use crate::routes::moments::{moments, KeForm, KeTerm};
use crate::routes::GreenSeries;
use crate::scalar::{Field, FieldOps, Real};
use rug::{Float, Rational};

/// Largest n accepted by [`green_coefficients`]: F_0 … F_120 are derived and printed in about
/// a second (the time grows about as n³).
pub const MAX_COEFFICIENT_INDEX: usize = 120;
/// Largest n accepted by [`moment_forms`]: α_n … δ_n up to n = 150 are derived and printed in
/// about a second (the time grows about as n³·⁵).
pub const MAX_MOMENT_INDEX: usize = 150;

fn check_index(what: &'static str, n: usize, max: usize, bound: &'static str) -> Result<()> {
    if n == 0 || n > max {
        return Err(Error::domain(what, n.to_string(), bound));
    }
    Ok(())
}

/// F_0(ν) … F_n(ν): the Taylor coefficients of g = −πΓ in x = M2², g = Σ F_n(ν) x^n, so that
/// the paper's f_n of (35)–(36) are F_n(ν)·M2^{2n}. Derived by [`GreenSeries`] (the corrected
/// recurrence (36)) over [`RatFunc`] with ν the variable: exact, in lowest terms; the
/// denominator of F_n is 2^k (1 − ν)^{n−1} for n ≥ 1.
///
/// Errors: [`Error::Domain`] unless 1 ≤ n ≤ [`MAX_COEFFICIENT_INDEX`].
pub fn green_coefficients(n: usize) -> Result<Vec<RatFunc>> {
    check_index(
        "n (symbolic coefficients)",
        n,
        MAX_COEFFICIENT_INDEX,
        "1 <= n <= 120",
    )?;
    Ok(GreenSeries::new(&RatFunc::var(), RatFunc::one(())).take(n + 1))
}

/// (α_k, β_k) and (γ_k, δ_k) for k = 0 … n: L_k = α_k K + β_k E (39) and M_k = γ_k K + δ_k E
/// (41) as rational functions of e², K = K(e), E = E(e). Derived by [`KeForm`] (the recursion
/// (40) from the starting values (42)) over [`RatFunc`] with k² = 1 − e²: exact, in lowest
/// terms; the denominators are powers of e² (and 1 − e² in β_0 = 1/k²).
///
/// Errors: [`Error::Domain`] unless 1 ≤ n ≤ [`MAX_MOMENT_INDEX`].
pub fn moment_forms(n: usize) -> Result<Vec<KeTerm<RatFunc>>> {
    check_index("n (symbolic moments)", n, MAX_MOMENT_INDEX, "1 <= n <= 150")?;
    let one = RatFunc::one(());
    let mut form = KeForm::new(one - RatFunc::var())?;
    Ok((0..=n).map(|_| form.next_term()).collect())
}

/// F_1(ν) as printed in the paper ((36): f1 = M2²(16ν² − 24ν + 14)/16); equal to the derived
/// F_1 (`tests/symbolic.rs`).
pub fn printed_f1() -> RatFunc {
    let p = Poly::new([14, -24, 16].map(Rational::from).to_vec());
    RatFunc::from_polys(p, Poly::constant(Rational::from(16)))
}

/// F_2(ν) as printed in the paper ((36): f2 = M2⁴(27 − 220ν + 312ν² − 224ν³ + 64ν⁴)/(64(1 − ν)));
/// the derivation has 67 for 27, so printed − derived = −5/(8(1 − ν)) (`docs/errata.md` #2).
pub fn printed_f2() -> RatFunc {
    let p = Poly::new([27, -220, 312, -224, 64].map(Rational::from).to_vec());
    let d = Poly::new([64, -64].map(Rational::from).to_vec());
    RatFunc::from_polys(p, d)
}

/// The condition numbers of the K, E basis at e² from the closed forms: for k = 0 … n,
/// log₂((|α_k|K + |β_k|E)/L_k) and log₂((|γ_k|K + |δ_k|E)/M_k) — the bits any evaluation of
/// L_k, M_k as α_k K + β_k E loses (the forward recursion (40) is one). α_k … δ_k are evaluated
/// exactly at the rational `e2`; K, E and L_k, M_k (by [`moments`], within 8 ε) at 128 bits;
/// the logarithms are accurate to about 2⁻¹⁰⁰ relative.
///
/// Errors: [`Error::Domain`] for e² ≥ 1 or e² = 0 (a pole of the forms), and those of
/// [`moments`].
pub fn ke_condition(forms: &[KeTerm<RatFunc>], e2: &Rational) -> Result<Vec<(f64, f64)>> {
    use crate::scalar::{Mp, MpPrec};
    let p = MpPrec::new(128)?;
    let mc_q = Rational::from(1) - e2;
    if mc_q.cmp0() != std::cmp::Ordering::Greater || e2.cmp0() == std::cmp::Ordering::Equal {
        return Err(Error::domain(
            "e^2 (condition of the K, E basis)",
            e2.to_string(),
            "e^2 < 1, e^2 != 0",
        ));
    }
    let mc = Mp::from_float(&Float::with_val(256, &mc_q), p);
    let n = forms.len().saturating_sub(1);
    let mom = moments(&mc, n)?;
    let (k, e) = ellipke_mc(&mc)?;
    let at = |f: &RatFunc| -> Result<Mp> {
        let v = f.eval(e2).ok_or(Error::domain(
            "e^2 (condition of the K, E basis)",
            e2.to_string(),
            "e^2 != 0",
        ))?;
        Ok(Mp::from_float(&Float::with_val(256, &v), p).abs())
    };
    let mut out = Vec::with_capacity(forms.len());
    for (i, t) in forms.iter().enumerate() {
        let kl = (at(&t.l.0)? * &k + at(&t.l.1)? * &e) / &mom.l()[i];
        let km = (at(&t.m.0)? * &k + at(&t.m.1)? * &e) / &mom.m()[i];
        out.push((log2(&kl), log2(&km)));
    }
    Ok(out)
}

/// The pole of the closed forms at e² = 0: α_n = a_n e^{−2p}(1 + O(e²)) and
/// β_n = b_n e^{−2p}(1 + O(e²)), exact.
#[derive(Clone, Debug, PartialEq)]
pub struct PoleTerm {
    /// n.
    pub n: usize,
    /// The order p of the pole of α_n and β_n at e² = 0 (the larger of the two).
    pub order: u32,
    /// a_n (0 when α_n has a pole of lower order).
    pub alpha: Rational,
    /// b_n (0 when β_n has a pole of lower order).
    pub beta: Rational,
}

/// The pole order of `f` at 0 and its leading coefficient f·x^p at 0.
fn pole_at_zero(f: &RatFunc) -> (u32, Rational) {
    let x = Poly::x();
    let mut p = 0;
    let mut rest = Poly::constant(Rational::from(1));
    for (q, e) in f.denom_factors() {
        if *q == x {
            p = *e;
        } else {
            rest = rest.mul(&q.pow(*e));
        }
    }
    let lead = f.numer().eval(&Rational::new()) / rest.eval(&Rational::new());
    (p, lead)
}

/// The pole of α_n, β_n at e² = 0 for each term of [`moment_forms`] (exact). Since L_n stays
/// finite as e → 0 (L_n(0) = W_n = ∫cos^{2n}) and K(0) = E(0) = π/2, a_n = −b_n: the two terms of
/// α_n K + β_n E cancel to within a factor e^{2p} — the cancellation that makes the forward
/// recursion (40) lose about 2p·log₂(1/e) bits (`docs/series.md`).
pub fn pole_terms(forms: &[KeTerm<RatFunc>]) -> Vec<PoleTerm> {
    forms
        .iter()
        .map(|t| {
            let (pa, a) = pole_at_zero(&t.l.0);
            let (pb, b) = pole_at_zero(&t.l.1);
            let order = pa.max(pb);
            PoleTerm {
                n: t.n,
                order,
                alpha: if pa == order { a } else { Rational::new() },
                beta: if pb == order { b } else { Rational::new() },
            }
        })
        .collect()
}

fn log2<T: Field + Real>(x: &T) -> f64 {
    x.to_float(64).log2().to_f64()
}
