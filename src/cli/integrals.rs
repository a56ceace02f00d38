//! `moving-hertz integrals`: I1 and I2 of (34) (normalisation of (37)) by a chosen or automatic
//! method, at a chosen precision or the lowest one reaching `--tol`.

use super::args::Args;
use super::json::{s, Json};
use moving_hertz::routes::choose::{self, Inputs, MethodRequest};
use moving_hertz::scalar::{Field, Real};
use moving_hertz::with_precision;

pub fn run(args: &Args) -> Result<(), String> {
    let inputs = Inputs::parse(
        args.required("nu")?,
        args.required("speed")?,
        args.required("k")?,
    )
    .map_err(|e| e.to_string())?;
    let request = MethodRequest::parse(args.optional("method").unwrap_or("auto"))
        .map_err(|e| format!("--method: {e}"))?;
    let json = args.flag("json");
    let tol = match args.optional("tol") {
        Some(t) => Some(
            t.trim()
                .parse::<f64>()
                .map_err(|_| format!("--tol: cannot parse {t:?}"))?,
        ),
        None => None,
    };
    // (I1, I2, error estimate, method, precision, work), values printed at the working precision.
    let (i1, i2, est, method, prec, work) = match (tol, args.optional("precision")) {
        (Some(tol), None) => {
            let a = choose::integrals(&inputs, tol, request).map_err(|e| e.to_string())?;
            let (i1, i2) = with_precision!(a.precision, T, p => {
                (T::from_float(&a.i1, p).to_decimal(), T::from_float(&a.i2, p).to_decimal())
            });
            (i1, i2, a.error_estimate, a.method, a.precision, a.work)
        }
        (tol, _) => {
            let prec = args.precision()?;
            let method = match request {
                MethodRequest::Auto => choose::choose_method(
                    &inputs,
                    tol.unwrap_or_else(|| 2f64.powi(1 - prec.bits() as i32))
                        .max(1e-300),
                ),
                MethodRequest::Fixed(m) => m,
            };
            with_precision!(prec, T, p => {
                let r = choose::run_at::<T>(&inputs, p, method, tol.unwrap_or(0.0))
                    .map_err(|e| e.to_string())?;
                let eps = T::epsilon(p).to_f64();
                let est = r.error_estimate.to_f64() + inputs.condition() * eps;
                (r.i1.to_decimal(), r.i2.to_decimal(), est, r.method, prec, r.work)
            })
        }
    };
    if json {
        let obj = Json::Obj(vec![
            ("I1".into(), s(i1)),
            ("I2".into(), s(i2)),
            ("method".into(), s(method.label())),
            ("precision".into(), s(prec.label())),
            ("error_estimate".into(), s(format!("{est:.3e}"))),
            ("work".into(), s(work.to_string())),
        ]);
        println!("{}", obj.render());
    } else {
        println!("I1 = {i1}");
        println!("I2 = {i2}");
        println!("A1/B1 = I2/I1 for this k; normalisation of (37) (pi times the paper's (34))");
        println!(
            "method {} at {} ({} bits), {} evaluations/terms, relative error estimate {:.2e}",
            method.label(),
            prec.label(),
            prec.bits(),
            work,
            est
        );
    }
    Ok(())
}
