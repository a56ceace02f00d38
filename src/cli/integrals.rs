//! `moving-hertz integrals`: I1 and I2 of (34) (normalisation of (37)) by a chosen or automatic
//! method, at a chosen precision or the lowest one reaching `--tol`.

use super::args::Args;
use super::json::{s, Json};
use moving_hertz::scalar::Real;
use moving_hertz::{
    integrals, integrals_to_tolerance, with_precision, ExactInputs, IntegralOptions, Method,
    RelError,
};

pub fn run(args: &Args) -> Result<(), String> {
    let inputs = ExactInputs::parse(
        args.required("nu")?,
        args.required("speed")?,
        args.required("k")?,
    )
    .map_err(|e| e.to_string())?;
    let method = Method::parse(args.optional("method").unwrap_or("auto"))
        .map_err(|e| format!("--method: {e}"))?;
    let json = args.flag("json");
    let tol = match args.optional("tol") {
        Some(t) => Some(RelError::parse(t).map_err(|e| format!("--tol: {e}"))?),
        None => None,
    };
    let r = match (tol, args.optional("precision")) {
        (Some(tol), None) => {
            integrals_to_tolerance(&inputs, tol, method).map_err(|e| e.to_string())?
        }
        (tol, _) => {
            let prec = args.precision()?;
            with_precision!(prec, T, p => {
                let (sp, k) = inputs.at::<T>(p).map_err(|e| e.to_string())?;
                let opts = IntegralOptions { method, tolerance: tol, ..Default::default() };
                let r = integrals(&sp, &k, &opts).map_err(|e| e.to_string())?;
                let bits = T::bits(p) + 64;
                let up = |e: moving_hertz::Estimated<T>| moving_hertz::Estimated::new(
                    moving_hertz::Mp::from_float(&e.value.to_float(bits), moving_hertz::MpPrec::clamped(bits)), e.error);
                moving_hertz::Integrals { i1: up(r.i1), i2: up(r.i2), di1_dk: None, di2_dk: None, j0: None, route: r.route, precision: r.precision, work: r.work }
            })
        }
    };
    let prec = r.precision;
    let (i1, i2) = with_precision!(prec, T, p => {
        (T::from_float(&r.i1.value.to_float(T::bits(p) + 64), p).to_decimal(),
         T::from_float(&r.i2.value.to_float(T::bits(p) + 64), p).to_decimal())
    });
    let est = r.i1.error.max(r.i2.error);
    if json {
        let obj = Json::Obj(vec![
            ("I1".into(), s(i1)),
            ("I2".into(), s(i2)),
            ("method".into(), s(r.route.label())),
            ("precision".into(), s(prec.label())),
            ("error_estimate".into(), s(format!("{est}"))),
            ("work".into(), s(r.work.to_string())),
        ]);
        println!("{}", obj.render());
    } else {
        println!("I1 = {i1}");
        println!("I2 = {i2}");
        println!("A1/B1 = I2/I1 for this k; normalisation of (37) (pi times the paper's (34))");
        println!(
            "route {} at {} ({} bits), {} evaluations/terms, relative error estimate {}",
            r.route.label(),
            prec.label(),
            prec.bits(),
            r.work,
            est
        );
    }
    Ok(())
}
