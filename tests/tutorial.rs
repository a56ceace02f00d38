//! docs/tutorial.md's snippets: every ```rust block is quoted verbatim (up to a common
//! indentation) from the example program it names (`examples/NAME.rs`), and every example the
//! tutorial quotes runs to completion here.

#[path = "../examples/contact_solution.rs"]
mod contact_solution;
#[path = "../examples/error_estimates.rs"]
mod error_estimates;
#[path = "../examples/precision_cost.rs"]
mod precision_cost;
#[path = "../examples/series_convergence.rs"]
mod series_convergence;
#[path = "../examples/sweep_curves.rs"]
mod sweep_curves;

const TUTORIAL: &str = include_str!("../docs/tutorial.md");

/// The examples run below, by file name.
const RUN: [&str; 5] = [
    "contact_solution",
    "error_estimates",
    "precision_cost",
    "series_convergence",
    "sweep_curves",
];

/// (example name, snippet) for every ```rust block, the example being the last
/// `examples/NAME.rs` named before the block.
fn snippets() -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut named: Option<String> = None;
    let mut block: Option<String> = None;
    for line in TUTORIAL.lines() {
        match &mut block {
            Some(b) if line.trim_start().starts_with("```") => {
                let name = named
                    .clone()
                    .expect("a snippet names its example before it");
                out.push((name, std::mem::take(b)));
                block = None;
            }
            Some(b) => {
                b.push_str(line);
                b.push('\n');
            }
            None if line.trim_start().starts_with("```rust") => block = Some(String::new()),
            None => {
                if let Some(i) = line.rfind("examples/") {
                    let rest = &line[i + "examples/".len()..];
                    if let Some(end) = rest.find(".rs") {
                        named = Some(rest[..end].to_string());
                    }
                }
            }
        }
    }
    out
}

#[test]
fn every_snippet_is_quoted_from_its_example() {
    let all = snippets();
    assert!(all.len() >= RUN.len(), "{} snippets", all.len());
    for (name, text) in &all {
        let path = format!("{}/examples/{name}.rs", env!("CARGO_MANIFEST_DIR"));
        let source = std::fs::read_to_string(&path).expect("the example exists");
        let quoted = (0..4).any(|level| {
            let pad = "    ".repeat(level);
            let indented: String = text
                .lines()
                .map(|l| {
                    if l.is_empty() {
                        "\n".to_string()
                    } else {
                        format!("{pad}{l}\n")
                    }
                })
                .collect();
            source.contains(indented.as_str())
        });
        assert!(
            quoted,
            "docs/tutorial.md: a snippet is not in {path}:\n{text}"
        );
        assert!(
            RUN.contains(&name.as_str()),
            "{name} is quoted but not run here"
        );
    }
}

#[test]
fn the_tutorials_examples_run() {
    contact_solution::main().expect("contact_solution");
    error_estimates::main().expect("error_estimates");
    precision_cost::main().expect("precision_cost");
    series_convergence::main().expect("series_convergence");
    sweep_curves::main().expect("sweep_curves");
}
