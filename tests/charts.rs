//! Every committed chart (docs/figures/*.svg) keeps its data inside its plot area and its text
//! inside its canvas (issue 46, item 6).
//!
//! The charts are written by `src/studies/svg.rs`, which marks what is checked here: the plot
//! area is the `rect` of class `plot-area`; each data line a `path` of class `line` (absolute
//! `M`/`L` commands), each marker a `g` of class `point` translated to its data point, each
//! heat-map cell a `rect` of class `cell`. Text widths are estimated as svg.rs estimates them,
//! 0.6 of the font size a character (Helvetica's average is about 0.5): a label is inside the
//! canvas when its estimated box is.

use std::path::{Path, PathBuf};

/// The estimated width of a character, as a fraction of the font size (svg.rs's `EM`).
const TEXT_EM: f64 = 0.6;
/// Coordinates are written to a hundredth of a pixel.
const SLACK: f64 = 0.01;

/// The value of attribute `name` in the tag text `tag` (`name="value"`).
fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let i = tag.find(&key)? + key.len();
    let rest = &tag[i..];
    Some(&rest[..rest.find('"')?])
}

fn num(tag: &str, name: &str) -> f64 {
    let v = attr(tag, name).unwrap_or_else(|| panic!("no {name} in {tag}"));
    v.parse()
        .unwrap_or_else(|_| panic!("{name}={v:?} in {tag}"))
}

/// The numbers of `translate(a,b)` (or `translate(a b)`) in a transform.
fn translate(transform: &str) -> (f64, f64) {
    let i = transform.find("translate(").expect("a translate") + "translate(".len();
    let inner = &transform[i..i + transform[i..].find(')').expect("closed")];
    let v: Vec<f64> = (inner.split([',', ' ']))
        .filter(|t| !t.is_empty())
        .map(|t| t.parse().expect("a number"))
        .collect();
    (v[0], v[1])
}

/// Each element `<name …>` of `svg` with its tag text and the text up to its closing tag.
fn elements<'a>(svg: &'a str, name: &str) -> Vec<(&'a str, &'a str)> {
    let open = format!("<{name} ");
    let close = format!("</{name}>");
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find(&open) {
        rest = &rest[i..];
        let end = rest.find('>').expect("a closed tag") + 1;
        let tag = &rest[..end];
        let body = if tag.ends_with("/>") {
            ""
        } else {
            let j = rest.find(&close).unwrap_or(end);
            &rest[end..j.max(end)]
        };
        out.push((tag, body));
        rest = &rest[end..];
    }
    out
}

/// A rectangle x0, y0, x1, y1.
type Rect = (f64, f64, f64, f64);

fn inside((x, y): (f64, f64), r: Rect) -> bool {
    x >= r.0 - SLACK && x <= r.2 + SLACK && y >= r.1 - SLACK && y <= r.3 + SLACK
}

/// What is wrong with one chart: data outside the plot area, text outside the canvas; and the
/// number of data points checked.
fn check(svg: &str) -> (Vec<String>, usize) {
    let mut bad = Vec::new();
    let (root, _) = elements(svg, "svg")[0];
    let canvas = (0.0, 0.0, num(root, "width"), num(root, "height"));
    let base_size = num(root, "font-size");
    let areas: Vec<Rect> = (elements(svg, "rect").into_iter())
        .filter(|(t, _)| attr(t, "class") == Some("plot-area"))
        .map(|(t, _)| {
            let (x, y) = (num(t, "x"), num(t, "y"));
            (x, y, x + num(t, "width"), y + num(t, "height"))
        })
        .collect();
    assert_eq!(areas.len(), 1, "one plot area");
    let area = areas[0];
    if !inside((area.0, area.1), canvas) || !inside((area.2, area.3), canvas) {
        bad.push(format!("plot area {area:?} outside the canvas {canvas:?}"));
    }
    let mut points: Vec<(f64, f64)> = Vec::new();
    for (t, _) in elements(svg, "g") {
        if attr(t, "class") == Some("point") {
            points.push(translate(attr(t, "transform").expect("a transform")));
        }
    }
    for (t, _) in elements(svg, "path") {
        if attr(t, "class") == Some("line") {
            let d = attr(t, "d").expect("a path");
            for xy in d.split(['M', 'L']).map(str::trim).filter(|s| !s.is_empty()) {
                let (x, y) = xy.split_once(',').expect("x,y");
                points.push((x.parse().expect("x"), y.parse().expect("y")));
            }
        }
    }
    for (t, _) in elements(svg, "rect") {
        if attr(t, "class") == Some("cell") {
            let (x, y) = (num(t, "x"), num(t, "y"));
            points.push((x, y));
            points.push((x + num(t, "width"), y + num(t, "height")));
        }
    }
    for &p in &points {
        if !inside(p, area) {
            bad.push(format!("data point {p:?} outside the plot area {area:?}"));
        }
    }
    for (t, body) in elements(svg, "text") {
        let text = body
            .replace("&amp;", "&")
            .replace("&lt;", "<")
            .replace("&gt;", ">");
        let size = attr(t, "font-size").map_or(base_size, |s| s.parse().expect("a size"));
        let w = text.chars().count() as f64 * TEXT_EM * size;
        let (before, after) = match attr(t, "text-anchor") {
            Some("middle") => (w / 2.0, w / 2.0),
            Some("end") => (w, 0.0),
            _ => (0.0, w),
        };
        // The box: along the text from the anchor, across it from the ascent to the descent.
        let corners = match attr(t, "transform") {
            Some(tr) if tr.contains("rotate(-90)") => {
                let (x, y) = translate(tr);
                [(x - size, y + before), (x + 0.25 * size, y - after)]
            }
            _ => {
                let (x, y) = (num(t, "x"), num(t, "y"));
                [(x - before, y - size), (x + after, y + 0.25 * size)]
            }
        };
        if !corners.iter().all(|&c| inside(c, canvas)) {
            bad.push(format!(
                "text {text:?} ({corners:?}) runs off the canvas {canvas:?}"
            ));
        }
    }
    (bad, points.len())
}

fn figures() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/figures");
    let mut v: Vec<PathBuf> = (std::fs::read_dir(&dir).expect("docs/figures"))
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    v.sort();
    v
}

/// Every committed chart: each data point (marker, vertex of a line, corner of a heat-map cell)
/// inside the plot area, each text inside the canvas, and something drawn.
#[test]
fn every_committed_chart_keeps_its_data_and_text_inside() {
    let files = figures();
    assert!(
        files.len() >= 40,
        "{} charts under docs/figures",
        files.len()
    );
    let mut failures = Vec::new();
    let mut total = 0;
    for f in &files {
        let svg = std::fs::read_to_string(f).expect("reads");
        let (bad, n) = check(&svg);
        let name = f.file_name().unwrap_or_default().to_string_lossy();
        if n == 0 {
            failures.push(format!("{name}: no data point"));
        }
        failures.extend(bad.into_iter().take(3).map(|b| format!("{name}: {b}")));
        total += n;
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(total > 10_000, "{total} data points checked");
}

/// The check finds a point moved outside the plot area and a title made too long for the
/// canvas, planted in a committed chart.
#[test]
fn the_check_finds_a_point_outside_and_a_long_title() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/figures/pareto_ellipse_0.svg");
    let svg = std::fs::read_to_string(path).expect("reads");
    assert!(check(&svg).0.is_empty());
    // A marker moved 20 px left of the plot area.
    let i = svg
        .find(r#"<g class="point" transform="translate("#)
        .expect("a marker");
    let at = i + r#"<g class="point" transform="translate("#.len();
    let planted = format!(
        "{}20.00,{}",
        &svg[..at],
        &svg[at + svg[at..].find(',').unwrap() + 1..]
    );
    let (bad, _) = check(&planted);
    assert!(
        bad.iter().any(|b| b.starts_with("data point (20.0")),
        "{bad:?}"
    );
    // A title of 120 characters (1080 px at 15 px) on a 760 px canvas.
    let long = format!(">{}</text>", "x".repeat(120));
    let j = svg.find(r#"font-size="15">"#).expect("a title") + r#"font-size="15""#.len();
    let k = j + svg[j..].find("</text>").unwrap() + "</text>".len();
    let planted = format!("{}{long}{}", &svg[..j], &svg[k..]);
    let (bad, _) = check(&planted);
    assert!(bad.iter().any(|b| b.contains("xxxx")), "{bad:?}");
}

/// The timing studies' committed charts are what `study NAME --redraw` draws from their
/// committed CSV data (the one path by which those studies draw); another study's `--redraw`
/// is refused before any work (exit 2).
#[test]
fn redraw_gives_the_committed_charts_of_the_timing_studies() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let tmp = std::env::temp_dir().join(format!("moving-hertz-charts-{}", std::process::id()));
    std::fs::create_dir_all(tmp.join("data")).expect("a temporary directory");
    let bin = env!("CARGO_BIN_EXE_moving-hertz");
    for (study, csv, prefix) in [
        ("pareto", "pareto_ellipse.csv", "pareto_"),
        ("integrals", "integrals_study.csv", "integrals_"),
        ("series", "series_terms.csv", "series_t"),
    ] {
        std::fs::copy(root.join("docs/data").join(csv), tmp.join("data").join(csv))
            .expect("copied");
        let out = std::process::Command::new(bin)
            .args(["study", study, "--redraw", "--out"])
            .arg(&tmp)
            .output()
            .expect("runs");
        assert!(
            out.status.success(),
            "{study}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let committed: Vec<PathBuf> = (figures().into_iter())
            .filter(|p| {
                p.file_name()
                    .unwrap_or_default()
                    .to_string_lossy()
                    .starts_with(prefix)
            })
            .collect();
        assert!(committed.len() >= 2, "{study}: {committed:?}");
        for f in committed {
            let name = f.file_name().expect("a name");
            let drawn = std::fs::read_to_string(tmp.join("figures").join(name)).expect("drawn");
            let want = std::fs::read_to_string(&f).expect("committed");
            assert!(
                drawn == want,
                "{study}: {name:?} differs from what --redraw draws"
            );
        }
    }
    let out = std::process::Command::new(bin)
        .args(["study", "rayleigh", "--redraw", "--out"])
        .arg(&tmp)
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--redraw"));
    let _ = std::fs::remove_dir_all(&tmp);
}
