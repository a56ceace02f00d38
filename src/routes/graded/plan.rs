//! The graded route's panel plans: how many Gauss–Legendre nodes a left panel of each length
//! needs at a precision, and the fewest-node split of an x-range into panels (dynamic
//! programming over the total length). Node counts and panels for (46)–(47); no equation.

/// The longest left panel, in units of ln 2 (the plan in [`left_plan`] mixes lengths 1…8).
pub const MAX_UNITS: usize = 8;

/// Nodes of a left panel of length `units`·ln 2 in x (w = a sinh x) at `bits` bits:
/// ⌈c·(bits + 8)⌉ with c = ln 2/(2 ln ρ) and ρ = h + √(h² + 1), h = π/(units·ln 2), the
/// Bernstein ellipse of the panel that just reaches the strip |Im x| < π/2 where every
/// singularity lies: ρ^{−2n} ≤ 2^{−bits−8}. The 2^8 covers the measured constant of the u^{−5/2}
/// branch points on the strip's edge with a margin of about two bits (docs/fixed-rules.md). At `f64`
/// 10, 14, 18, 22, 26, 31, 35, 40 for units 1…8; at double-double 18, 26, 33, 41, 49, 57, 65,
/// 74; at 256 bits 42, 59, 77, 95, 113, 132, 151, 170.
/// Node counts for (46)–(47); implements no equation.
pub fn left_nodes(bits: u32, units: usize) -> usize {
    let b = bits.max(24) as f64;
    let h = std::f64::consts::PI / (units.max(1) as f64 * std::f64::consts::LN_2);
    let rho = h + (h * h + 1.0).sqrt();
    (std::f64::consts::LN_2 / (2.0 * rho.ln()) * (b + 8.0)).ceil() as usize
}

/// The most nodes a left panel's rule may have when a longer panel would save nodes: building
/// an n-point Gauss–Legendre rule costs O(n²) operations at the working precision (once per
/// precision, but a single call at 1024 bits would wait seconds for rules of 300–600 nodes).
pub const MAX_RULE_NODES: usize = 180;

/// The longest panel the plans use at `bits` bits, in units of ln 2: the longest whose rule has
/// at most [`MAX_RULE_NODES`] nodes, and at least 2 (8 up to 256 bits, 3 at 512, 2 at 1024).
/// Panel lengths for (46)–(47); implements no equation.
pub fn max_units(bits: u32) -> usize {
    (3..=MAX_UNITS)
        .take_while(|&l| left_nodes(bits, l) <= MAX_RULE_NODES)
        .last()
        .unwrap_or(2)
}

/// The node counts of the panel lengths 1…[`max_units`] at `bits` bits.
pub(super) fn length_costs(bits: u32) -> Vec<usize> {
    (1..=max_units(bits)).map(|l| left_nodes(bits, l)).collect()
}

/// The left half's panels for an x-range of `units`·ln 2 (or a little more): lengths in units
/// of ln 2, each at most [`max_units`], summing to at least `units`, with the fewest nodes
/// ([`left_nodes`]) and, among those, the fewest panels; longest first.
/// The panels for (46)–(47); implements no equation.
pub fn left_plan(bits: u32, units: usize) -> Vec<usize> {
    pick_plan(
        &plan_table(&length_costs(bits), units.max(1) + MAX_UNITS),
        units,
    )
}

/// x-ranges (in units of ln 2) whose plans [`Rules`] keeps: up to (PLANNED − [`MAX_UNITS`])·ln 2
/// ≈ 61, i.e. a ≥ 10^-26, without a search or an allocation per layout.
pub(super) const PLANNED: usize = 96;

/// One entry of the plan table: the fewest nodes and panels for an exact total, and the length
/// of the last panel on the way there.
#[derive(Clone, Copy, Debug)]
pub(super) struct Best {
    nodes: usize,
    panels: usize,
    last: usize,
}

/// The fewest nodes for every exact total 0…`len` − 1 of panel lengths 1…`cost.len()`
/// (`cost[ℓ − 1]` nodes each): dynamic programming over the total.
pub(super) fn plan_table(cost: &[usize], len: usize) -> Vec<Best> {
    let none = Best {
        nodes: usize::MAX,
        panels: usize::MAX,
        last: 0,
    };
    let mut best = vec![none; len];
    best[0] = Best {
        nodes: 0,
        panels: 0,
        last: 0,
    };
    for c in 1..len {
        for (l, &n) in cost.iter().enumerate().map(|(i, n)| (i + 1, n)).take(c) {
            let b = best[c - l];
            let cand = Best {
                nodes: b.nodes + n,
                panels: b.panels + 1,
                last: l,
            };
            if (cand.nodes, cand.panels) < (best[c].nodes, best[c].panels) {
                best[c] = cand;
            }
        }
    }
    best
}

/// The plan for at least `units` from a table covering `units` + [`MAX_UNITS`] − 1.
pub(super) fn pick_plan(table: &[Best], units: usize) -> Vec<usize> {
    let lo = units.max(1);
    let hi = (lo + MAX_UNITS).min(table.len());
    let total = (lo..hi)
        .min_by_key(|&c| (table[c].nodes, table[c].panels, c))
        .unwrap_or(lo);
    let mut plan = Vec::with_capacity(table[total].panels);
    let mut c = total;
    while c > 0 {
        plan.push(table[c].last);
        c -= table[c].last;
    }
    plan.sort_unstable_by(|a, b| b.cmp(a));
    plan
}
