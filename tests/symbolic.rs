//! Symbolic mode (`moving_hertz::symbolic`): F_n(ν) of (36) and α_n … δ_n(e²) of (40) as exact
//! rational functions, checked symbol for symbol against an independent sympy derivation
//! (tools/gen_symbolic.py: series expansion of −πΓ as printed; L_n, M_n reduced to K and E by
//! differentiation), against the exact `Rational` runs of the same recurrences at rational
//! points (bit for bit), against the floating runs (within their error), and the rational
//! function arithmetic against naive cross-multiplication.

mod common;

use common::{read_csv, rel_eps, SplitMix};
use moving_hertz::numerics::elliptic::ellipke_mc;
use moving_hertz::routes::moments::{ke_condition_bits, moments, KeForm};
use moving_hertz::routes::GreenSeries;
use moving_hertz::scalar::{decimal_to_rational, FieldOps, Mp, Real};
use moving_hertz::symbolic::{
    coefficient_items, expression, green_coefficients, ke_condition, moment_forms, moment_items,
    pole_terms, printed_f1, printed_f2, render, Poly, RatFunc, Style, Variable,
};
use moving_hertz::Error;
use rug::{Float, Rational};
use std::collections::HashMap;

/// name → (numerator, denominator) coefficient lists from tests/data/symbolic_reference.txt.
fn sympy_reference() -> HashMap<String, (Vec<Rational>, Vec<Rational>)> {
    let path = format!(
        "{}/tests/data/symbolic_reference.txt",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("reference data");
    let list = |s: &str| -> Vec<Rational> {
        s.split_whitespace()
            .map(|t| decimal_to_rational(t).expect("rational"))
            .collect()
    };
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split('|').collect();
            (f[0].to_string(), (list(f[1]), list(f[2])))
        })
        .collect()
}

/// Lowest terms: the numerator is coprime to each base of the factored denominator (cheap, the
/// bases being small), and the bases multiply to the denominator.
fn assert_lowest_terms(f: &RatFunc, what: &str) {
    let mut d = Poly::constant(Rational::from(1));
    for (q, e) in f.denom_factors() {
        assert_eq!(f.numer().gcd(q).degree(), 0, "{what}");
        d = d.mul(&q.pow(*e));
    }
    assert_eq!(d, f.denom(), "{what}");
}

fn canonical(f: &RatFunc) -> (Vec<Rational>, Vec<Rational>) {
    (f.numer().coeffs().to_vec(), f.denom().coeffs().to_vec())
}

#[test]
fn coefficients_equal_the_sympy_series_of_printed_gamma_symbol_for_symbol() {
    let refs = sympy_reference();
    let f = green_coefficients(30).expect("F_0..F_30");
    assert_eq!(f.len(), 31);
    for (n, fn_) in f.iter().enumerate() {
        let want = &refs[&format!("F_{n}")];
        assert_eq!(&canonical(fn_), want, "F_{n}");
        // Lowest terms; the monic denominator is (ν − 1)^(n−1).
        assert_lowest_terms(fn_, &format!("F_{n}"));
        assert_eq!(fn_.denom().degree(), n.saturating_sub(1), "F_{n}");
    }
}

#[test]
fn moment_forms_equal_the_sympy_reduction_to_k_and_e_symbol_for_symbol() {
    let refs = sympy_reference();
    let t = moment_forms(50).expect("n <= 50");
    assert_eq!(t.len(), 51);
    for term in &t {
        let n = term.n;
        for (name, f) in [
            ("alpha", &term.l.0),
            ("beta", &term.l.1),
            ("gamma", &term.m.0),
            ("delta", &term.m.1),
        ] {
            assert_eq!(&canonical(f), &refs[&format!("{name}_{n}")], "{name}_{n}");
            assert_lowest_terms(f, &format!("{name}_{n}"));
        }
    }
}

/// F_n(ν) at rational ν is the `Rational` run of the same recurrence, bit for bit, and both
/// equal the exact Taylor coefficients of tools/gen_series.py (n ≤ 30).
#[test]
fn substituting_rational_nu_reproduces_the_exact_run_bit_for_bit() {
    let f = green_coefficients(60).expect("F_0..F_60");
    let mut table: Vec<(Rational, Vec<Rational>)> = Vec::new();
    for row in read_csv("series_coefficients.csv") {
        let nu = decimal_to_rational(&row[0]).expect("nu");
        let c = decimal_to_rational(&row[2]).expect("F_n");
        match table.last_mut() {
            Some((m, v)) if *m == nu => v.push(c),
            _ => table.push((nu, vec![c])),
        }
    }
    assert_eq!(table.len(), 6);
    let extra = [(7, 13), (-99, 100), (1, 3), (123_456_789, 987_654_321)];
    let nus = table
        .iter()
        .map(|(nu, _)| nu.clone())
        .chain(extra.iter().map(|&q| Rational::from(q)));
    for nu in nus {
        let exact = GreenSeries::new(&nu, Rational::from(1)).take(61);
        for (n, (fn_, want)) in f.iter().zip(&exact).enumerate() {
            assert_eq!(&fn_.eval(&nu).expect("no pole"), want, "nu = {nu}, n = {n}");
        }
        if let Some((_, csv)) = table.iter().find(|(m, _)| *m == nu) {
            assert_eq!(&exact[..], &csv[..61], "nu = {nu}");
        }
    }
}

/// α_n … δ_n at rational e² are the `Rational` run of KeForm, bit for bit (e² on both sides of
/// 1/2 and negative, i.e. k > 1).
#[test]
fn substituting_rational_e2_reproduces_the_exact_run_bit_for_bit() {
    let t = moment_forms(60).expect("n <= 60");
    for q in [
        (3, 4),
        (1, 2),
        (1, 7),
        (-1, 1),
        (-255, 1),
        (999, 1000),
        (-3, 1024),
    ] {
        let e2 = Rational::from(q);
        let mut form = KeForm::new(Rational::from(1) - &e2).expect("e2 != 0");
        for term in &t {
            let want = form.next_term();
            let at = |f: &RatFunc| f.eval(&e2).expect("no pole");
            assert_eq!(at(&term.l.0), want.l.0, "e2 = {e2}, alpha_{}", term.n);
            assert_eq!(at(&term.l.1), want.l.1, "e2 = {e2}, beta_{}", term.n);
            assert_eq!(at(&term.m.0), want.m.0, "e2 = {e2}, gamma_{}", term.n);
            assert_eq!(at(&term.m.1), want.m.1, "e2 = {e2}, delta_{}", term.n);
        }
    }
}

/// F_n at a floating ν (evaluated exactly, rounded once) against the floating recurrence at
/// the same ν: within (n + 4) ε, the recurrence's accuracy (tests/series_coefficients.rs).
fn floating_coefficients<T: Real>(p: T::Prec, label: &str) {
    let f = green_coefficients(30).expect("F_0..F_30");
    let mut worst: f64 = 0.0;
    for nu_text in ["-0.9", "0.05", "0.2", "0.3", "0.4999"] {
        let nu = T::parse(nu_text, p).expect("nu");
        let got = GreenSeries::new(&nu, T::one(p)).take(31);
        for (n, (g, fn_)) in got.iter().zip(&f).enumerate() {
            // F_n at the exact value of ν, rounded to the working bits plus 8.
            let exact = fn_.eval(&nu.to_float(T::bits(p)).to_rational().unwrap());
            let want = Float::with_val(T::bits(p) + 8, exact.expect("no pole"));
            let e = rel_eps(g, &want);
            worst = worst.max(e);
            assert!(
                e <= (n + 4) as f64,
                "{label}: nu = {nu_text}, F_{n}: {e} eps"
            );
        }
    }
    println!(
        "{label}: worst error of the floating recurrence against F_n(nu), n <= 30: {worst:.2} eps"
    );
}

#[test]
fn substituting_floating_nu_reproduces_the_numeric_runs_within_their_error() {
    at_all_precisions!(floating_coefficients, [64, 256]);
}

/// L_n = α_n K + β_n E and M_n = γ_n K + δ_n E, formed at 2048 bits from the exact forms at a
/// rational e², against the default moment table at f64, double-double and MPFR: within 8 ε, the
/// table's stated accuracy.
fn floating_moments<T: Real>(p: T::Prec, label: &str) {
    let t = moment_forms(50).expect("n <= 50");
    let wide = common::mp(2048);
    let mut worst: f64 = 0.0;
    for e2_text in ["0.875", "0.5", "0.25", "-1.5"] {
        let e2 = decimal_to_rational(e2_text).expect("e2");
        let mc_q = Rational::from(1) - &e2;
        let mc = T::from_float(&Float::with_val(128, &mc_q), p);
        let tab = moments(&mc, 50).expect("moments");
        let mcw = Mp::from_float(&Float::with_val(128, &mc_q), wide);
        let (k, e) = ellipke_mc(&mcw).expect("K, E");
        let at = |f: &RatFunc| Mp::from_float(&Float::with_val(2048, f.eval(&e2).unwrap()), wide);
        for term in &t {
            let n = term.n;
            let l = at(&term.l.0) * &k + at(&term.l.1) * &e;
            let m = at(&term.m.0) * &k + at(&term.m.1) * &e;
            let el = rel_eps(&tab.l()[n], &l.to_float(2048));
            let em = rel_eps(&tab.m()[n], &m.to_float(2048));
            worst = worst.max(el).max(em);
            assert!(
                el <= 8.0 && em <= 8.0,
                "{label}: e2 = {e2_text}, n = {n}: {el}, {em} eps"
            );
        }
    }
    println!("{label}: worst error of the moment table against the closed forms, n <= 50: {worst:.2} eps");
}

#[test]
fn substituting_floating_e2_reproduces_the_numeric_moments_within_their_error() {
    at_all_precisions!(floating_moments, [64, 256]);
}

#[test]
fn printed_f1_is_right_and_printed_f2_differs_by_minus_five_eighths_over_one_minus_nu() {
    let f = green_coefficients(2).expect("F_0..F_2");
    assert_eq!(printed_f1(), f[1]);
    let one_minus_nu = RatFunc::one(()) - RatFunc::var();
    let diff = printed_f2() - &f[2];
    assert_eq!(diff, RatFunc::from_ratio(-5, 8, ()) / one_minus_nu);
    // The printed 27 and the derived 67 are the constant terms of the numerators over 64(1 − ν).
    let over = |g: &RatFunc| {
        (g.clone() * RatFunc::from_poly(Poly::new(vec![64.into(), (-64).into()])))
            .numer()
            .coeffs()[0]
            .clone()
    };
    assert_eq!(over(&printed_f2()), 27);
    assert_eq!(over(&f[2]), 67);
}

/// Rational function arithmetic against naive cross-multiplication, with denominators that
/// share factors partly ((x − 1)², x² − 1, x(x + 2)), so that the coprime base must refine.
#[test]
fn rational_function_arithmetic_is_exact_and_in_lowest_terms() {
    let mut rng = SplitMix(19);
    let small = |rng: &mut SplitMix| {
        Rational::from((
            (rng.next_u64() % 7) as i64 - 3,
            1 + (rng.next_u64() % 3) as i64,
        ))
    };
    let poly = |rng: &mut SplitMix, deg: usize| Poly::new((0..=deg).map(|_| small(rng)).collect());
    let factors = [
        Poly::new(vec![(-1).into(), 1.into()]),
        Poly::new(vec![1.into(), (-2).into(), 1.into()]),
        Poly::new(vec![(-1).into(), 0.into(), 1.into()]),
        Poly::new(vec![0.into(), 2.into(), 1.into()]),
        Poly::x(),
    ];
    let pick = |rng: &mut SplitMix| {
        let mut d = Poly::constant(Rational::from(1 + (rng.next_u64() % 3) as i64));
        for f in &factors {
            if rng.next_u64().is_multiple_of(3) {
                d = d.mul(f);
            }
        }
        let deg = (rng.next_u64() % 4) as usize;
        let n = poly(rng, deg);
        (n.clone(), d.clone(), RatFunc::from_polys(n, d))
    };
    for _ in 0..300 {
        let (an, ad, a) = pick(&mut rng);
        let (bn, bd, b) = pick(&mut rng);
        let check = |got: &RatFunc, n: Poly, d: Poly, what: &str| {
            // got = n/d  ⇔  got.num·d = n·got.den
            assert_eq!(got.numer().mul(&d), n.mul(&got.denom()), "{what}");
            assert_eq!(
                got.numer().gcd(&got.denom()).degree(),
                0,
                "{what}: lowest terms"
            );
            assert_eq!(got.denom().lead(), 1, "{what}: monic denominator");
        };
        check(
            &(a.clone() + &b),
            an.mul(&bd).add(&bn.mul(&ad)),
            ad.mul(&bd),
            "sum",
        );
        check(
            &(a.clone() - &b),
            an.mul(&bd).add(&bn.mul(&ad).neg()),
            ad.mul(&bd),
            "difference",
        );
        check(&(a.clone() * &b), an.mul(&bn), ad.mul(&bd), "product");
        if !bn.is_zero() {
            check(&(a.clone() / &b), an.mul(&bd), ad.mul(&bn), "quotient");
        }
    }
}

/// A tiny evaluator of the sympy output (numbers, one variable, x, + − * / ** and parentheses),
/// exact over ℚ: the printed text denotes the same function.
fn eval_text(s: &str, var: &str, v: &Rational, x: &Rational) -> Rational {
    struct P<'a> {
        s: &'a [u8],
        i: usize,
        var: &'a str,
        v: &'a Rational,
        x: &'a Rational,
    }
    impl P<'_> {
        fn ws(&mut self) {
            while self.i < self.s.len() && self.s[self.i] == b' ' {
                self.i += 1;
            }
        }
        fn eat(&mut self, t: &str) -> bool {
            self.ws();
            if self.s[self.i..].starts_with(t.as_bytes()) {
                self.i += t.len();
                true
            } else {
                false
            }
        }
        fn sum(&mut self) -> Rational {
            let mut a = if self.eat("-") {
                -self.product()
            } else {
                self.product()
            };
            loop {
                if self.eat("+") {
                    a += self.product();
                } else if self.eat("-") {
                    a -= self.product();
                } else {
                    return a;
                }
            }
        }
        fn product(&mut self) -> Rational {
            let mut a = self.power();
            loop {
                if self.s[self.i..].starts_with(b"**") {
                    return a;
                }
                if self.eat("*") {
                    a *= self.power();
                } else if self.eat("/") {
                    a /= self.power();
                } else {
                    return a;
                }
            }
        }
        fn power(&mut self) -> Rational {
            let b = self.atom();
            if self.eat("**") {
                let e = self.atom();
                let e = e.numer().to_i32().expect("small exponent");
                return rug::ops::Pow::pow(b, e);
            }
            b
        }
        fn atom(&mut self) -> Rational {
            self.ws();
            if self.eat("(") {
                let a = self.sum();
                assert!(self.eat(")"));
                return a;
            }
            if self.eat(self.var) {
                return self.v.clone();
            }
            if self.eat("x") {
                return self.x.clone();
            }
            let start = self.i;
            while self.i < self.s.len() && self.s[self.i].is_ascii_digit() {
                self.i += 1;
            }
            let t = std::str::from_utf8(&self.s[start..self.i]).unwrap();
            Rational::from(t.parse::<rug::Integer>().expect("number"))
        }
    }
    let mut p = P {
        s: s.as_bytes(),
        i: 0,
        var,
        v,
        x,
    };
    let r = p.sum();
    p.ws();
    assert_eq!(p.i, s.len(), "unparsed tail in {s}");
    r
}

#[test]
fn sympy_text_denotes_the_derived_functions() {
    let f = green_coefficients(12).expect("F");
    let items = coefficient_items(&f);
    let t = moment_forms(12).expect("moments");
    let mitems = moment_items(&t);
    let x = Rational::from((3, 7));
    for (items, var, v) in [
        (&items, "nu", Rational::from((2, 9))),
        (&mitems, "e2", Rational::from((-5, 11))),
    ] {
        let text = render("title", items, Style::Sympy);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), items.len());
        for (line, it) in lines.iter().zip(items.iter()) {
            let (name, expr) = line.split_once(" = ").expect("name = expression");
            assert_eq!(name, it.name);
            let want = it.value.eval(&v).unwrap() * rug::ops::Pow::pow(x.clone(), it.xpow as i32);
            assert_eq!(eval_text(expr, var, &v, &x), want, "{line}");
        }
    }
    // The paper's form of f2: ascending powers over 64(1 − ν).
    assert_eq!(
        expression(&f[2], Variable::Nu, 2, Style::Text),
        "x^2 (67 - 220 nu + 312 nu^2 - 224 nu^3 + 64 nu^4)/(64 (1 - nu))"
    );
}

#[test]
fn indices_out_of_range_are_typed_errors() {
    for (r, bound) in [
        (green_coefficients(0).err(), "1 <= n <= 120"),
        (green_coefficients(121).err(), "1 <= n <= 120"),
        (moment_forms(0).err(), "1 <= n <= 150"),
        (moment_forms(151).err(), "1 <= n <= 150"),
    ] {
        match r {
            Some(Error::Domain { bound: b, .. }) => assert_eq!(b, bound),
            other => panic!("expected a domain error, got {other:?}"),
        }
    }
    assert!(green_coefficients(moving_hertz::symbolic::MAX_COEFFICIENT_INDEX).is_ok());
}

/// The condition number of the K, E basis from the closed forms equals the one the floating
/// KeForm gives (`ke_condition_bits`), and grows as predicted: for e² < 1/2 about
/// n·log₂(k²/e²) bits.
#[test]
fn condition_of_the_ke_basis_from_the_closed_forms() {
    let t = moment_forms(50).expect("n <= 50");
    for e2_text in ["0.9", "0.25", "-3"] {
        let e2 = decimal_to_rational(e2_text).expect("e2");
        let closed = ke_condition(&t, &e2).expect("condition");
        let mc = Mp::from_float(
            &Float::with_val(128, Rational::from(1) - &e2),
            common::mp(128),
        );
        let numeric = ke_condition_bits(&mc, 50).expect("numeric");
        for (n, (a, b)) in closed.iter().zip(&numeric).enumerate() {
            assert!(
                (a.0 - b.0).abs() < 1e-6 && (a.1 - b.1).abs() < 1e-6,
                "e2 = {e2_text}, n = {n}: {a:?} vs {b:?}"
            );
        }
        if e2_text == "0.25" {
            // |r| = k²/e² = 3: about log₂ 3 = 1.585 bits per step.
            let slope = (closed[50].0 - closed[30].0) / 20.0;
            assert!((slope - 3f64.log2()).abs() < 0.05, "slope {slope}");
        }
    }
    assert!(matches!(
        ke_condition(&t, &Rational::from(1)),
        Err(Error::Domain { .. })
    ));
    assert!(matches!(
        ke_condition(&t, &Rational::new()),
        Err(Error::Domain { .. })
    ));
}

/// α_n and β_n have a pole of order n at e² = 0 with opposite leading coefficients (L_n stays
/// finite and K(0) = E(0)), a_n in closed form: the cancellation of the K, E basis as e → 0.
#[test]
fn alpha_and_beta_have_opposite_poles_of_order_n_at_e2_zero() {
    let t = moment_forms(80).expect("n <= 80");
    let poles = pole_terms(&t);
    for p in &poles[1..] {
        assert_eq!(p.order as usize, p.n, "n = {}", p.n);
        assert_eq!(p.alpha, -p.beta.clone(), "n = {}", p.n);
        // a_n = (−1)^(n+1)·(2n − 1)/(2n)·4^n/C(2n, n), i.e. |a_n| = (2n − 1)/(2n)·(π/2)/W_n.
        let n = p.n as u32;
        let c = rug::Integer::from(rug::Integer::binomial_u(2 * n, n));
        let mut a = Rational::from((rug::Integer::from(2 * n - 1) << (2 * n), c * (2 * n)));
        if n.is_multiple_of(2) {
            a = -a;
        }
        assert_eq!(p.alpha, a, "n = {n}");
    }
    // At e² = 2^-20, |α_n|K + |β_n|E ≈ 2|a_n|·2^(20n)·π/2 while L_n ≈ W_n = (π/2)·Π(2j−1)/(2j):
    // the bits lost are log₂(2|a_n|) + 20n − log₂ Π(2j−1)/(2j), to O(e²).
    let e2 = Rational::from((1, 1 << 20));
    let closed = ke_condition(&t[..=10], &e2).expect("condition");
    for (n, (bits_l, _)) in closed.iter().enumerate().skip(1) {
        let a = poles[n].alpha.to_f64().abs().log2();
        let want = a + 20.0 * n as f64 + 1.0;
        let wallis = (1..=n).fold(0.0, |s, j| s + ((2 * j - 1) as f64 / (2 * j) as f64).log2());
        assert!(
            (bits_l - (want - wallis)).abs() < 0.01,
            "n = {n}: {bits_l} vs {}",
            want - wallis
        );
    }
}
