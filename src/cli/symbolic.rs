//! `moving-hertz symbolic coefficients|moments --n N [--format text|latex|sympy|json]`: the
//! coefficients of (36) as rational functions of ν and those of (40) as rational functions of e²,
//! exact (`moving_hertz::symbolic`).

use moving_hertz::symbolic::{
    coefficient_items, green_coefficients, moment_forms, moment_items, render, Style,
    MAX_COEFFICIENT_INDEX, MAX_MOMENT_INDEX,
};

/// What to derive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SymbolicKind {
    /// f_n = F_n(ν)·x^n, n = 0 … N, and the paper's printed f1, f2 beside them.
    Coefficients,
    /// α_n, β_n, γ_n, δ_n(e²), n = 0 … N: L_n = α_n K + β_n E, M_n = γ_n K + δ_n E.
    Moments,
}

impl SymbolicKind {
    /// `coefficients` or `moments`.
    pub fn parse(s: &str) -> Result<Self, String> {
        match s {
            "coefficients" => Ok(SymbolicKind::Coefficients),
            "moments" => Ok(SymbolicKind::Moments),
            other => Err(format!(
                "`symbolic` takes `coefficients` or `moments`, not `{other}`"
            )),
        }
    }
}

/// The output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SymbolicFormat {
    /// Plain text.
    Text,
    /// LaTeX (`align*`).
    Latex,
    /// `name = expression` lines for `sympy.sympify`.
    Sympy,
    /// JSON with the canonical coefficient lists.
    Json,
}

impl SymbolicFormat {
    /// `text`, `latex`, `sympy` or `json`.
    pub fn parse(s: &str) -> Result<Self, String> {
        match s {
            "text" => Ok(SymbolicFormat::Text),
            "latex" => Ok(SymbolicFormat::Latex),
            "sympy" => Ok(SymbolicFormat::Sympy),
            "json" => Ok(SymbolicFormat::Json),
            other => Err(format!(
                "--format: `{other}` is not one of text, latex, sympy, json"
            )),
        }
    }
}

/// The largest index `--n` may take: [`MAX_COEFFICIENT_INDEX`] or [`MAX_MOMENT_INDEX`] (each
/// derived in about a second).
pub fn parse_n(s: &str) -> Result<usize, String> {
    s.trim()
        .parse::<usize>()
        .map_err(|_| format!("--n: `{s}` is not a non-negative integer"))
}

/// Derives and prints the functions of `kind` for indices 0 … `n` in `format`.
pub fn run(kind: SymbolicKind, n: usize, format: SymbolicFormat) -> Result<(), String> {
    let style = match format {
        SymbolicFormat::Text => Style::Text,
        SymbolicFormat::Latex => Style::Latex,
        SymbolicFormat::Sympy => Style::Sympy,
        SymbolicFormat::Json => Style::Json,
    };
    let err = |e: moving_hertz::Error| format!("--n: {e}");
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
    };
    print!("{}", render(&title, &items, style));
    Ok(())
}
