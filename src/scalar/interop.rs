//! Interoperability with `num-traits` and `num-complex` for the `Copy` backends.
//!
//! `rug::Float` cannot implement `num_traits::Num` (it is not `Copy` and rug gives it no `Zero`),
//! which is why the crate's formulas are written over its own [`super::Field`]/[`super::Real`].
//! For `f64` and [`Dd`] the standard traits fit, so [`Dd`] implements `Zero`, `One`, `Num`,
//! `ToPrimitive`, `FromPrimitive` — enough for `num_complex::Complex<Dd>` to do arithmetic — and the
//! crate's [`Complex`] converts to and from `num_complex::Complex` for `f64` and [`Dd`].

use super::{Complex, Dd, Field, FieldOps, Real};

impl num_traits::Zero for Dd {
    fn zero() -> Dd {
        Dd::from_f64_exact(0.0)
    }
    fn is_zero(&self) -> bool {
        FieldOps::is_zero(self)
    }
}

impl num_traits::One for Dd {
    fn one() -> Dd {
        Dd::from_f64_exact(1.0)
    }
}

impl std::ops::Rem for Dd {
    type Output = Dd;
    /// Remainder with the sign of the dividend: `self − trunc(self/rhs)·rhs`.
    fn rem(self, rhs: Dd) -> Dd {
        let q = self / rhs;
        let t = if q.is_negative() {
            -((-q).floor())
        } else {
            q.floor()
        };
        self - t * rhs
    }
}

impl num_traits::Num for Dd {
    type FromStrRadixErr = crate::Error;
    /// Decimal text only (radix 10), parsed at double-double precision.
    fn from_str_radix(s: &str, radix: u32) -> Result<Dd, crate::Error> {
        if radix != 10 {
            return Err(crate::Error::Parse {
                text: s.to_string(),
                reason: "only radix 10 is supported",
            });
        }
        Dd::parse(s, ())
    }
}

impl num_traits::ToPrimitive for Dd {
    fn to_i64(&self) -> Option<i64> {
        let f = Field::to_f64(self);
        (f.is_finite() && f.abs() < 9.2e18).then_some(f as i64)
    }
    fn to_u64(&self) -> Option<u64> {
        let f = Field::to_f64(self);
        (f.is_finite() && (0.0..1.8e19).contains(&f)).then_some(f as u64)
    }
    fn to_f64(&self) -> Option<f64> {
        Some(Field::to_f64(self))
    }
}

impl num_traits::FromPrimitive for Dd {
    fn from_i64(n: i64) -> Option<Dd> {
        Some(<Dd as FieldOps>::from_i64(n, ()))
    }
    fn from_u64(n: u64) -> Option<Dd> {
        let hi = n as f64;
        let lo = (n as i128 - hi as i128) as f64;
        Some(Dd::from_parts(hi, lo))
    }
    fn from_f64(x: f64) -> Option<Dd> {
        Some(Dd::from_f64_exact(x))
    }
}

macro_rules! complex_conversions {
    ($t:ty) => {
        impl From<Complex<$t>> for num_complex::Complex<$t> {
            fn from(z: Complex<$t>) -> Self {
                num_complex::Complex::new(z.re, z.im)
            }
        }
        impl From<num_complex::Complex<$t>> for Complex<$t> {
            fn from(z: num_complex::Complex<$t>) -> Self {
                Complex::new(z.re, z.im)
            }
        }
    };
}

complex_conversions!(f64);
complex_conversions!(Dd);
