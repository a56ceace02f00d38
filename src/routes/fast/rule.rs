//! The fixed rules of the fast route: their sizes per precision and the per-precision rule
//! (left and right halves, built once and cached).

use super::*;

/// The sizes of the fixed rules of the fast route.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct RuleSizes {
    /// Gauss–Legendre nodes on the left half (w = tan α ∈ [0, 1]).
    pub left: usize,
    /// Gauss–Legendre nodes on the right half (v = cot α ∈ [0, 1]).
    pub right: usize,
    /// Taylor terms J of b(σ) subtracted on the right half.
    pub taylor: usize,
    /// The left half on the sinh-mapped panels of [`crate::routes::graded`] (w = a sinh x,
    /// x ∈ [0, 3 ln 2]) instead of one Gauss–Legendre rule in w; `left` is then the layout's
    /// node count ([`left_sinh_nodes`]). Above double-double.
    pub left_sinh: bool,
}

/// The largest scale a of the left half's map w = a sinh x: below the lowest singularity the
/// pole subtraction leaves, G's branch point at w = ±iδ with δ ≥ 0.2956 (ν = 1/2, M_R → 1);
/// the layout rounds it to three units of ln 2, a = 1/sinh(3 ln 2) ≈ 0.254.
pub(crate) const LEFT_SCALE: f64 = 0.28;

/// Nodes of the left half's sinh-mapped panels at `bits` bits ([`graded::left_plan`] for three
/// units of ln 2): 77 at 256 bits, 392 at 1024, 1556 at 4096.
/// Node counts for (46)–(47); implements no equation.
pub fn left_sinh_nodes(bits: u32) -> usize {
    graded::sinh_node_count(bits, LEFT_SCALE)
}

impl RuleSizes {
    /// The sizes for a working precision of `bits` bits, chosen so that the truncation error of
    /// each half is below 1ε (measured convergence: the left half gains 2.3 bits a node in its
    /// worst case, ν = 1/2 and M_R → 1; the right half about 4 bits a node with J ≈ 0.13·bits
    /// Taylor terms, worst for k between 0.1 and 0.9).
    ///
    /// 53 bits (`f64`): 20, 12, J = 8; 106 bits (double-double): 44, 26, J = 14; otherwise
    /// ⌈0.24·bits⌉ + 1 right nodes and J = ⌈0.13·bits⌉, with the left half in one rule of
    /// ⌈0.433·bits⌉ − 2 nodes up to 106 bits and on the sinh-mapped panels above
    /// ([`left_sinh_nodes`]; 256 bits: 77, 63, 34).
    /// Rule sizes for (46)–(47); implements no equation.
    pub fn for_bits(bits: u32) -> RuleSizes {
        let b = bits.max(24) as usize;
        match b {
            53 => RuleSizes {
                left: 20,
                right: 12,
                taylor: 8,
                left_sinh: false,
            },
            106 => RuleSizes {
                left: 44,
                right: 26,
                taylor: 14,
                left_sinh: false,
            },
            _ => {
                let left_sinh = b > 106;
                RuleSizes {
                    left: if left_sinh {
                        left_sinh_nodes(bits)
                    } else {
                        (b * 433).div_ceil(1000) - 2
                    },
                    right: (b * 24).div_ceil(100) + 1,
                    taylor: (b * 13).div_ceil(100),
                    left_sinh,
                }
            }
        }
    }

    /// Integrand evaluations per call (G is evaluated once per node).
    /// Evaluations of G (45) per call; exact.
    pub fn nodes(&self) -> usize {
        self.left + self.right
    }
}

/// The nodes of one half on [0, 1] with the node-only quantities the integrands use.
#[derive(Debug)]
pub(crate) struct Half<T> {
    /// s = node² (w² on the left, σ = v² on the right).
    pub(crate) s: Vec<T>,
    /// p = 1 + s, 2p, 4p.
    pub(crate) p: Vec<T>,
    pub(crate) two_p: Vec<T>,
    pub(crate) four_p: Vec<T>,
    /// The weight ω and ω·s.
    pub(crate) w: Vec<T>,
    pub(crate) ws: Vec<T>,
}

impl<T: Real> Half<T> {
    /// The rule on [0, 1] from the symmetric n-point Gauss–Legendre rule on [−1, 1]: nodes
    /// (1 ± x)/2, weights ω/2.
    pub(crate) fn new(n: usize, p: T::Prec) -> Result<Self> {
        let gl = GaussLegendre::<T>::get(n, p)?;
        let one = T::one(p);
        let half = T::from_ratio(1, 2, p);
        let mut pts: Vec<(T, T)> = Vec::with_capacity(n);
        for (x, w) in gl.nodes().iter().zip(gl.weights()) {
            let hw = w.clone() * &half;
            if x.is_zero() {
                pts.push((half.clone(), hw));
            } else {
                pts.push(((one.clone() - x) * &half, hw.clone()));
                pts.push(((one.clone() + x) * &half, hw));
            }
        }
        pts.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(std::cmp::Ordering::Equal));
        let s: Vec<T> = pts.iter().map(|(x, _)| x.square()).collect();
        let w: Vec<T> = pts.into_iter().map(|(_, w)| w).collect();
        Ok(Self::from_squares(s, w, p))
    }

    /// The left half on the sinh-mapped panels w = a sinh x of [`graded`] for a scale of at
    /// most [`LEFT_SCALE`]: node squares and weights (dw/dx times the panel weight), each within
    /// a few ulps (absolute) of the working precision; the panels' rules and e^{±x} tables are
    /// the graded route's, shared with the right half's sinh layout.
    pub(crate) fn sinh(p: T::Prec) -> Result<Self> {
        graded::with_sinh_layout(p, LEFT_SCALE, |layout| {
            let (s, w) = layout.fill(&T::one(p))?;
            Ok(Self::from_squares(s, w, p))
        })
    }

    /// The half from its node squares s and weights ω: p = 1 + s, 2p, 4p and ω·s.
    fn from_squares(s: Vec<T>, w: Vec<T>, p: T::Prec) -> Self {
        let one = T::one(p);
        let pp: Vec<T> = s.iter().map(|s| one.clone() + s).collect();
        let two_p: Vec<T> = pp.iter().map(|x| x.clone().mul_i64(2)).collect();
        let four_p: Vec<T> = pp.iter().map(|x| x.clone().mul_i64(4)).collect();
        let ws: Vec<T> = w.iter().zip(&s).map(|(w, s)| w.clone() * s).collect();
        Half {
            s,
            p: pp,
            two_p,
            four_p,
            w,
            ws,
        }
    }

    pub(crate) fn len(&self) -> usize {
        self.s.len()
    }

    /// The node quantities (s, p, 2p, 4p), node by node.
    #[inline(always)]
    pub(crate) fn nodes(&self) -> impl Iterator<Item = (&T, &T, &T, &T)> {
        self.nodes_in(0..self.len())
    }

    /// [`Half::nodes`] for the nodes of `range` only.
    #[inline(always)]
    pub(crate) fn nodes_in(
        &self,
        range: std::ops::Range<usize>,
    ) -> impl Iterator<Item = (&T, &T, &T, &T)> {
        self.s[range.clone()]
            .iter()
            .zip(&self.p[range.clone()])
            .zip(&self.two_p[range.clone()])
            .zip(&self.four_p[range])
            .map(|(((s, p), two_p), four_p)| (s, p, two_p, four_p))
    }
}

/// The fixed rules of the fast route at one precision: nodes and weights on [0, 1] for both
/// halves, with the node-only quantities precomputed, and the exact rational constants of the
/// Taylor coefficients of b and of the moment recurrences. Built once per precision and kept in
/// the shared rule cache of [`crate::numerics::quadrature`]; for `f64` and double-double a
/// static slot filled from it serves later calls without the cache's lock.
#[derive(Debug)]
pub struct FastRule<T: Real> {
    pub(crate) prec: T::Prec,
    pub(crate) sizes: RuleSizes,
    pub(crate) left: Half<T>,
    /// The right half's rule: built with the rule at `f64` and double-double, on first use above
    /// (where the right half may be laid out on sinh-mapped panels instead, [`right_sinh`]).
    pub(crate) right: OnceLock<Half<T>>,
    /// The binomial coefficients β_l of √(1 − z) = Σ β_l z^l, l < J.
    pub(crate) sqrt_binomial: Vec<T>,
    /// 1/(2j) and (2j − 1)/(2j) for j = 1..=J (index j − 1): the N_j recurrence.
    pub(crate) inv_2j: Vec<T>,
    pub(crate) ratio_2j: Vec<T>,
}

fixed_slot!(static_slot, FastRule);

impl<T: Real> FastRule<T> {
    /// The rule for precision `p` with the sizes of [`RuleSizes::for_bits`], built on first use
    /// and cached for the life of the process.
    /// The nodes for (46)–(47); implements no equation (accuracy: [`RuleSizes::for_bits`]).
    pub fn get(p: T::Prec) -> Result<Arc<Self>> {
        check_rule_bits(T::bits(p))?;
        let build = || Self::build(Self::default_sizes(p), p);
        match static_slot::<T>() {
            Some(slot) => slotted(slot, 0, p, |r: &Self| r.prec, build).cloned(),
            None => cached(0, p, |r: &Self| r.prec, build),
        }
    }

    pub(crate) fn default_sizes(p: T::Prec) -> RuleSizes {
        RuleSizes::for_bits(T::bits(p))
    }

    /// A rule with explicit sizes (not cached): for convergence studies and calibration.
    /// The nodes for (46)–(47); implements no equation.
    pub fn build(sizes: RuleSizes, p: T::Prec) -> Result<Self> {
        if sizes.left == 0 || sizes.right == 0 {
            return Err(Error::Domain {
                name: "fast route node count",
                value: format!("{}/{}", sizes.left, sizes.right),
                bound: ">= 1",
            });
        }
        let left = if sizes.left_sinh {
            let h = Half::sinh(p)?;
            if h.len() != sizes.left {
                return Err(Error::Domain {
                    name: "fast route left node count with the sinh layout",
                    value: sizes.left.to_string(),
                    bound: "the layout's count (left_sinh_nodes)",
                });
            }
            h
        } else {
            Half::new(sizes.left, p)?
        };
        let right = OnceLock::new();
        if T::bits(p) <= 106 {
            let _ = right.set(Half::new(sizes.right, p)?);
        }
        let j_max = sizes.taylor;
        // β_0 = 1, β_{l+1} = β_l (2l − 1)/(2l + 2).
        let mut sqrt_binomial = Vec::with_capacity(j_max);
        let mut beta = T::one(p);
        for l in 0..j_max as i64 {
            sqrt_binomial.push(beta.clone());
            beta = beta.mul_i64(2 * l - 1).div_i64(2 * l + 2);
        }
        let inv_2j = (1..=j_max as i64)
            .map(|j| T::from_ratio(1, 2 * j, p))
            .collect();
        let ratio_2j = (1..=j_max as i64)
            .map(|j| T::from_ratio(2 * j - 1, 2 * j, p))
            .collect();
        Ok(FastRule {
            prec: p,
            sizes,
            left,
            right,
            sqrt_binomial,
            inv_2j,
            ratio_2j,
        })
    }

    /// The right half's rule (built on first use above double-double).
    pub(crate) fn right_half(&self) -> Result<&Half<T>> {
        if let Some(h) = self.right.get() {
            return Ok(h);
        }
        let h = Half::new(self.sizes.right, self.prec)?;
        Ok(self.right.get_or_init(|| h))
    }
}
