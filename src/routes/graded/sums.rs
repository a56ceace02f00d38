//! The weighted node sums of the fixed and graded rules: Σ f·x^{−3/2} and Σ f·x^{−5/2} over
//! the nodes of one half (x = u = 1 + k²s on the left, x = σ + k² on the right), the work an
//! axis ratio k costs once the speed's set-up is built.
//!
//! Laid out so that the compiler vectorises them at `f64`: a chunk's kernel powers are formed
//! first into a table (independent nodes, one square root and one division each, two nodes to
//! an SSE2 square root and division), then each sum is a dot product of two tables ([`dot`]:
//! four partial sums in two SSE2 registers). The same code runs at every precision.

use crate::numerics::shares::{for_shares, shares};
use crate::scalar::Real;

/// Nodes a chunk of [`chunked_sums`] (the tables of [`power_sums`] hold one chunk).
pub(super) const CHUNK: usize = 32;

/// Σ wᵢ xᵢ: with four interleaved partial sums at `f64` (at most [`CHUNK`] terms; the
/// independent chains fill two SSE2 lanes twice), pairwise above (error ~log₂ n ε instead of
/// n ε for the 40 to 400 terms of the higher-precision rules). Rounding, for positive terms
/// each within a relative error q: within q + (⌈n/4⌉ + 2) roundings at `f64` (each partial sum
/// takes ⌈n/4⌉ products and sums, then two sums join them), q + (⌈log₂ n⌉ + 1) roundings
/// above 8 terms (n + 1 below).
#[inline(always)]
pub(crate) fn dot<T: Real>(w: &[T], x: &[T]) -> T {
    let n = w.len().min(x.len());
    let p = w[0].prec();
    if T::bits(p) > 53 {
        return dot_wide(&w[..n], &x[..n]);
    }
    let zero = T::zero(p);
    let mut acc = [zero.clone(), zero.clone(), zero.clone(), zero];
    let (wc, xc) = (w[..n].chunks_exact(4), x[..n].chunks_exact(4));
    let (wr, xr) = (wc.remainder(), xc.remainder());
    for (a, b) in wc.zip(xc) {
        for j in 0..4 {
            acc[j] += a[j].clone() * &b[j];
        }
    }
    for (j, (a, b)) in wr.iter().zip(xr).enumerate() {
        acc[j] += a.clone() * b;
    }
    let [a0, a1, a2, a3] = acc;
    (a0 + &a1) + &(a2 + &a3)
}

/// [`dot`] above `f64`: in order up to 8 terms, pairwise above.
fn dot_wide<T: Real>(w: &[T], x: &[T]) -> T {
    let n = w.len();
    if n <= 8 {
        let mut acc = w[0].clone() * &x[0];
        for (a, b) in w[1..].iter().zip(&x[1..]) {
            acc += a.clone() * b;
        }
        acc
    } else {
        let h = n / 2;
        dot_wide(&w[..h], &x[..h]) + dot_wide(&w[h..], &x[h..])
    }
}

/// The kernel powers at the nodes `xs`: x^{−3/2} into `v3` and, with `dk`, x^{−5/2} into `v5`
/// (x = shift(node)): [`Real::pow_m3_2`], [`Real::pow_m3_2_m5_2`], one square root and one
/// division a node, no dependence between nodes.
#[inline(always)]
pub(super) fn kernel_powers<T: Real>(
    xs: &[T],
    v3: &mut [T],
    v5: &mut [T],
    dk: bool,
    shift: &impl Fn(&T) -> T,
) {
    if dk {
        for ((x, a), b) in xs.iter().zip(v3).zip(v5) {
            (*a, *b) = shift(x).pow_m3_2_m5_2();
        }
    } else {
        for (x, a) in xs.iter().zip(v3) {
            *a = shift(x).pow_m3_2();
        }
    }
}

/// The kernel's argument x at a node s of one half: u = 1 + k²s on the left half (`Left`),
/// σ + k² on the right (`Right`), with k² and 1 at the working precision.
#[derive(Clone, Copy)]
pub(crate) enum Kernel<'a, T> {
    Left { k2: &'a T, one: &'a T },
    Right { k2: &'a T },
}

impl<T: Real> Kernel<'_, T> {
    #[inline(always)]
    fn at(&self, s: &T) -> T {
        match self {
            Kernel::Left { k2, one } => (*one).clone() + (*k2).clone() * s,
            Kernel::Right { k2 } => s.clone() + *k2,
        }
    }

    /// Σ g_i x^{−3/2} from S_i = Σ g_i x^{−5/2} and S_{i+1}, x = α + βs:
    /// α S_i + β S_{i+1} (left: S_i + k² S_{i+1}; right: k² S_i + S_{i+1}).
    #[inline(always)]
    fn w3(&self, si: &T, next: &T) -> T {
        match self {
            Kernel::Left { k2, .. } => si.clone() + (*k2).clone() * next,
            Kernel::Right { k2 } => (*k2).clone() * si + next,
        }
    }
}

/// The kernel sums of one half over its nodes s with x = [`Kernel::at`] (α + βs > 0) and the
/// factors [g0, g1, g2] = `g` with g1 = s·g0, g2 = s·g1: returns [Σ g0 x^{−3/2}, Σ g1 x^{−3/2}]
/// and, with `dk`, [Σ g0 x^{−5/2}, Σ g1 x^{−5/2}, Σ g2 x^{−5/2}] (zero without; g2 is read only
/// with `dk`). With `dk` only x^{−5/2} is formed and the x^{−3/2} sums follow from
/// x^{−3/2} = (α + βs) x^{−5/2}: Σ g_i x^{−3/2} = α Σ g_i x^{−5/2} + β Σ g_{i+1} x^{−5/2}
/// (three dot products a chunk instead of four; positive terms, so within two roundings more
/// than the sums it is formed from).
///
/// Per chunk of [`CHUNK`] nodes the kernel powers into a table, then the sums
/// ([`dot`]), the chunks' sums added in order ([`chunked_sums`]). One square root and one
/// division a node. Rounding, for factors within a relative error q: each sum within
/// q + 3 (the kernel power: x, its square root, the product and the division, x^{−5/2}
/// 4 with x²) + ⌈m/4⌉ + 2 ([`dot`] of a chunk of m) + (the chunks, one a chunk) roundings,
/// the x^{−3/2} sums from x^{−5/2} two more.
#[inline(always)]
pub(crate) fn power_sums<T: Real>(
    nodes: &[T],
    g: [&[T]; 3],
    dk: bool,
    kernel: Kernel<'_, T>,
) -> ([T; 2], [T; 3]) {
    let p = match kernel {
        Kernel::Left { k2, .. } | Kernel::Right { k2 } => k2.prec(),
    };
    let n = nodes.len();
    let [t0, t1, s0, s1, s2] = if std::mem::needs_drop::<T>() {
        // Values that own memory (MPFR): the table filled afresh each chunk, with no zeros
        // allocated to be overwritten.
        chunked_sums(n, p, Vec::new, |i0, v: &mut Vec<T>| {
            v.clear();
            v.extend(nodes[i0..n.min(i0 + CHUNK)].iter().map(|x| match dk {
                true => kernel.at(x).pow_m3_2_m5_2().1,
                false => kernel.at(x).pow_m3_2(),
            }));
            chunk_dots(g, i0, v, dk)
        })
    } else {
        let table = || -> [T; CHUNK] { std::array::from_fn(|_| T::zero(p)) };
        chunked_sums(n, p, table, |i0, v| {
            let m = CHUNK.min(n - i0);
            let v = &mut v[..m];
            let xs = &nodes[i0..i0 + m];
            if dk {
                for (x, y) in xs.iter().zip(v.iter_mut()) {
                    *y = kernel.at(x).pow_m3_2_m5_2().1;
                }
            } else {
                for (x, y) in xs.iter().zip(v.iter_mut()) {
                    *y = kernel.at(x).pow_m3_2();
                }
            }
            chunk_dots(g, i0, v, dk)
        })
    };
    if !dk {
        return ([t0, t1], [s0, s1, s2]);
    }
    let w3 = [kernel.w3(&s0, &s1), kernel.w3(&s1, &s2)];
    (w3, [s0, s1, s2])
}

/// One half's node tables for [`power_sums`]: the nodes s and the factors f, s·f and s²·f.
#[derive(Clone, Debug)]
pub(crate) struct NodeTables<T> {
    s: Vec<T>,
    g: [Vec<T>; 3],
}

impl<T: Real> NodeTables<T> {
    /// The tables of the nodes `s` and the factors `f` at precision `p` (s·f and s²·f formed
    /// here, on the cores above [`crate::numerics::shares::PARALLEL_ABOVE_BITS`]).
    pub(crate) fn new(s: Vec<T>, f: Vec<T>, p: T::Prec) -> Self {
        let (mut sf, mut ssf) = (s.clone(), s.clone());
        super::node_map(p, &f, &mut sf, |f, s| s.clone() * f);
        super::node_map(p, &sf, &mut ssf, |sf, s| s.clone() * sf);
        NodeTables { s, g: [f, sf, ssf] }
    }

    /// The number of nodes.
    pub(crate) fn len(&self) -> usize {
        self.s.len()
    }

    /// [`power_sums`] over the tables.
    #[inline(always)]
    pub(crate) fn sums(&self, dk: bool, kernel: Kernel<'_, T>) -> ([T; 2], [T; 3]) {
        let [f, sf, ssf] = &self.g;
        power_sums(&self.s, [f, sf, ssf], dk, kernel)
    }
}

/// The sums of [`power_sums`] over the chunk from node i0, from its kernel powers `v`
/// (x^{−5/2} with `dk`, else x^{−3/2}): [Σ g0 v, Σ g1 v, 0, 0, 0] or [0, 0, Σ g0 v, Σ g1 v, Σ g2 v].
#[inline(always)]
fn chunk_dots<T: Real>(g: [&[T]; 3], i0: usize, v: &[T], dk: bool) -> [T; 5] {
    let range = i0..i0 + v.len();
    let (g0, g1, g2) = (&g[0][range.clone()], &g[1][range.clone()], &g[2][range]);
    let zero = || T::zero(v[0].prec());
    if dk {
        [zero(), zero(), dot(g0, v), dot(g1, v), dot(g2, v)]
    } else {
        [dot(g0, v), dot(g1, v), zero(), zero(), zero()]
    }
}

/// `N` sums over `n` nodes from `chunk(i0, scratch)`, the sums of the [`CHUNK`] nodes from i0
/// (`scratch` from `scratch()`, one a thread), each chunk's sums added to the total in chunk
/// order (above [`crate::numerics::shares::PARALLEL_ABOVE_BITS`] the chunks' sums are formed
/// on the cores first: the same bits).
#[inline(always)]
pub(super) fn chunked_sums<T: Real, S, const N: usize>(
    n: usize,
    p: T::Prec,
    scratch: impl Fn() -> S + Sync,
    chunk: impl Fn(usize, &mut S) -> [T; N] + Sync,
) -> [T; N] {
    let zero = || -> [T; N] { std::array::from_fn(|_| T::zero(p)) };
    let add = |acc: &mut [T; N], part: [T; N]| {
        for (s, q) in acc.iter_mut().zip(part) {
            *s += &q;
        }
    };
    let mut acc = zero();
    let count = shares(T::bits(p), n);
    if count == 1 {
        let mut s = scratch();
        let mut i0 = 0;
        while i0 < n {
            add(&mut acc, chunk(i0, &mut s));
            i0 += CHUNK;
        }
        return acc;
    }
    let mut parts: Vec<[T; N]> = (0..n.div_ceil(CHUNK)).map(|_| zero()).collect();
    for_shares(count, &mut parts, &mut [] as &mut [T], &|start, ps, _| {
        let mut s = scratch();
        for (c, part) in (start..).zip(ps) {
            *part = chunk(c * CHUNK, &mut s);
        }
    });
    for part in parts {
        add(&mut acc, part);
    }
    acc
}
