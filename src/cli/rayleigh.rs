//! `moving-hertz rayleigh`: the Rayleigh root and the other two roots of the cubic.

use super::args::Args;
use super::json::{s, Json};
use moving_hertz::physics::Material;
use moving_hertz::scalar::Real;
use moving_hertz::with_precision;

pub fn run(args: &Args) -> Result<(), String> {
    let nu_text = args.required("nu")?;
    let prec = args.precision()?;
    let json = args.flag("json");
    with_precision!(prec, T, p => {
        let nu = T::parse(nu_text, p).map_err(|e| format!("--nu: {e}"))?;
        let mat = Material::new(nu).map_err(|e| e.to_string())?;
        let r = mat.roots();
        let roots = r.all();
        if json {
            let obj = Json::Obj(vec![
                ("nu".into(), s(mat.nu().to_decimal())),
                ("precision".into(), s(prec.label())),
                ("m1".into(), s(r.m1.to_decimal())),
                ("cR_over_c2".into(), s(mat.cr_over_c2().to_decimal())),
                (
                    "roots".into(),
                    Json::Arr(
                        roots
                            .iter()
                            .map(|z| Json::Arr(vec![s(z.re.to_decimal()), s(z.im.to_decimal())]))
                            .collect(),
                    ),
                ),
            ]);
            println!("{}", obj.render());
        } else {
            println!("Rayleigh cubic (1-nu)x^3 - 8(1-nu)x^2 + 8(2-nu)x - 8 = 0, x = (V/c2)^2");
            println!("nu        = {}", mat.nu().to_decimal());
            println!("precision = {} ({} bits)", prec.label(), prec.bits());
            println!("m1 = (c_R/c2)^2 = {}", r.m1.to_decimal());
            println!("c_R/c2          = {}", mat.cr_over_c2().to_decimal());
            println!("c_R/c1          = {}", mat.cr_over_c1().to_decimal());
            for (i, z) in roots.iter().enumerate() {
                println!("root m{}: re = {}  im = {}", i + 1, z.re.to_decimal(), z.im.to_decimal());
            }
        }
        Ok(())
    })
}
