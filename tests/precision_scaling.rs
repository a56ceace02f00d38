//! Issue 16 at high precision: the fixed rule at 1024 bits (its right half on sinh-mapped panels
//! for most k, by the Taylor subtraction for the smallest) against the adaptive quadrature at
//! 1088 bits, with k-derivatives and the k-independent set-up; and the refusal of precisions
//! above `MAX_RULE_BITS`, naming the bits asked for, before any rule is built.
//!
//! Inputs are exact binary fractions, so that one value serves every precision.

use moving_hertz::numerics::quadrature::{GaussLegendre, MAX_RULE_BITS};
use moving_hertz::routes::fast::{self, FastSetup, BOUND_EPS, DK_BOUND_EPS};
use moving_hertz::routes::{direct, AxisRatio};
use moving_hertz::scalar::{Field, Mp, MpPrec, Real};
use moving_hertz::{integrals, solve_ellipse, Error, IntegralOptions, Material, Options};

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

#[test]
fn fixed_rule_at_1024_bits_matches_the_adaptive_quadrature() {
    let bits = 1024u32;
    let (mut worst, mut worst_dk) = (0f64, 0f64);
    for (nu, mr, k) in CASES {
        let (sp, ax) = inputs(nu, mr, k, bits as u64);
        let (spr, axr) = inputs(nu, mr, k, bits as u64 + 64);
        let q = MpPrec::new(bits as u64 + 64).expect("precision");
        let want = direct::contact_integrals(&spr, &axr, &Mp::zero(q)).expect("reference");
        let wdk = want.dk.clone().expect("derivatives");
        let got = fast::integrals_with_dk(&sp, &ax).expect("fixed rule");
        let gdk = got.dk.clone().expect("derivatives");
        let e = eps_err(&got.i1, &want.i1, bits).max(eps_err(&got.i2, &want.i2, bits));
        let edk = eps_err(&gdk[0], &wdk[0], bits).max(eps_err(&gdk[1], &wdk[1], bits));
        let est = (got.error_estimate.0.clone() << (bits as i32 - 1)).to_f64();
        // The k-independent set-up (laid out per octave of k) gives the same values.
        let setup = FastSetup::new(&sp).expect("set-up");
        let s = setup.integrals_with_dk(&ax).expect("set-up evaluation");
        let sdk = s.dk.clone().expect("derivatives");
        let es = eps_err(&s.i1, &got.i1, bits).max(eps_err(&s.i2, &got.i2, bits));
        let esdk = eps_err(&sdk[0], &gdk[0], bits).max(eps_err(&sdk[1], &gdk[1], bits));
        println!(
            "nu={nu} M_R={mr} k={k}: {} nodes, I {e:.2} eps (estimate {est:.0}), dI/dk {edk:.2} \
             eps; set-up against one-shot {es:.2}, {esdk:.2} eps",
            got.work
        );
        assert!(e <= est && e <= BOUND_EPS as f64, "I: {e} eps");
        assert!(edk <= DK_BOUND_EPS as f64, "dI/dk: {edk} eps");
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
    refused(fast::integrals(&sp, &ax).map(|_| ()));
    refused(integrals(&sp, &ax.k, &IntegralOptions::default()).map(|_| ()));
    refused(solve_ellipse(&sp, &Mp::from_i64(2, p), &Options::default()).map(|_| ()));
}
