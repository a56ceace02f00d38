//! Unit tests of the SVG writer (`src/studies/svg.rs`): every point drawn lies inside the plot
//! area (tests/charts.rs checks the same of every committed chart).

use super::{Chart, Heatmap, Series, Style};

/// A rectangle x0, y0, x1, y1.
type Rect = (f64, f64, f64, f64);

/// The number after `key` (`x="` …) in `tag`.
fn num(tag: &str, key: &str) -> f64 {
    let i = tag.find(key).unwrap_or_else(|| panic!("{key} in {tag}")) + key.len();
    let end = i + tag[i..].find(['"', ',', ')']).expect("an end");
    tag[i..end].parse().expect("a number")
}

/// The plot area (x0, y0, x1, y1) and every data point of `svg`: markers, line vertices and
/// heat-map cell corners.
fn area_and_points(svg: &str) -> (Rect, Vec<(f64, f64)>) {
    let a = &svg[svg.find(r#"class="plot-area""#).expect("a plot area")..];
    let (x, y) = (num(a, r#"x=""#), num(a, r#"y=""#));
    let area = (x, y, x + num(a, r#"width=""#), y + num(a, r#"height=""#));
    let mut pts = Vec::new();
    for g in svg
        .split(r#"<g class="point" transform="translate("#)
        .skip(1)
    {
        pts.push((num(g, ""), num(g, ",")));
    }
    for p in svg.split(r#"<path class="line" d=""#).skip(1) {
        let d = &p[..p.find('"').expect("closed")];
        for xy in d.split(['M', 'L']).map(str::trim).filter(|s| !s.is_empty()) {
            let (x, y) = xy.split_once(',').expect("x,y");
            pts.push((x.parse().expect("x"), y.parse().expect("y")));
        }
    }
    for c in svg.split(r#"<rect class="cell" "#).skip(1) {
        let (x, y) = (num(c, r#"x=""#), num(c, r#"y=""#));
        pts.push((x, y));
        pts.push((x + num(c, r#"width=""#), y + num(c, r#"height=""#)));
    }
    (area, pts)
}

fn assert_inside(svg: &str, at_least: usize) {
    let (a, pts) = area_and_points(svg);
    assert!(pts.len() >= at_least, "{} points", pts.len());
    for (x, y) in pts {
        let ok = x >= a.0 - 0.01 && x <= a.2 + 0.01 && y >= a.1 - 0.01 && y <= a.3 + 0.01;
        assert!(ok, "({x}, {y}) outside the plot area {a:?}");
    }
}

/// Lines and markers on log and linear axes, with points the axes cannot show (skipped), a
/// range that widens an axis and data spanning 30 decades, all inside the plot area.
#[test]
fn every_point_of_a_chart_is_inside_its_plot_area() {
    for (x_log, y_log) in [(false, false), (true, true), (true, false), (false, true)] {
        let mut c = Chart::new("t", "x", "y").log(x_log, y_log);
        c.y_range = Some((0.5, 2.0));
        let pts = |s: f64| {
            (1..60)
                .map(|j| (s * j as f64, 1e-15 * 3f64.powi(j)))
                .collect()
        };
        c.push(Series::new("a", pts(1.0), Style::LineMarkers));
        c.push(Series::new("b", pts(-0.5), Style::Markers));
        let mut gaps: Vec<(f64, f64)> = pts(0.1);
        gaps[7] = (f64::NAN, 1.0);
        c.push(Series::new("c", gaps, Style::Dashed));
        assert_inside(&c.to_svg(), 150);
    }
}

/// A heat map's cells, on log and linear axes, lie inside its plot area.
#[test]
fn every_cell_of_a_heat_map_is_inside_its_plot_area() {
    for log in [false, true] {
        let xs: Vec<f64> = (0..13).map(|j| 10f64.powf(-6.0 + 0.5 * j as f64)).collect();
        let ys: Vec<f64> = (0..9).map(|j| 0.02 + 0.12 * j as f64).collect();
        let z = (ys.iter())
            .map(|y| {
                xs.iter()
                    .map(|x| if *x > 1e-1 { f64::NAN } else { y * 10.0 })
                    .collect()
            })
            .collect();
        let h = Heatmap {
            title: "t".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            z_label: "z".into(),
            xs,
            ys,
            z,
            x_log: log,
            y_log: !log,
            z_range: (0.0, 10.0),
            missing: "none".into(),
        };
        assert_inside(&h.to_svg(), 2 * 13 * 9);
    }
}

/// A path coordinate is written to two decimals as `{:.2}` writes it (away from ties of x·100).
#[test]
fn coordinates_have_two_decimals() {
    let px = |v| {
        let mut s = String::new();
        super::push_px(&mut s, v);
        s
    };
    for v in [
        0.0,
        1.0,
        12.345_678,
        -12.345_678,
        759.999,
        0.004,
        78.1,
        401.26,
    ] {
        assert_eq!(px(v), format!("{v:.2}"), "{v}");
    }
}
