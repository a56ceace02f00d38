//! `moving-hertz symbolic coefficients|moments --n N [--format text|sympy]`: the coefficients of
//! (36) as rational functions of ν and those of (40) as rational functions of e², exact
//! (`moving_hertz::symbolic`); `symbolic condition --n N`: what the closed forms say about the
//! K, E basis (the pole at e² = 0, the bits lost on a grid of e²).

use super::output::emit;
use super::CliError;
use moving_hertz::routes::moments::KeTerm;
use moving_hertz::scalar::decimal_to_rational;
use moving_hertz::symbolic::{
    coefficient_items, green_coefficients, ke_condition, moment_forms, moment_items, pole_terms,
    render, RatFunc, Style, MAX_COEFFICIENT_INDEX, MAX_MOMENT_INDEX,
};
use std::fmt::Write as _;

/// The e² of the condition table: both sides of 1/2 and k > 1.
const E2_GRID: [&str; 12] = [
    "0.99",
    "0.9",
    "0.75",
    "0.5625",
    "0.5",
    "0.4375",
    "0.25",
    "0.0625",
    "0.00390625",
    "-1",
    "-15",
    "-255",
];

/// The n of the condition table.
fn n_grid(n: usize) -> Vec<usize> {
    let mut v: Vec<usize> = [1, 2, 5, 10, 20, 50, 100, 150]
        .into_iter()
        .filter(|&k| k < n)
        .collect();
    v.push(n);
    v
}

/// The pole of α_n, β_n at e² = 0 and the bits lost by α_n K + β_n E on [`E2_GRID`], as the
/// text to print.
fn condition(forms: &[KeTerm<RatFunc>]) -> Result<String, String> {
    let n = forms.len() - 1;
    let ns = n_grid(n);
    let poles = pole_terms(forms);
    let mut rows = Vec::new();
    for e2 in E2_GRID {
        let q = decimal_to_rational(e2).map_err(|e| e.to_string())?;
        let bits = ke_condition(forms, &q).map_err(|e| e.to_string())?;
        rows.push((e2, ns.iter().map(|&k| bits[k].0).collect::<Vec<f64>>()));
    }
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# (40), (42) in closed form: L_n = alpha_n K + beta_n E, e2 = e^2 = 1 - k^2"
    );
    let _ = writeln!(
        out,
        "# near e2 = 0: alpha_n = a_n e2^-p (1 + O(e2)), beta_n = b_n e2^-p (1 + O(e2))"
    );
    let _ = writeln!(out, "n\tp\ta_n\tb_n");
    for &k in &ns {
        let t = &poles[k];
        let _ = writeln!(out, "{}\t{}\t{}\t{}", t.n, t.order, t.alpha, t.beta);
    }
    let _ = writeln!(
        out,
        "# bits lost by alpha_n K + beta_n E: log2((|alpha_n| K + |beta_n| E) / L_n)"
    );
    let head: Vec<String> = ns.iter().map(|k| format!("n={k}")).collect();
    let _ = writeln!(out, "e2\t{}", head.join("\t"));
    for (e2, b) in rows {
        let b: Vec<String> = b.iter().map(|x| format!("{x:.2}")).collect();
        let _ = writeln!(out, "{e2}\t{}", b.join("\t"));
    }
    Ok(out)
}

/// `moving-hertz symbolic KIND --n N [--format FORMAT]`.
#[derive(clap::Args, Debug)]
pub struct SymbolicArgs {
    /// What to derive: `coefficients` (f_n of (35)-(36) as F_n(nu) x^n, n = 0..N, with the
    /// paper's printed f1, f2 beside them), `moments` (alpha_n..delta_n(e2) of (40),
    /// L_n = alpha_n K + beta_n E, M_n = gamma_n K + delta_n E) or `condition` (the pole of
    /// alpha_n, beta_n at e2 = 0 and the bits the K, E basis loses on a grid of e2).
    #[arg(value_enum)]
    pub kind: SymbolicKind,
    /// The largest index N: 1 <= N <= 120 for coefficients, 1 <= N <= 150 for moments and
    /// condition (each derived in about a second).
    #[arg(long, value_name = "N")]
    pub n: usize,
    /// Output: plain text or sympy (`name = expression` lines that `sympy.sympify` parses, in
    /// the variables nu, x, e2). `condition` prints text.
    #[arg(long, value_enum, default_value = "text")]
    pub format: SymbolicFormat,
}

/// What to derive.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum SymbolicKind {
    /// f_n = F_n(ν)·x^n, n = 0 … N, and the paper's printed f1, f2 beside them.
    Coefficients,
    /// α_n, β_n, γ_n, δ_n(e²), n = 0 … N: L_n = α_n K + β_n E, M_n = γ_n K + δ_n E.
    Moments,
    /// From the closed forms: the pole of α_n, β_n at e² = 0 and the bits lost by the K, E basis
    /// on a grid of e² (text only).
    Condition,
}

/// The output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum SymbolicFormat {
    /// Plain text.
    Text,
    /// `name = expression` lines for `sympy.sympify`.
    Sympy,
}

/// Derives and prints the functions of `kind` for indices 0 … `n` in `format`.
pub fn run(kind: SymbolicKind, n: usize, format: SymbolicFormat) -> Result<(), CliError> {
    let max = match kind {
        SymbolicKind::Coefficients => MAX_COEFFICIENT_INDEX,
        _ => MAX_MOMENT_INDEX,
    };
    if n == 0 || n > max {
        let why = format!("n = {n} is outside 1 <= n <= {max}");
        return Err(CliError::value("--n", &n.to_string(), why));
    }
    let style = match format {
        SymbolicFormat::Text => Style::Text,
        SymbolicFormat::Sympy => Style::Sympy,
    };
    let err = |e: moving_hertz::Error| CliError::Failed(e.to_string());
    if kind == SymbolicKind::Condition {
        if style != Style::Text {
            return Err(CliError::Input(
                "invalid value for '--format': `symbolic condition` prints text".into(),
            ));
        }
        let text = condition(&moment_forms(n).map_err(err)?).map_err(CliError::Failed)?;
        return emit(&text);
    }
    let (title, items) = match kind {
        SymbolicKind::Coefficients => (
            format!(
                "(35)-(36) corrected: g = -pi*Gamma = sum_n f_n, f_n = F_n(nu) x^n, x = M2^2, \
                 n <= {n} (max {MAX_COEFFICIENT_INDEX}); then the paper's f1, f2 as printed"
            ),
            coefficient_items(&green_coefficients(n).map_err(err)?),
        ),
        SymbolicKind::Moments => (
            format!(
                "(40), (42): L_n = alpha_n K + beta_n E, M_n = gamma_n K + delta_n E, \
                 K = K(e), E = E(e), e2 = e^2 = 1 - k^2, n <= {n} (max {MAX_MOMENT_INDEX})"
            ),
            moment_items(&moment_forms(n).map_err(err)?),
        ),
        SymbolicKind::Condition => unreachable!("handled above"),
    };
    emit(&render(&title, &items, style))
}
