//! Helpers shared by the integration tests: reference-data parsing, error measurement, and a
//! macro running a generic check at every precision.
#![allow(dead_code)]

pub mod printed;
pub mod roots;
pub mod tanh_sinh;

use moving_hertz::scalar::Field as _;
use moving_hertz::scalar::{mixed_precision_events, FieldOps, MpPrec, Real};
use rug::Float;

/// Bits used to hold reference values.
pub const REF_BITS: u32 = 1200;

/// Reads a committed CSV under tests/data, skipping `#` comments; returns the fields per line.
pub fn read_csv(name: &str) -> Vec<Vec<String>> {
    let path = format!("{}/tests/data/{}", env!("CARGO_MANIFEST_DIR"), name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| l.split(',').map(|s| s.trim().to_string()).collect())
        .collect()
}

/// A reference decimal at REF_BITS.
pub fn reference(s: &str) -> Float {
    Float::with_val(
        REF_BITS,
        Float::parse(s).unwrap_or_else(|_| panic!("bad reference {s}")),
    )
}

/// |got − want| / |scale| in units of the working epsilon of `got`'s precision.
pub fn err_eps<T: Real>(got: &T, want: &Float, scale: &Float) -> f64 {
    let g = got.to_float(REF_BITS);
    let d = Float::with_val(REF_BITS, &g - want);
    let rel = Float::with_val(REF_BITS, d / scale).abs();
    let eps = T::epsilon(got.prec()).to_float(64);
    Float::with_val(64, rel / eps).to_f64()
}

/// Relative error against a high-precision reference, in units of ε.
pub fn rel_eps<T: Real>(got: &T, want: &Float) -> f64 {
    err_eps(got, want, want)
}

/// `|got − want| / |want|` in units of the working ε when both are at the working precision
/// (absolute error in ε if want = 0).
pub fn rel_err_eps<T: Real>(got: &T, want: &T) -> f64 {
    let p = want.prec();
    let d = (got.clone() - want).abs();
    let r = if want.is_zero() {
        d
    } else {
        d / &want.clone().abs()
    };
    (r / &T::epsilon(p)).to_f64()
}

/// SplitMix64: a small deterministic generator for test arguments.
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E3779B97F4A7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58476D1CE4E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D049BB133111EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in 0 … n − 1.
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }
    /// A value for a parameter whose domain is [lo, hi]: one draw in five from the specials
    /// (NaN, ±∞, ±0, subnormals, ±MAX, 1e±100, 1e±300, the ends and their neighbours), two
    /// uniform in [lo, hi], one log-uniform in ±[1e-12, 1e12], one clustered at lo.
    pub fn value(&mut self, lo: f64, hi: f64) -> f64 {
        let ulp = |x: f64| f64::EPSILON * x.abs().max(f64::MIN_POSITIVE);
        let specials = [
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.0,
            -0.0,
            5e-324,
            f64::MIN_POSITIVE,
            f64::MAX,
            -f64::MAX,
            1e-300,
            1e300,
            lo,
            hi,
            lo - ulp(lo),
            lo + ulp(lo),
            hi - ulp(hi),
            hi + ulp(hi),
            1e-100,
            1e100,
            1.0 - 1e-12,
            1e-6,
            1e6,
        ];
        match self.below(5) {
            0 => specials[self.below(specials.len() as u64) as usize],
            1 | 2 => lo + (hi - lo) * self.unit(),
            3 => {
                10f64.powf(-12.0 + 24.0 * self.unit()) * if self.below(6) == 0 { -1.0 } else { 1.0 }
            }
            _ => lo + (hi - lo) * self.unit().powi(8),
        }
    }
}

/// The MPFR precision token for `bits` bits.
pub fn mp(bits: u64) -> MpPrec {
    MpPrec::new(bits).expect("valid precision")
}

/// Asserts that no MPFR operation in this test process mixed precisions.
pub fn assert_no_mixing() {
    assert_eq!(
        mixed_precision_events(),
        0,
        "an MPFR operation mixed precisions"
    );
}

/// Runs a generic check `f::<T>(p, label)` at f64, double-double and MPFR at the given bit
/// counts (default 128, 256, 1024), then checks the mixed-precision counter.
#[macro_export]
macro_rules! at_all_precisions {
    ($f:ident) => {
        at_all_precisions!($f, [128, 256, 1024])
    };
    ($f:ident, [$($bits:expr),*]) => {{
        $f::<f64>((), "f64");
        $f::<moving_hertz::scalar::Dd>((), "dd");
        $( $f::<moving_hertz::scalar::Mp>(common::mp($bits), concat!("mpfr", stringify!($bits))); )*
        common::assert_no_mixing();
    }};
}

// ---------------------------------------------------------------------------------------------
// References for I1, I2, dI/dk by the adaptive route (tests/unit/fast.rs, tests/unit/graded.rs)

use moving_hertz::physics::{Material, Speed};
use moving_hertz::routes::AxisRatio;
use moving_hertz::scalar::Mp;
use moving_hertz::{integrals, IntegralOptions, Method};

/// Bits of the adaptive reference computation.
pub const ADAPTIVE_REF_PREC: u64 = 400;

/// One row of an adaptive reference file: inputs (the `f64` values of the decimals) and I1, I2,
/// dI1/dk, dI2/dk.
pub struct IntegralCase {
    pub nu: f64,
    pub mr: f64,
    pub k: f64,
    pub i1: Float,
    pub i2: Float,
    pub d1: Float,
    pub d2: Float,
}

/// The rows of tests/data/`name`.
pub fn integral_cases(name: &str) -> Vec<IntegralCase> {
    read_csv(name)
        .into_iter()
        .map(|r| IntegralCase {
            nu: r[0].parse().expect("nu"),
            mr: r[1].parse().expect("M_R"),
            k: r[2].parse().expect("k"),
            i1: reference(&r[3]),
            i2: reference(&r[4]),
            d1: reference(&r[5]),
            d2: reference(&r[6]),
        })
        .collect()
}

/// Speed (with its material) and axis ratio from `f64` inputs, taken exactly at precision `p`.
pub fn integral_inputs<T: Real>(nu: f64, mr: f64, k: f64, p: T::Prec) -> (Speed<T>, AxisRatio<T>) {
    let mat = Material::new(T::from_f64(nu, p)).expect("nu");
    let sp = mat.speed(T::from_f64(mr, p)).expect("M_R");
    let ax = AxisRatio::new(T::from_f64(k, p)).expect("k");
    (sp, ax)
}

/// I1, I2 by the adaptive route at [`ADAPTIVE_REF_PREC`] bits, and dI/dk by central differences
/// with h = k·2^−100 (truncation ~2^−200 relative, rounding ~2^−300).
pub fn adaptive_reference(nu: f64, mr: f64, k: f64) -> [Float; 4] {
    let p = mp(ADAPTIVE_REF_PREC);
    let (sp, ax) = integral_inputs::<Mp>(nu, mr, k, p);
    let adaptive = IntegralOptions {
        method: Method::Adaptive,
        ..Default::default()
    };
    let at = |kk: Mp| {
        let r = integrals(&sp, &kk, &adaptive).expect("adaptive reference");
        (r.i1.value, r.i2.value)
    };
    let (i1, i2) = at(ax.k.clone());
    let h = ax.k.clone().mul_pow2(-100);
    let (a1, a2) = at(ax.k.clone() + &h);
    let (b1, b2) = at(ax.k.clone() - &h);
    let two_h = h.mul_pow2(1);
    let bits = ADAPTIVE_REF_PREC as u32;
    [
        i1.to_float(bits),
        i2.to_float(bits),
        ((a1 - &b1) / &two_h).to_float(bits),
        ((a2 - &b2) / &two_h).to_float(bits),
    ]
}

/// Writes tests/data/`name` over the grid, with the command that regenerates it in the header.
pub fn write_adaptive_reference(name: &str, command: &str, nus: &[f64], mrs: &[f64], ks: &[f64]) {
    let mut out = format!(
        "# REGRESSION DATA, not an independent reference: this crate's own adaptive route.\n\
         # The routes are held to independent values by tests/references.rs (Arb) and\n\
         # tests/data/integrals_mpmath.csv; these rows pin the fixed rules to the adaptive one.\n\
         # generated by `{command}`:\n\
         # the adaptive route (Method::Adaptive) at {ADAPTIVE_REF_PREC} bits (tolerance: the precision's floor); dI/dk by\n\
         # central differences with h = k*2^-100. Inputs are the f64 values of the decimals.\n\
         # nu,mr,k,I1,I2,dI1/dk,dI2/dk\n",
    );
    for &nu in nus {
        for &mr in mrs {
            for &k in ks {
                let r = adaptive_reference(nu, mr, k);
                let s: Vec<String> = r.iter().map(|x| x.to_string_radix(10, Some(90))).collect();
                out += &format!("{nu},{mr},{k},{}\n", s.join(","));
            }
        }
    }
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::write(&path, out).expect("write reference");
}

/// Recomputes row `idx` of an adaptive reference and checks it to 1e-85 relative.
pub fn check_adaptive_row(case: &IntegralCase, idx: usize) {
    let r = adaptive_reference(case.nu, case.mr, case.k);
    for (got, want) in r.iter().zip([&case.i1, &case.i2, &case.d1, &case.d2]) {
        let d = Float::with_val(ADAPTIVE_REF_PREC as u32, got - want) / want;
        let e = Float::with_val(64, d).abs().to_f64();
        assert!(e < 1e-85, "row {idx}: {e:e}");
    }
}

/// One row of tests/data/integrals_mpmath.csv (tools/gen_integrals.py): decimal inputs and
/// mpmath's I1, I2.
pub struct MpmathCase {
    pub nu: String,
    pub mr: String,
    pub k: String,
    pub i1: Float,
    pub i2: Float,
}

/// The I1, I2 rows of tests/data/integrals_mpmath.csv.
pub fn mpmath_cases() -> Vec<MpmathCase> {
    read_csv("integrals_mpmath.csv")
        .into_iter()
        .filter(|r| r[0] == "I")
        .map(|r| MpmathCase {
            nu: r[1].clone(),
            mr: r[2].clone(),
            k: r[3].clone(),
            i1: reference(&r[4]),
            i2: reference(&r[5]),
        })
        .collect()
}

impl MpmathCase {
    /// The case's material, speed and axis ratio, each decimal parsed at precision `p`.
    pub fn inputs<T: Real>(&self, p: T::Prec) -> (Speed<T>, AxisRatio<T>) {
        let mat = Material::new(T::parse(&self.nu, p).unwrap()).unwrap();
        let sp = mat.speed(T::parse(&self.mr, p).unwrap()).unwrap();
        let ax = AxisRatio::new(T::parse(&self.k, p).unwrap()).unwrap();
        (sp, ax)
    }

    /// The larger relative error of (I1, I2) against mpmath, in ε of the working precision.
    pub fn error_eps<T: Real>(&self, i1: &T, i2: &T) -> f64 {
        rel_eps(i1, &self.i1).max(rel_eps(i2, &self.i2))
    }
}

/// A route's (I1, I2) against the mpmath rows whose axis ratio `keep` selects (inputs parsed at
/// `p`): each within `bound` ε of the working precision, `count` rows in all.
pub fn check_mpmath_rows<T: Real>(
    label: &str,
    p: T::Prec,
    keep: impl Fn(&T) -> bool,
    (bound, count): (f64, usize),
    route: impl Fn(&Speed<T>, &AxisRatio<T>) -> (T, T),
) {
    let mut n = 0;
    for c in mpmath_cases() {
        let (sp, ax) = c.inputs::<T>(p);
        if !keep(&ax.k) {
            continue;
        }
        let (i1, i2) = route(&sp, &ax);
        let e = c.error_eps(&i1, &i2);
        assert!(
            e <= bound,
            "{label} nu={} M_R={} k={}: {e:.1} eps",
            c.nu,
            c.mr,
            c.k
        );
        n += 1;
    }
    assert_eq!(n, count, "{label}: rows checked");
}

// ---------------------------------------------------------------------------------------------
// Sweeps

use moving_hertz::physics::{Moduli, Solid};
use moving_hertz::sweep::{EllipsePoint, SpeedGiven};
use moving_hertz::{solve_ellipse, Ellipse, Options};

/// Bits above the working precision at which [`independent`] solves a point.
pub const INDEPENDENT_GUARD: u32 = 64;

/// A value of any precision as an MPFR number of `p` bits, exactly (`p` ≥ its bits).
pub fn up<T: Real>(x: &T, p: MpPrec) -> Mp {
    Mp::from_float(&x.to_float(T::bits(x.prec())), p)
}

/// The same sweep point solved on its own, by `solve_ellipse` with default options, at
/// [`INDEPENDENT_GUARD`] bits above the point's precision (MPFR), its inputs converted exactly:
/// a reference that shares neither the sweep's seeds and continuation nor its roundings.
pub fn independent<T: Real>(pt: &EllipsePoint<T>) -> moving_hertz::Result<Ellipse<Mp>> {
    let p = MpPrec::new(u64::from(T::bits(pt.nu.prec()) + INDEPENDENT_GUARD)).unwrap();
    let mat = Material::new(up(&pt.nu, p))?;
    let speed = match &pt.speed {
        SpeedGiven::Mr(m) => mat.speed(up(m, p))?,
        SpeedGiven::Gap(g) => mat.speed_from_gap(up(g, p))?,
        SpeedGiven::Text(m) => mat.parse_speed(m)?,
        SpeedGiven::Velocity { velocity, moduli } => {
            let moduli = match moduli {
                Moduli::Youngs {
                    youngs_modulus,
                    density,
                } => Moduli::Youngs {
                    youngs_modulus: up(youngs_modulus, p),
                    density: up(density, p),
                },
                Moduli::Shear {
                    shear_modulus,
                    density,
                } => Moduli::Shear {
                    shear_modulus: up(shear_modulus, p),
                    density: up(density, p),
                },
                other => panic!("moduli this test does not convert: {other:?}"),
            };
            Solid::new(&mat, moduli)?.speed_from_velocity(up(velocity, p))?
        }
        other => panic!("a speed this test does not convert: {other:?}"),
    };
    solve_ellipse(&speed, &up(&pt.ratio, p), &Options::default())
}

/// |k − k_ref|/k_ref over the sum of both bounds (≤ 1: within the bounds), `want` from
/// [`independent`].
pub fn within<T: Real>(got: &Ellipse<T>, want: &Ellipse<Mp>) -> f64 {
    let k = up(&got.k().value, want.k().value.prec());
    let d = ((k - &want.k().value) / &want.k().value).abs();
    d.to_f64() / (got.k().error.to_f64() + want.k().error.to_f64())
}
