//! `moving-hertz rayleigh`: the Rayleigh root and the other two roots of the cubic (section 3).

use super::args::{self, Decimal};
use super::output::{print_json, Obj, OutputArgs, Text};
use super::CliError;
use moving_hertz::scalar::{Precision, Real};
use moving_hertz::{with_precision, Material};

#[derive(clap::Args, Debug)]
pub struct RayleighArgs {
    /// Poisson's ratio ν, -1 < NU <= 1/2 (dimensionless; decimal or p/q, checked exactly
    /// before it is rounded).
    #[arg(long, value_name = "NU", value_parser = args::decimal, allow_hyphen_values = true)]
    pub nu: Decimal,
    /// The working precision: f64, dd (double-double, 106 bits) or a number of MPFR bits from
    /// 24 to 1048576 (the crate's MPFR limit: the roots need no quadrature rule), written 256 or
    /// mpfr256 as the output labels it.
    #[arg(long, value_name = "P", default_value = "f64", value_parser = args::precision_any)]
    pub precision: Precision,
    #[command(flatten)]
    pub output: OutputArgs,
}

pub fn run(a: &RayleighArgs) -> Result<(), CliError> {
    with_precision!(a.precision, T, p => {
        let mat = Material::<T>::parse(&a.nu.text, p).map_err(|e| CliError::value("--nu", &a.nu.text, e))?;
        report(a, &mat)
    })
}

fn report<T: Real>(a: &RayleighArgs, mat: &Material<T>) -> Result<(), CliError> {
    let prec = a.precision;
    let r = mat.roots();
    let roots = r.all();
    if a.output.json {
        let inputs = (Obj::default().put("nu", a.nu.text.as_str())).put("precision", prec.label());
        let roots = roots
            .iter()
            .map(|z| vec![z.re.to_decimal(), z.im.to_decimal()]);
        return print_json(
            &(Obj::head("rayleigh", inputs, prec).put("m1", r.m1.to_decimal()))
                .put("cR_over_c2", mat.cr_over_c2().to_decimal())
                .put("cR_over_c1", mat.cr_over_c1().to_decimal())
                .put("roots", roots.collect::<Vec<_>>()),
        );
    }
    let mut t = Text::new(a.output.digits);
    t.line(format!(
        "Rayleigh cubic (1-nu)x^3 - 8(1-nu)x^2 + 8(2-nu)x - 8 = 0, x = (V/c2)^2, for nu = {}",
        a.nu.text
    ));
    t.line(format!("at {} ({} bits)", prec.label(), prec.bits()));
    t.plain("m1 = (c_R/c2)^2, the Rayleigh root", &r.m1);
    t.plain("c_R/c2", &mat.cr_over_c2());
    t.plain("c_R/c1", &mat.cr_over_c1());
    for (i, z) in roots.iter().enumerate() {
        t.line(format!("root m{} (real part, imaginary part):", i + 1));
        t.line(format!("  {}", t.value(&z.re)));
        t.line(format!("  {}", t.value(&z.im)));
    }
    t.print()
}
