//! Brent's method (Brent 1973, `zero`) at the working precision: an independent root finder for
//! the references of the tests (the crate solves its own equations by other means).

use moving_hertz::scalar::Real;

/// A root of `f` in `[a, b]`, where `f(a)` and `f(b)` differ in sign, to a relative bracket
/// half-width of `2ε`, by inverse quadratic interpolation, secant steps and bisection. Panics
/// without a sign change or after `max_iter` evaluations (a test failure).
pub fn brent<T: Real, F: FnMut(&T) -> T>(mut f: F, a: &T, b: &T, max_iter: usize) -> T {
    let p = a.prec();
    let rtol = T::epsilon(p).mul_i64(2);
    let (mut a, mut b) = (a.clone(), b.clone());
    let (mut fa, mut fb) = (f(&a), f(&b));
    assert!(
        fa.is_finite() && fb.is_finite(),
        "brent: f not finite at an end"
    );
    if fa.is_zero() {
        return a;
    }
    if fb.is_zero() {
        return b;
    }
    assert!(
        fa.is_negative() != fb.is_negative(),
        "brent: no sign change"
    );
    let (mut c, mut fc) = (a.clone(), fa.clone());
    let mut d = b.clone() - &a;
    let mut e = d.clone();
    let one = T::one(p);
    for _ in 0..max_iter {
        // Keep the root bracketed by [b, c] with b the better end.
        if fb.is_negative() == fc.is_negative() {
            c = a.clone();
            fc = fa.clone();
            d = b.clone() - &a;
            e = d.clone();
        }
        if fc.clone().abs() < fb.clone().abs() {
            a = std::mem::replace(&mut b, c.clone());
            c = a.clone();
            fa = std::mem::replace(&mut fb, fc.clone());
            fc = fa.clone();
        }
        let tol1 = rtol.clone() * &b.clone().abs();
        let xm = (c.clone() - &b).mul_pow2(-1);
        if xm.clone().abs() <= tol1 || fb.is_zero() {
            return b;
        }
        // Interpolation (secant with two distinct points, inverse quadratic otherwise),
        // accepted only well inside the bracket and shrinking fast enough; else bisection.
        if e.clone().abs() >= tol1 && fa.clone().abs() > fb.clone().abs() {
            let s = fb.clone() / &fa;
            let (mut pp, mut q) = if a == c {
                (xm.clone().mul_pow2(1) * &s, one.clone() - &s)
            } else {
                let q = fa.clone() / &fc;
                let r = fb.clone() / &fc;
                let pp = s.clone()
                    * &(xm.clone().mul_pow2(1) * &q * &(q.clone() - &r)
                        - (b.clone() - &a) * &(r.clone() - &one));
                let q = (q - &one) * &(r - &one) * &(s - &one);
                (pp, q)
            };
            if pp.is_positive() {
                q = -q;
            } else {
                pp = -pp;
            }
            let bound1 = xm.clone().mul_i64(3) * &q - (tol1.clone() * &q).abs();
            let bound2 = (e.clone() * &q).abs();
            if pp.clone().mul_pow2(1) < bound1.min_of(bound2) {
                e = std::mem::replace(&mut d, pp / &q);
            } else {
                d = xm.clone();
                e = xm.clone();
            }
        } else {
            d = xm.clone();
            e = xm.clone();
        }
        a = b.clone();
        fa = fb.clone();
        // Never step by less than tol1, so each evaluation makes progress.
        if d.clone().abs() > tol1 {
            b += &d;
        } else if xm.is_negative() {
            b -= &tol1;
        } else {
            b += &tol1;
        }
        if b == a {
            return b;
        }
        fb = f(&b);
        assert!(fb.is_finite(), "brent: f not finite");
    }
    panic!("brent: no convergence in {max_iter} evaluations");
}
