//! The right half on sinh-mapped panels (above double-double): one layout per octave of k.

use super::*;

/// Octaves of k on the route's domain: k ∈ (2^(−j−1), 2^−j], j = 0 … 40.
pub(crate) const OCTAVES: usize = 41;

/// The octave j of 2^−40 ≤ k ≤ 1 (40 for every smaller k, which [`sinh_octave`] never lays out).
pub(crate) fn octave<T: Real>(k: &T) -> usize {
    ((-k.to_f64().log2()).floor().max(0.0) as usize).min(OCTAVES - 1)
}

/// The largest scale a of v = a sinh x for the octave j: 4/5 of its smallest k, so that the
/// branch points ±ik of (σ + k²)^{−3/2} lie on or beyond the strip |Im x| < π/2.
pub(crate) fn octave_scale(j: usize) -> f64 {
    0.8 * 0.5f64.powi(j as i32 + 1)
}

/// What a node of the right half costs besides the Taylor polynomial's J products (G's cleared
/// form and the kernel power), in products: the weight of J in [`sinh_octave`]'s comparison.
pub(crate) const NODE_COST: usize = 30;

/// The octave of k when the rule's right half takes the sinh-mapped panels ([`right_sinh`]):
/// above double-double, when their nodes cost less than the Taylor subtraction's
/// n_r (1 + J/[`NODE_COST`]) (the J products of the polynomial at every node grow like bits²).
/// At `f64` and double-double, and below k = 2⁻⁴⁰ (the Taylor form's cost does not grow as k
/// falls, the panels' does), never.
pub(crate) fn sinh_octave<T: Real>(rule: &FastRule<T>, k: &T) -> Option<usize> {
    let bits = T::bits(rule.prec);
    if bits <= 106 {
        return None;
    }
    if *k < T::one(rule.prec).mul_pow2(1 - OCTAVES as i32) {
        return None;
    }
    let j = octave(k);
    let z = rule.sizes;
    let n = graded::sinh_node_count(bits, octave_scale(j));
    (n * NODE_COST < z.right * (NODE_COST + z.taylor)).then_some(j)
}

/// The right half on sinh-mapped panels: v = a sinh x over x ∈ [0, C ln 2] with a ≤ (4/5)·k for
/// every k of the octave `j`, the panels of [`crate::routes::graded`] (lengths ℓ ln 2, node
/// counts from the Bernstein ellipse that reaches the strip |Im x| < π/2, where the branch points
/// ±ik of (σ + k²)^{−3/2} and every singularity of b(σ), at |v| ≥ 1 on or near the imaginary
/// axis, lie). No subtraction: the integrands b(σ)(σ + k²)^{−3/2} dv/dx are positive and analytic
/// in the strip. Kept per k-independent part: σ, f = ω b(σ) (ω the weight times dv/dx), σf and
/// σ²f; a k costs one square root and one division a node ([`graded`]'s power sums).
pub(crate) fn right_sinh<T: Real>(
    sc: &SpeedConsts<T>,
    p: T::Prec,
    j: usize,
) -> Result<graded::NodeTables<T>> {
    graded::with_sinh_layout(p, octave_scale(j), |layout| {
        // b(σ) = (2/m1) √f1 D′/E; the factor 2/m1 goes into the weights.
        let (s, mut f) = layout.fill(&sc.two_over_m1)?;
        let one = T::one(p);
        graded::node_map(p, &s, &mut f, |sg, fi| {
            let (f1, dd, e) = sc.right_at(sg, &one);
            fi.clone() * dd * f1.sqrt_div(&e)
        });
        Ok(graded::NodeTables::new(s, f, p))
    })
}
