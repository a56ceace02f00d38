//! docs/tutorial.md's snippets: every ```rust block is quoted verbatim (up to a common
//! indentation) from the example program it names (`examples/NAME.rs`), every example the
//! tutorial quotes runs to completion here, and every output the tutorial shows ("prints" and a
//! ```text block) is what the example's binary prints.

#[path = "../examples/contact_solution.rs"]
mod contact_solution;
#[path = "../examples/error_estimates.rs"]
mod error_estimates;
#[path = "../examples/precision_cost.rs"]
mod precision_cost;
#[path = "../examples/series_convergence.rs"]
mod series_convergence;
#[path = "../examples/steel_in_si_units.rs"]
mod steel_in_si_units;
#[path = "../examples/sweep_curves.rs"]
mod sweep_curves;

const TUTORIAL: &str = include_str!("../docs/tutorial.md");

/// The examples run below, by file name.
const RUN: [&str; 6] = [
    "contact_solution",
    "error_estimates",
    "precision_cost",
    "series_convergence",
    "steel_in_si_units",
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
    steel_in_si_units::main().expect("steel_in_si_units");
    sweep_curves::main().expect("sweep_curves");
}

/// (example name, the text the tutorial says it prints): every ```text block that follows a
/// line "prints", the example being the last `cargo run --release --example NAME` before it.
fn printed_outputs() -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut ran: Option<String> = None;
    let mut lines = TUTORIAL.lines().peekable();
    while let Some(line) = lines.next() {
        if let Some(name) = line.trim().strip_prefix("cargo run --release --example ") {
            ran = Some(name.trim().to_string());
        }
        if line.trim() != "prints" {
            continue;
        }
        while lines.peek().is_some_and(|l| l.trim().is_empty()) {
            lines.next();
        }
        if lines.next().map(str::trim) != Some("```text") {
            continue;
        }
        let mut text = String::new();
        for l in lines.by_ref().take_while(|l| l.trim() != "```") {
            text.push_str(l);
            text.push('\n');
        }
        let name = ran
            .clone()
            .expect("a printed output names its example before it");
        out.push((name, text));
    }
    out
}

/// What the tutorial says an example prints is what it prints: the example's binary (which
/// `cargo test` builds beside the tests, in `target/<profile>/examples/`) is run and its
/// standard output compared with the block, digit for digit.
#[test]
fn the_printed_outputs_are_current() {
    let outputs = printed_outputs();
    assert!(outputs.len() >= 3, "{} printed outputs", outputs.len());
    let exe = std::env::current_exe().expect("the test binary's path");
    let dir = exe
        .parent()
        .and_then(|deps| deps.parent())
        .expect("target/<profile>/deps")
        .join("examples");
    for (name, expected) in &outputs {
        let bin = dir.join(format!("{name}{}", std::env::consts::EXE_SUFFIX));
        assert!(
            bin.exists(),
            "{} is missing: run `cargo test --release` (which builds the examples) or \
             `cargo build --release --examples` first",
            bin.display()
        );
        let run = std::process::Command::new(&bin)
            .output()
            .expect("the example runs");
        assert!(run.status.success(), "{name} failed");
        let printed = String::from_utf8(run.stdout).expect("UTF-8 output");
        assert_eq!(
            printed.trim_matches('\n'),
            expected.trim_matches('\n'),
            "docs/tutorial.md: the output shown for `cargo run --release --example {name}` is \
             not what it prints"
        );
    }
}
