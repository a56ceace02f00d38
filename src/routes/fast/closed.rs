//! The closed forms of the right half: the Taylor coefficients b_j of b(σ), the moments of (σ + k²)^{−3/2} and the pole terms.

use super::*;

/// The Taylor coefficients b_j (j < J) of b(σ) at σ = 0, from its rationalised form
/// b = (2/m1) N(σ)/(Q'(σ)(1 + ε²σ)) with
/// N = (2 + (2 − c)σ)² √(1 + (1 − γc)σ) + 4(1 + σ)(1 + (1 − γc)σ) √(1 + δ²σ): the binomial series
/// of the two square roots (coefficients β_l(−a)^l, β_l those of √(1 − z)) multiplied by the
/// quadratics, then divided by the cubic d0 + d1σ + d2σ² + d3σ³ = Q'(σ)(1 + ε²σ) term by term,
/// b_j = ((2/m1)N_j − d1 b_{j−1} − d2 b_{j−2} − d3 b_{j−3})/d0. The roots of the cubic are
/// σ = −1/ε² and σ = m/(c − m) for the Rayleigh roots m = m2, m3, all of modulus ≥ 1 (equality only
/// at M_R = 0, a triple root at −1), so the division is stable (errors grow at most like j² at
/// M_R = 0). About 14 operations a coefficient; the value at σ = 0 is b_0 = 2(1 − ν).
pub(crate) fn taylor_b<T: Real>(sc: &SpeedConsts<T>, rule: &FastRule<T>, out: &mut [T]) {
    let j_max = out.len();
    if j_max == 0 {
        return;
    }
    let p = sc.c.prec();
    let zero = T::zero(p);
    let four = T::from_i64(4, p);
    // Numerator quadratics: (2 + e1σ)² = 4 + 4e1σ + e1²σ², 4(1 + σ)(1 + a1σ) = 4 + 4(1 + a1)σ + 4a1σ².
    let e1 = T::from_i64(2, p) - &sc.c;
    let na = [four.clone(), e1.clone().mul_i64(4), e1.square()];
    let nb = [
        four,
        (T::one(p) + &sc.a1).mul_i64(4),
        sc.a1.clone().mul_i64(4),
    ];
    // Denominator: Q'(σ) = q + (2q − Sc)σ + (c² − Sc + q)σ², times (1 + ε²σ).
    let q0 = sc.q.clone();
    let q1 = sc.q.clone().mul_i64(2) - &sc.sc;
    let q2 = sc.c2.clone() - &sc.sc + &sc.q;
    let inv_d0 = q0.clone().recip();
    let g = [
        (q1.clone() + sc.eps2.clone() * &q0) * &inv_d0,
        (q2.clone() + sc.eps2.clone() * &q1) * &inv_d0,
        sc.eps2.clone() * &q2 * &inv_d0,
    ];
    let f = sc.two_over_m1.clone() * inv_d0;
    let (minus_a1, minus_d2) = (-sc.a1.clone(), -sc.d2.clone());
    let (mut pa, mut pb) = (T::one(p), T::one(p));
    // Histories: α_{j−1}, α_{j−2}; B_{j−1}, B_{j−2}; b_{j−1}, b_{j−2}, b_{j−3}.
    let (mut al, mut bl) = ([zero.clone(), zero.clone()], [zero.clone(), zero.clone()]);
    let mut bh = [zero.clone(), zero.clone(), zero];
    for (j, out_j) in out.iter_mut().enumerate() {
        let beta = &rule.sqrt_binomial[j];
        let a = beta.clone() * &pa;
        let b = beta.clone() * &pb;
        let n = na[0].clone() * &a
            + na[1].clone() * &al[0]
            + na[2].clone() * &al[1]
            + nb[0].clone() * &b
            + nb[1].clone() * &bl[0]
            + nb[2].clone() * &bl[1];
        let bj = f.clone() * n
            - &(g[0].clone() * &bh[0] + g[1].clone() * &bh[1] + g[2].clone() * &bh[2]);
        *out_j = bj.clone();
        pa *= &minus_a1;
        pb *= &minus_d2;
        al = [a, al[0].clone()];
        bl = [b, bl[0].clone()];
        bh = [bj, bh[0].clone(), bh[1].clone()];
    }
}

/// The moments of the right half's weights that start the recurrences: M_0 = ∫_0^1 (v² +
/// k²)^{−3/2} dv = 1/(k²√(1 + k²)), P_0 = ∫(v² + k²)^{−5/2} dv = (2 + 3k²)/(3k⁴(1 + k²)^{3/2}),
/// N_0 = ∫(v² + k²)^{−1/2} dv = asinh(1/k), and √(1 + k²), returned as (M_0, P_0, N_0, √(1 + k²)).
pub(crate) fn moment_bases<T: Real>(k: &T, k2: &T) -> (T, T, T, T) {
    let p = k.prec();
    let one = T::one(p);
    let opk2 = one.clone() + k2;
    let r1 = opk2.clone().sqrt();
    let m0 = (k2.clone() * &r1).recip();
    // N_0 = asinh(1/k) = ln((1 + √(1 + k²))/k).
    let n0 = ((one + &r1) / k).ln();
    // P_0 = M_0 (2 + 3k²)/(3k²(1 + k²)).
    let p0 = m0.clone() * (T::from_i64(2, p) + k2.clone().mul_i64(3)) / (opk2 * k2).mul_i64(3);
    (m0, p0, n0, r1)
}

/// N_{j+1} = ∫_0^1 v^{2j+2}(v² + k²)^{−1/2} dv from N_j by the upward recurrence
/// N_{j+1} = (√(1 + k²) − (2j + 1)k² N_j)/(2j + 2) (each step multiplies the inherited error by
/// (2j + 1)k²/(2j + 2) < 1); `inv` = 1/(2j + 2), `ratio` = (2j + 1)/(2j + 2), `r1` = √(1 + k²).
#[inline(always)]
pub(crate) fn next_moment<T: Real>(nj: &T, k2: &T, r1: &T, inv: &T, ratio: &T) -> T {
    r1.clone() * inv - k2.clone() * ratio * nj
}

/// Synthetic division by σ − x0: P(σ) = P(x0) + (σ − x0) Q(σ) for P = Σ b_j σ^j; writes the
/// coefficients of Q (ascending, `q.len() = b.len() − 1`) and returns P(x0).
pub(crate) fn synthetic_division<T: Real>(b: &[T], x0: &T, q: &mut [T]) -> T {
    let Some((last, rest)) = b.split_last() else {
        return T::zero(x0.prec());
    };
    let mut acc = last.clone();
    for i in (0..rest.len()).rev() {
        q[i] = acc.clone();
        acc = acc * x0 + &rest[i];
    }
    acc
}

/// The closed-form parts of the right half: ∫ P W3, ∫ σ P W3 and, when `dk`, ∫ P W5, ∫ σ P W5
/// (P = Σ_{j<J} b_j σ^j the subtracted Taylor polynomial, W_m = (σ + k²)^{−m/2}, integrals over
/// v ∈ [0, 1]), exactly: expanded about the branch point, P = P(−k²) + (σ + k²) Q(σ) and
/// Q = Q(−k²) + (σ + k²) Q2(σ), so that only the stable N_j ([`next_moment`]) enter (the
/// M_j = N_{j−1} − k² M_{j−1} recurrence is neutral at k = 1 and would accumulate J² ε there):
///
/// ```text
/// ∫ P W3 = P(−k²) M_0 + Σ q_i N_i,   ∫ σ P W3 = −k² P(−k²) M_0 + P(−k²) N_0 + Σ q_i N_{i+1},
/// ∫ P W5 = P(−k²) P_0 + ∫ Q W3,      ∫ σ P W5 = −k² P(−k²) P_0 + P(−k²) M_0 + ∫ σ Q W3,
/// ```
///
/// the N_j formed once, upwards, as the sums need them. `scratch` holds 2J values.
pub(crate) fn right_closed_forms<T: Real>(
    b: &[T],
    k: &T,
    k2: &T,
    inv_2j: &[T],
    ratio_2j: &[T],
    dk: bool,
    scratch: &mut [T],
) -> [T; 4] {
    let p = k.prec();
    let j_max = b.len();
    let (q, rest) = scratch.split_at_mut(j_max.saturating_sub(1));
    let q2 = &mut rest[..if dk { j_max.saturating_sub(2) } else { 0 }];
    let x0 = -k2.clone();
    let pv = synthetic_division(b, &x0, q);
    let qv = if dk {
        synthetic_division(q, &x0, q2)
    } else {
        T::zero(p)
    };
    let (m0, p0, n0, r1) = moment_bases(k, k2);
    // ∫ R W3 = R(−k²) M_0 + …, ∫ σ R W3 = R(−k²) N_0 − k² R(−k²) M_0 + … for R = P, Q.
    let kpv = k2.clone() * &pv;
    let mut s1 = pv.clone() * &m0;
    let mut s2 = pv.clone() * &n0 - &(kpv.clone() * &m0);
    let mut t1 = qv.clone() * &m0;
    let mut t2 = qv.clone() * &n0 - &((k2.clone() * &qv) * &m0);
    let mut nj = n0;
    for (i, qi) in q.iter().enumerate() {
        let next = next_moment(&nj, k2, &r1, &inv_2j[i], &ratio_2j[i]);
        s1 += qi.clone() * &nj;
        s2 += qi.clone() * &next;
        if let Some(q2i) = q2.get(i) {
            t1 += q2i.clone() * &nj;
            t2 += q2i.clone() * &next;
        }
        nj = next;
    }
    if !dk {
        return [s1, s2, T::zero(p), T::zero(p)];
    }
    let d1 = pv.clone() * &p0 + &t1;
    let d2 = pv * &m0 - &(kpv * &p0) + &t2;
    [s1, s2, d1, d2]
}

/// The scratch of [`right_closed_forms`] held inline: 2J values at double-double (J = 14), 16 at
/// `f64`.
const SCRATCH_INLINE: usize = 28;

/// [`right_closed_forms`] at the working precision, or, above double-double, with 64 guard bits
/// (in MPFR) and rounded once: the expansion of P about the
/// branch point −k² cancels like √J·log J when k → 1 (P(−1) and the quotient grow like √J while
/// the integrals stay O(1)), about 15ε at 256 bits (J = 34) in working precision. At `f64` and
/// double-double (J = 8, 14) the cancellation costs under 2ε and no guard precision is used.
pub(crate) fn right_closed_forms_guarded<T: Real>(
    rule: &FastRule<T>,
    b: &[T],
    kc: &KConsts<T>,
    dk: bool,
) -> [T; 4] {
    let p = rule.prec;
    let j_max = b.len();
    let len = 2 * j_max;
    if T::bits(p) <= 106 {
        let mut scratch = Buf::<T, SCRATCH_INLINE>::zeros(len, p);
        return right_closed_forms(
            b,
            &kc.k,
            &kc.k2,
            &rule.inv_2j,
            &rule.ratio_2j,
            dk,
            &mut scratch,
        );
    }
    // 64 guard bits cover the √J·log J growth for every J a rule can have (J ≈ 0.13·bits).
    let bits = T::bits(p);
    let pw = MpPrec::clamped(bits + 64);
    let up = |x: &T| Mp::from_float(&x.to_float(bits), pw);
    let kw = up(&kc.k);
    let k2w = kw.square();
    let bw: Vec<Mp> = b.iter().map(up).collect();
    let inv: Vec<Mp> = (1..=j_max as i64)
        .map(|j| Mp::from_ratio(1, 2 * j, pw))
        .collect();
    let ratio: Vec<Mp> = (1..=j_max as i64)
        .map(|j| Mp::from_ratio(2 * j - 1, 2 * j, pw))
        .collect();
    let mut scratch = vec![Mp::zero(pw); len];
    let r = right_closed_forms(&bw, &kw, &k2w, &inv, &ratio, dk, &mut scratch);
    r.map(|x| T::from_float(&x.0, p))
}
