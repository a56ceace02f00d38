//! Unit tests of the studies' shared helpers (`src/studies/mod.rs`).

use super::svg::{Chart, Series, Style};

/// Pieces written one after the other give their concatenation, empty pieces and more
/// pieces than one `writev` takes (1,024 on Linux) included.
#[test]
fn pieces_are_written_in_order() {
    let dir = std::env::temp_dir().join(format!("moving-hertz-pieces-{}", std::process::id()));
    let path = dir.join("sub").join("table.csv");
    let mut pieces = vec![String::from("header\n"), String::new()];
    pieces.extend((0..3000).map(|i| format!("{i},{}\n", "x".repeat(i % 7))));
    super::write_pieces(&path, &pieces).expect("writes");
    assert_eq!(
        std::fs::read_to_string(&path).expect("reads"),
        pieces.concat()
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A chart whose legend promises a curve with no point to draw is refused; with the point
/// it is written.
#[test]
fn a_chart_with_an_empty_series_is_not_written() {
    let dir = std::env::temp_dir().join(format!("moving-hertz-svg-{}", std::process::id()));
    let path = dir.join("chart.svg");
    let mut chart = Chart::new("t", "x", "y").log(true, true);
    chart.push(Series::new(
        "full",
        vec![(1.0, 2.0), (2.0, 3.0)],
        Style::Line,
    ));
    // A point at x = 0 cannot be drawn on a log axis: the series is empty.
    chart.push(Series::new("lost", vec![(0.0, 1.0)], Style::Markers));
    let err = super::write_text(&path, &chart.to_svg()).expect_err("refused");
    assert!(err.to_string().contains("lost"), "{err}");
    assert!(!path.exists());
    chart.series[1].points.push((3.0, 1.0));
    super::write_text(&path, &chart.to_svg()).expect("written");
    let _ = std::fs::remove_dir_all(&dir);
}
