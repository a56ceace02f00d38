//! Issue 16 at high precision: the fixed rule at 1024 bits (its right half on sinh-mapped panels
//! for most k, by the Taylor subtraction for the smallest) against the adaptive quadrature at
//! 1088 bits, with k-derivatives and the k-independent set-up; and the refusal of precisions
//! above `MAX_RULE_BITS`, naming the bits asked for, before any rule is built.
//!
//! Inputs are exact binary fractions, so that one value serves every precision.

use moving_hertz::numerics::quadrature::{GaussLegendre, MAX_RULE_BITS};
use moving_hertz::routes::AxisRatio;
use moving_hertz::scalar::{FieldOps, Mp, MpPrec, Real};
use moving_hertz::{
    integrals, solve_ellipse, Error, Estimated, Evaluator, IntegralOptions, Integrals, Material,
    Method, Options,
};

/// The fixed rule's a-priori bounds in ε ([`IntegralOptions`]): I1, I2 and their k-derivatives.
const BOUND_EPS: f64 = 16.0;
const DK_BOUND_EPS: f64 = 128.0;

/// [`Method::Fixed`] (or [`Method::Adaptive`]) with the k-derivatives.
fn with_dk(method: Method) -> IntegralOptions {
    IntegralOptions {
        method,
        derivatives: true,
        ..Default::default()
    }
}

/// (ν, M_R, k): the static limit near k = 1 (where the Taylor form's derivative cancels most),
/// the Rayleigh peak, a narrow k-peak, a negative ν, and a k small enough for the Taylor form.
const CASES: [(&str, &str, &str); 7] = [
    ("0.5", "0", "0.5"),
    ("0.5", "0", "1"),
    ("0.25", "0.9990234375", "0.5"),
    ("0.5", "0.9990234375", "0.0078125"),
    ("-0.75", "0.9375", "0.75"),
    ("0", "0.5", "0.0625"),
    ("0.25", "0.5", "0.00000095367431640625"),
];

fn inputs(nu: &str, mr: &str, k: &str, bits: u64) -> (moving_hertz::Speed<Mp>, AxisRatio<Mp>) {
    let p = MpPrec::new(bits).expect("precision");
    let mat = Material::new(Mp::parse(nu, p).expect("nu")).expect("material");
    let sp = mat.speed(Mp::parse(mr, p).expect("M_R")).expect("speed");
    let ax = AxisRatio::new(Mp::parse(k, p).expect("k")).expect("k");
    (sp, ax)
}

/// |a − b|/|b| in units of 2^(1 − bits).
fn eps_err(a: &Mp, b: &Mp, bits: u32) -> f64 {
    let d = rug::Float::with_val(bits + 128, &a.0 - &b.0);
    ((d / &b.0) << (bits as i32 - 1)).to_f64().abs()
}

/// The larger error (units of 2^(1 − bits)) of I1, I2 and, second, of dI1/dk, dI2/dk of `got`
/// against `want` (both evaluated with the derivatives).
fn errors(got: &Integrals<Mp>, want: &Integrals<Mp>, bits: u32) -> (f64, f64) {
    let dk = |ig: &Integrals<Mp>| {
        let d = |x: &Option<Estimated<Mp>>| x.clone().expect("dI/dk").value;
        [d(&ig.di1_dk), d(&ig.di2_dk)]
    };
    let worst = |g: [&Mp; 2], w: [&Mp; 2]| eps_err(g[0], w[0], bits).max(eps_err(g[1], w[1], bits));
    let (gdk, wdk) = (dk(got), dk(want));
    (
        worst(
            [&got.i1.value, &got.i2.value],
            [&want.i1.value, &want.i2.value],
        ),
        worst([&gdk[0], &gdk[1]], [&wdk[0], &wdk[1]]),
    )
}

#[test]
fn fixed_rule_at_1024_bits_matches_the_adaptive_quadrature() {
    let bits = 1024u32;
    let (mut worst, mut worst_dk) = (0f64, 0f64);
    for (nu, mr, k) in CASES {
        let (sp, ax) = inputs(nu, mr, k, bits as u64);
        let (spr, axr) = inputs(nu, mr, k, bits as u64 + 64);
        let want = integrals(&spr, &axr.k, &with_dk(Method::Adaptive)).expect("reference");
        let got = integrals(&sp, &ax.k, &with_dk(Method::Fixed)).expect("fixed rule");
        let (e, edk) = errors(&got, &want, bits);
        let est = got.i1.error.to_f64() * 2f64.powi(bits as i32 - 1);
        // A k-independent set-up of its own (laid out per octave of k, for a speed built anew)
        // gives the same values.
        let (fresh, _) = inputs(nu, mr, k, bits as u64);
        let ev = Evaluator::new(&fresh, with_dk(Method::Fixed)).expect("set-up");
        let s = ev.at(&ax.k).expect("set-up evaluation");
        let (es, esdk) = errors(&s, &got, bits);
        println!(
            "nu={nu} M_R={mr} k={k}: {} nodes, I {e:.2} eps (estimate {est:.0}), dI/dk {edk:.2} \
             eps; set-up against one-shot {es:.2}, {esdk:.2} eps",
            got.work
        );
        assert!(e <= est && e <= BOUND_EPS, "I: {e} eps");
        assert!(edk <= DK_BOUND_EPS, "dI/dk: {edk} eps");
        assert!(es <= 4.0 && esdk <= 16.0, "set-up: {es}, {esdk} eps");
        worst = worst.max(e);
        worst_dk = worst_dk.max(edk);
    }
    println!("1024 bits: worst I {worst:.2} eps, dI/dk {worst_dk:.2} eps");
}

#[test]
fn precisions_beyond_the_rules_are_refused_naming_the_bits_asked_for() {
    let bits = MAX_RULE_BITS as u64 + 1;
    let refused = |r: Result<(), Error>| {
        assert_eq!(
            r,
            Err(Error::Precision {
                bits,
                min: MpPrec::MIN_BITS,
                max: MAX_RULE_BITS,
            })
        )
    };
    let p = MpPrec::new(bits).expect("precision");
    refused(GaussLegendre::<Mp>::get(8, p).map(|_| ()));
    let (sp, ax) = inputs("0.25", "0.5", "0.5", bits);
    let fixed = IntegralOptions {
        method: Method::Fixed,
        ..Default::default()
    };
    refused(integrals(&sp, &ax.k, &fixed).map(|_| ()));
    refused(integrals(&sp, &ax.k, &IntegralOptions::default()).map(|_| ()));
    refused(solve_ellipse(&sp, &Mp::from_i64(2, p), &Options::default()).map(|_| ()));
}
