//! `moving-hertz ellipse` and `moving-hertz contact`: the contact ellipse's shape (33) and the
//! full moving-punch Hertz solution.

use super::args::Args;
use super::json::{s, Json};
use moving_hertz::physics::Material;
use moving_hertz::scalar::Real;
use moving_hertz::{solve_ellipse, with_precision, ContactProblem, Loading, Method, Options};
use std::time::Instant;

fn parse<T: Real>(name: &str, text: &str, p: T::Prec) -> Result<T, String> {
    T::parse(text, p).map_err(|e| format!("--{name}: {e}"))
}

pub fn ellipse(args: &Args) -> Result<(), String> {
    let prec = args.precision()?;
    let json = args.flag("json");
    let method = Method::parse(args.optional("method").unwrap_or("auto"))
        .map_err(|e| format!("--method: {e}"))?;

    let repeat: usize = match args.optional("repeat") {
        Some(r) => r
            .parse()
            .map_err(|_| format!("--repeat: cannot parse {r:?}"))?,
        None => 0,
    };
    with_precision!(prec, T, p => {
        let mat = Material::<T>::parse(args.required("nu")?, p).map_err(|e| format!("--nu: {e}"))?;
        let sp = mat.parse_speed(args.required("speed")?).map_err(|e| format!("--speed: {e}"))?;
        let ratio = parse::<T>("ratio", args.required("ratio")?, p)?;
        let opts = Options::<T> { method, ..Default::default() };
        let sol = solve_ellipse(&sp, &ratio, &opts).map_err(|e| e.to_string())?;
        let mut times: Vec<f64> = (0..repeat)
            .map(|_| {
                let t = Instant::now();
                let r = solve_ellipse(&sp, &ratio, &opts);
                let ns = t.elapsed().as_nanos() as f64;
                std::hint::black_box(r.is_ok());
                ns
            })
            .collect();
        times.sort_by(|a, b| a.total_cmp(b));
        let ci = &sol.integrals;
        if json {
            let mut fields = vec![
                ("k".into(), s(sol.k.value.to_decimal())),
                ("e".into(), s(sol.e.value.to_decimal())),
                ("I1".into(), s(ci.i1.value.to_decimal())),
                ("I2".into(), s(ci.i2.value.to_decimal())),
                ("method".into(), s(ci.route.label())),
                ("precision".into(), s(prec.label())),
                ("error_estimate".into(), s(format!("{}", sol.k.error))),
                ("major_axis".into(), s(sol.major.label())),
            ];
            if !times.is_empty() {
                fields.push(("median_ns".into(), s(format!("{:.0}", times[times.len() / 2]))));
                fields.push(("min_ns".into(), s(format!("{:.0}", times[0]))));
            }
            println!("{}", Json::Obj(fields).render());
        } else {
            println!("contact ellipse for A1/B1 = R2/R1 = {} at M_R = {}, nu = {}", ratio.to_decimal(), sp.mr().to_decimal(), mat.nu().to_decimal());
            println!("k = b/a (across/along the motion) = {}", sol.k.value.to_decimal());
            println!("eccentricity e = {}  (major axis {} the motion)", sol.e.value.to_decimal(), sol.major.label());
            println!("I1 = {}", ci.i1.value.to_decimal());
            println!("I2 = {}", ci.i2.value.to_decimal());
            println!("relative error estimate of k: {}; {} Newton steps at {}", sol.k.error, sol.iterations, prec.label());
            if !times.is_empty() {
                println!("time per solve over {} runs: median {:.0} ns, min {:.0} ns", times.len(), times[times.len() / 2], times[0]);
            }
        }
        Ok(())
    })
}

pub fn contact(args: &Args) -> Result<(), String> {
    let prec = args.precision()?;
    let json = args.flag("json");
    with_precision!(prec, T, p => {
        let mat = Material::<T>::parse(args.required("nu")?, p).map_err(|e| format!("--nu: {e}"))?;
        let sp = mat.parse_speed(args.required("speed")?).map_err(|e| format!("--speed: {e}"))?;
        let r1 = parse::<T>("r-along", args.required("r-along")?, p)?;
        let r2 = parse::<T>("r-across", args.required("r-across")?, p)?;
        let mu = parse::<T>("shear-modulus", args.required("shear-modulus")?, p)?;
        let loading = match (args.optional("load"), args.optional("approach")) {
            (Some(l), None) => Loading::Load(parse::<T>("load", l, p)?),
            (None, Some(d)) => Loading::Approach(parse::<T>("approach", d, p)?),
            _ => return Err("`contact` needs exactly one of --load P or --approach D0".into()),
        };
        let problem = ContactProblem { speed: sp.clone(), radius_along: r1, radius_across: r2, loading, shear_modulus: mu };
        let sol = problem.solve(&Options::default()).map_err(|e| e.to_string())?;
        if json {
            let obj = Json::Obj(vec![
                ("a".into(), s(sol.a.to_decimal())),
                ("b".into(), s(sol.b.to_decimal())),
                ("k".into(), s(sol.k().to_decimal())),
                ("e".into(), s(sol.e().to_decimal())),
                ("p0".into(), s(sol.p0.to_decimal())),
                ("d0".into(), s(sol.d0.to_decimal())),
                ("load".into(), s(sol.load.to_decimal())),
                ("precision".into(), s(prec.label())),
                ("error_estimate".into(), s(format!("{}", sol.k().error))),
            ]);
            println!("{}", obj.render());
        } else {
            println!("moving rigid punch on an elastic half-space, nu = {}, M_R = V/c_R = {}", mat.nu().to_decimal(), sp.mr().to_decimal());
            println!("(units: as given; SI inputs give SI outputs: m, Pa, N)");
            println!("semi-axis along the motion  a  = {}", sol.a.to_decimal());
            println!("semi-axis across the motion b  = {}", sol.b.to_decimal());
            println!("axis ratio k = b/a             = {}", sol.k().to_decimal());
            println!("eccentricity e                 = {}  (major axis {} the motion)", sol.e().to_decimal(), sol.ellipse.major.label());
            println!("central pressure p0            = {}", sol.p0.to_decimal());
            println!("approach d0                    = {}", sol.d0.to_decimal());
            println!("load P                         = {}", sol.load.to_decimal());
            println!("relative error estimate (k): {} at {}", sol.k().error, prec.label());
        }
        Ok(())
    })
}
