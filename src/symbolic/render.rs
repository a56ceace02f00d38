//! Output of the symbolic results: plain text and sympy input (`name = expression`, one per
//! line, parsed by `sympy.sympify`). Exact: every integer is printed in full.
//!
//! An expression is written as ±A·P(v) / (B·Π q_i(v)^{e_i}), as the paper prints f2: P and each
//! base q_i are integer polynomials with coprime coefficients, written in ascending powers with
//! their lowest nonzero coefficient positive (`67 - 220 nu + ...`, `1 - nu`, `e2`), and A, B
//! are coprime positive integers.
//!
//! No item of this module implements a formula of the paper: they print the exact results of
//! [`super::green_coefficients`] ((35)-(36)) and [`super::moment_forms`] ((40), (42)) without
//! rounding.

use super::ratfunc::RatFunc;
use crate::routes::moments::KeTerm;
use rug::{Integer, Rational};
use std::cmp::Ordering;
use std::fmt::Write;

/// An output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// Plain text for a reader: `f_2 = x^2 (67 - 220 nu + ... + 64 nu^4)/(64 (1 - nu))`.
    Text,
    /// `name = expression` per line, in sympy syntax (`**` for powers), variables `nu`, `x`, `e2`.
    Sympy,
}

/// The variable of a rational function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variable {
    /// Poisson's ratio ν (`nu`).
    Nu,
    /// The squared eccentricity e² = 1 − k² (`e2`).
    E2,
}

impl Variable {
    /// v^k as `style` writes it.
    fn power(self, k: usize, style: Style) -> String {
        let name = match self {
            Variable::Nu => "nu",
            Variable::E2 => "e2",
        };
        power(name, k, style)
    }
}

/// `base`^k as `style` writes it (`base` alone for k = 1).
fn power(base: &str, k: usize, style: Style) -> String {
    match style {
        _ if k == 1 => base.to_string(),
        Style::Text => format!("{base}^{k}"),
        Style::Sympy => format!("{base}**{k}"),
    }
}

/// `s` in parentheses when `wrap`.
fn wrapped(s: String, wrap: bool) -> String {
    if wrap {
        format!("({s})")
    } else {
        s
    }
}

/// A polynomial with integer coefficients (ascending) as `style` writes it, in ascending powers.
fn int_poly(c: &[Integer], v: Variable, style: Style) -> String {
    let mut out = String::new();
    for (k, a) in c.iter().enumerate() {
        if a.cmp0() == Ordering::Equal {
            continue;
        }
        let neg = a.cmp0() == Ordering::Less;
        if out.is_empty() {
            if neg {
                out.push('-');
            }
        } else {
            out.push_str(if neg { " - " } else { " + " });
        }
        let abs = Integer::from(a.abs_ref());
        if k == 0 {
            let _ = write!(out, "{abs}");
        } else if abs == 1 {
            out.push_str(&v.power(k, style));
        } else {
            let _ = write!(out, "{abs}{}{}", times(style), v.power(k, style));
        }
    }
    out
}

/// The sign of a product as `style` writes it.
fn times(style: Style) -> &'static str {
    match style {
        Style::Text => " ",
        Style::Sympy => "*",
    }
}

fn terms(c: &[Integer]) -> usize {
    c.iter().filter(|a| a.cmp0() != Ordering::Equal).count()
}

/// `c` (ascending, not all zero) with the sign that makes its lowest nonzero coefficient
/// positive, and whether it was flipped.
fn positive_low(mut c: Vec<Integer>) -> (Vec<Integer>, bool) {
    let low = c.iter().find(|a| a.cmp0() != Ordering::Equal);
    let flip = low.is_some_and(|a| a.cmp0() == Ordering::Less);
    if flip {
        c.iter_mut().for_each(|a| *a = Integer::from(-&*a));
    }
    (c, flip)
}

/// The expression of `f` in the variable `v`, times x^`xpow` when `xpow` > 0 (see the module
/// docs for the normal form).
pub fn expression(f: &RatFunc, v: Variable, xpow: usize, style: Style) -> String {
    if f.numer().is_zero() {
        return "0".into();
    }
    let (mut r, prim) = f.numer().primitive();
    let (prim, flip) = positive_low(prim);
    if flip {
        r = -r;
    }
    let mut bases = Vec::new();
    for (q, e) in f.denom_factors() {
        let (qi, _) = positive_low(q.primitive().1);
        // q = qi / lead(qi), so 1/q^e = lead^e / qi^e.
        let lead = qi.last().cloned().unwrap_or_default();
        r *= Rational::from(Integer::from(rug::ops::Pow::pow(&lead, *e)));
        bases.push((qi, *e));
    }
    let (neg, mul) = (r.cmp0() == Ordering::Less, times(style));
    let (a, b) = (Integer::from(r.numer().abs_ref()), r.denom().clone());
    let has_den = b != 1 || !bases.is_empty();
    // Numerator: [A ·] [x^k ·] P; P stands bare when nothing precedes it and the sign or a
    // bar cannot be misread.
    let mut num = Vec::new();
    if a != 1 {
        num.push(a.to_string());
    }
    if xpow > 0 {
        num.push(power("x", xpow, style));
    }
    if prim.len() > 1 {
        let bare = num.is_empty() && !has_den && !neg;
        num.push(wrapped(
            int_poly(&prim, v, style),
            !bare && terms(&prim) > 1,
        ));
    }
    let num = if num.is_empty() {
        "1".to_string()
    } else {
        num.join(mul)
    };
    let sign = if neg { "-" } else { "" };
    if !has_den {
        return format!("{sign}{num}");
    }
    // Denominator: [B ·] Π base^e (the base v itself as v's power).
    let mut den = Vec::new();
    if b != 1 {
        den.push(b.to_string());
    }
    for (qi, e) in &bases {
        den.push(if terms(qi) == 1 && qi.len() == 2 {
            v.power(*e as usize, style)
        } else {
            let wrap = terms(qi) > 1;
            power(&wrapped(int_poly(qi, v, style), wrap), *e as usize, style)
        });
    }
    format!("{sign}{num}/{}", wrapped(den.join(mul), den.len() > 1))
}

/// One named function for [`render`]: `name = value(v) · x^xpow`.
#[derive(Clone, Debug)]
pub struct Named {
    /// The name (`f_2`, `alpha_10`, ...).
    pub name: String,
    /// The rational function.
    pub value: RatFunc,
    /// The variable of `value`.
    pub var: Variable,
    /// A power of x multiplying `value` (0 for none).
    pub xpow: usize,
}

/// The document for `items` in `style`: `name = expression` lines, under `title` as a comment in
/// text (sympy output holds only the lines).
pub fn render(title: &str, items: &[Named], style: Style) -> String {
    let mut out = String::new();
    if style == Style::Text {
        let _ = writeln!(out, "# {title}");
    }
    for it in items {
        let e = expression(&it.value, it.var, it.xpow, style);
        let _ = writeln!(out, "{} = {e}", it.name);
    }
    out
}

/// The named functions of [`super::green_coefficients`]: `f_n` = F_n(ν)·x^n for each n, then
/// the paper's printed `f_1_printed`, `f_2_printed` and `f_2_printed_minus_derived` (each
/// times its power of x).
pub fn coefficient_items(f: &[RatFunc]) -> Vec<Named> {
    let mut items: Vec<Named> = f
        .iter()
        .enumerate()
        .map(|(n, v)| Named {
            name: format!("f_{n}"),
            value: v.clone(),
            var: Variable::Nu,
            xpow: n,
        })
        .collect();
    let mut push = |name: &str, value: RatFunc, xpow: usize| {
        items.push(Named {
            name: name.into(),
            value,
            var: Variable::Nu,
            xpow,
        })
    };
    push("f_1_printed", super::printed_f1(), 1);
    push("f_2_printed", super::printed_f2(), 2);
    if let Some(f2) = f.get(2) {
        push("f_2_printed_minus_derived", super::printed_f2() - f2, 2);
    }
    items
}

/// The named functions of [`super::moment_forms`]: `alpha_n`, `beta_n`, `gamma_n`, `delta_n`
/// with L_n = alpha_n K + beta_n E, M_n = gamma_n K + delta_n E.
pub fn moment_items(t: &[KeTerm<RatFunc>]) -> Vec<Named> {
    let mut items = Vec::with_capacity(4 * t.len());
    for term in t {
        for (name, value) in [
            ("alpha", &term.l.0),
            ("beta", &term.l.1),
            ("gamma", &term.m.0),
            ("delta", &term.m.1),
        ] {
            items.push(Named {
                name: format!("{name}_{}", term.n),
                value: value.clone(),
                var: Variable::E2,
                xpow: 0,
            });
        }
    }
    items
}
