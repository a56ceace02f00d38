//! The studies' SVG charts: line and marker charts on linear or log axes with a legend, and heat
//! maps with a colour bar, on one fixed 760 × 480 px layout. No dependency: plain SVG 1.1 text.
//!
//! * **Axes fitted to the data**: an axis spans its data (widened to a range the chart asks for),
//!   padded by 4 % of its span (of its decades on a log axis), so every point lies inside the
//!   plot area. Ticks in 1-2-5 steps; on a log axis at decades (every 1, 2, 5, 10 … decades),
//!   with 2 and 5 between them under three decades.
//! * **Text inside the canvas**: a character is taken as 0.6 of the font size wide; a title or a
//!   legend line too wide is broken into lines, an axis label too long is set smaller.
//! * **Marked for checking** (tests/charts.rs reads every committed chart): the plot area is the
//!   `rect` of class `plot-area`, each data line a `path` of class `line` (`M`/`L` commands),
//!   each marker a `g` of class `point` translated to its point, each heat-map cell a `rect` of
//!   class `cell`.
//!
//! No item of this module implements a formula of the paper: they draw the studies' results.

use std::fmt::Write;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// A polyline through the points.
    Line,
    /// Markers only.
    Markers,
    /// A polyline with markers.
    LineMarkers,
    /// A dashed polyline (reference curves).
    Dashed,
}

/// One data series.
#[derive(Clone, Debug)]
pub struct Series {
    /// Legend text.
    pub label: String,
    /// The points (non-finite ones, and non-positive ones on a log axis, are skipped and break
    /// the line).
    pub points: Vec<(f64, f64)>,
    /// Drawing style.
    pub style: Style,
    /// The colour and marker by number (the series' place when `None`): a series keeps its
    /// look across charts where others are left out.
    pub look: Option<usize>,
}

impl Series {
    /// A series with the given label, points and style.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style) -> Series {
        let label = label.into();
        Series {
            label,
            points,
            style,
            look: None,
        }
    }
    /// The colour and marker of place `i`, wherever it is drawn.
    pub fn look(self, i: usize) -> Series {
        Series {
            look: Some(i),
            ..self
        }
    }
}

/// A 2-D chart.
#[derive(Clone, Debug, Default)]
pub struct Chart {
    /// Title above the plot.
    pub title: String,
    /// Horizontal axis label (with units).
    pub x_label: String,
    /// Vertical axis label (with units).
    pub y_label: String,
    /// Logarithmic horizontal axis.
    pub x_log: bool,
    /// Logarithmic vertical axis.
    pub y_log: bool,
    /// A horizontal range the axis spans at least (the data widen it).
    pub x_range: Option<(f64, f64)>,
    /// A vertical range the axis spans at least (the data widen it).
    pub y_range: Option<(f64, f64)>,
    /// Ticks of the horizontal axis (value, label) in place of the automatic ones (those
    /// outside the axis are left out).
    pub x_ticks: Option<Vec<(f64, String)>>,
    /// The series.
    pub series: Vec<Series>,
    /// Lines of text below the legend's keys: what is not drawn and why.
    pub notes: Vec<String>,
}

/// The mark an SVG carries for a series without a usable point (see `studies::write_text`).
pub const EMPTY_SERIES: &str = "empty series";

const PALETTE: [&str; 10] = [
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
    "#7f7f7f", "#bcbd22",
];
/// The canvas, the plot area's left and bottom margins, the least distance of text from the
/// canvas' edge (px) and the estimated width of a character in font sizes.
const W: f64 = 760.0;
const H: f64 = 480.0;
const ML: f64 = 78.0;
const MB: f64 = 58.0;
const EDGE: f64 = 4.0;
const EM: f64 = 0.6;

impl Chart {
    /// An empty chart with a title and axis labels, linear axes.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Chart {
        Chart {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            ..Chart::default()
        }
    }
    /// Sets log scales.
    pub fn log(self, x_log: bool, y_log: bool) -> Chart {
        Chart {
            x_log,
            y_log,
            ..self
        }
    }
    /// Adds a series.
    pub fn push(&mut self, s: Series) {
        self.series.push(s);
    }

    fn usable(&self, &(x, y): &(f64, f64)) -> bool {
        x.is_finite() && y.is_finite() && (!self.x_log || x > 0.0) && (!self.y_log || y > 0.0)
    }

    /// Renders the chart as an SVG document.
    pub fn to_svg(&self) -> String {
        let usable =
            || (self.series.iter()).flat_map(|s| s.points.iter().filter(|p| self.usable(p)));
        let range = |r: Option<(f64, f64)>| r.into_iter().flat_map(<[f64; 2]>::from);
        let xs = usable().map(|p| p.0).chain(range(self.x_range));
        let ys = usable().map(|p| p.1).chain(range(self.y_range));
        let xa = Axis::fit(xs, self.x_log, &self.x_label);
        let ya = Axis::fit(ys, self.y_log, &self.y_label);
        let f = Frame::new(&self.title, 190.0, xa, ya);
        let x_ticks = match &self.x_ticks {
            Some(t) => t
                .iter()
                .filter(|(v, _)| (0.0..=1.0).contains(&f.x.frac(*v)))
                .cloned()
                .collect(),
            None => f.x.ticks(),
        };
        let mut o = f.open(x_ticks, true);
        // The legend takes a few kilobytes, each point about 16 bytes: grown once.
        o.reserve(8192 + 16 * self.series.iter().map(|s| s.points.len()).sum::<usize>());
        let (lx, mut y) = (f.ml + f.pw + 14.0, f.mt + 10.0);
        for (i, s) in self.series.iter().enumerate() {
            let i = s.look.unwrap_or(i);
            let c = PALETTE[i % PALETTE.len()];
            let dash = if s.style == Style::Dashed {
                r#" stroke-dasharray="6,4""#
            } else {
                ""
            };
            let (line, marks) = (
                s.style != Style::Markers,
                matches!(s.style, Style::Markers | Style::LineMarkers),
            );
            if !s.points.iter().any(|p| self.usable(p)) {
                // Refused by `studies::write_text`: a chart never shows an empty series.
                let _ = write!(o, "<!-- {EMPTY_SERIES}: {} -->", esc(&s.label));
            }
            if line {
                let mut d = String::with_capacity(16 * s.points.len());
                let mut pen = 'M';
                for p in &s.points {
                    if self.usable(p) {
                        d.push(pen);
                        push_px(&mut d, f.px(p.0));
                        d.push(',');
                        push_px(&mut d, f.py(p.1));
                        d.push(' ');
                        pen = 'L';
                    } else {
                        pen = 'M';
                    }
                }
                let _ = write!(
                    o,
                    r#"<path class="line" d="{d}" fill="none" stroke="{c}" stroke-width="1.8"{dash}/>"#
                );
                // The legend's key.
                let _ = write!(
                    o,
                    r#"<line x1="{lx}" y1="{y}" x2="{}" y2="{y}" stroke="{c}" stroke-width="1.8"{dash}/>"#,
                    lx + 22.0
                );
            }
            if marks {
                for p in s.points.iter().filter(|p| self.usable(p)) {
                    marker(&mut o, "point", i, f.px(p.0), f.py(p.1), c);
                }
                marker(&mut o, "key", i, lx + 11.0, y, c);
            }
            y = text_lines(&mut o, &s.label, lx + 28.0, y + 4.0) - 1.0;
        }
        for note in &self.notes {
            y = text_lines(&mut o, note, lx, y + 4.0) - 1.0;
        }
        o + "</svg>\n"
    }
}

/// Writes `text` left-aligned at (`x`, `y`) in the default size, broken into lines that end
/// before the canvas' edge; the baseline of the line after the last.
fn text_lines(o: &mut String, text: &str, x: f64, mut y: f64) -> f64 {
    for line in wrap(text, 12.0, W - EDGE - x) {
        let _ = write!(o, r#"<text x="{x:.1}" y="{y:.1}">{}</text>"#, esc(&line));
        y += 15.0;
    }
    y
}

/// `text` broken at spaces into lines no wider than `width` at `size` (a word longer than a
/// line is broken inside).
fn wrap(text: &str, size: f64, width: f64) -> Vec<String> {
    let per_line = ((width / (EM * size)).floor() as usize).max(1);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        let mut word: Vec<char> = word.chars().collect();
        let n = line.chars().count();
        if n > 0 && n + 1 + word.len() > per_line {
            lines.push(std::mem::take(&mut line));
        }
        while word.len() > per_line {
            lines.extend((!line.is_empty()).then(|| std::mem::take(&mut line)));
            lines.push(word.drain(..per_line).collect());
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.extend(word);
    }
    lines.extend((!line.is_empty() || lines.is_empty()).then_some(line));
    lines
}

/// A chart's axes and plot area (left and top margins, width and height) and title lines.
struct Frame {
    x: Axis,
    y: Axis,
    ml: f64,
    mt: f64,
    pw: f64,
    ph: f64,
    title: Vec<String>,
}

impl Frame {
    /// The standard left and bottom margins, `right` for the legend or colour bar, and a top
    /// margin that holds `title` broken into lines.
    fn new(title: &str, right: f64, x: Axis, y: Axis) -> Frame {
        let title = wrap(title, 15.0, W - 2.0 * EDGE);
        let mt = 40.0 + 18.0 * (title.len() - 1) as f64;
        let (pw, ph) = (W - ML - right, H - mt - MB);
        Frame {
            x,
            y,
            ml: ML,
            mt,
            pw,
            ph,
            title,
        }
    }
    fn px(&self, v: f64) -> f64 {
        self.ml + self.pw * self.x.frac(v)
    }
    fn py(&self, v: f64) -> f64 {
        self.mt + self.ph * (1.0 - self.y.frac(v))
    }

    /// The document's opening: white background, the title, the ticks (`x_ticks` along x) with
    /// grid lines (`grid`) or short outer marks, the plot area's border and the axis labels
    /// (each set smaller where it would not fit the canvas).
    fn open(&self, x_ticks: Vec<(f64, String)>, grid: bool) -> String {
        let mut o = format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}" font-family="Helvetica, Arial, sans-serif" font-size="12"><rect width="{W}" height="{H}" fill="white"/>"#
        );
        for (i, line) in self.title.iter().enumerate() {
            let y = 22.0 + 18.0 * i as f64;
            let _ = write!(
                o,
                r#"<text x="{}" y="{y}" text-anchor="middle" font-size="15">{}</text>"#,
                W / 2.0,
                esc(line)
            );
        }
        let (ml, mt, b, r) = (self.ml, self.mt, self.mt + self.ph, self.ml + self.pw);
        let (stroke, x_mark, y_mark) = if grid {
            ("#e6e6e6", (mt, b), (ml, r))
        } else {
            ("black", (b, b + 5.0), (ml - 5.0, ml))
        };
        for (v, label) in x_ticks {
            let x = self.px(v);
            let _ = write!(
                o,
                r#"<line x1="{x:.1}" y1="{:.1}" x2="{x:.1}" y2="{:.1}" stroke="{stroke}"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
                x_mark.0,
                x_mark.1,
                b + 17.0,
                esc(&label)
            );
        }
        for (v, label) in self.y.ticks() {
            let y = self.py(v);
            let _ = write!(
                o,
                r#"<line x1="{:.1}" y1="{y:.1}" x2="{:.1}" y2="{y:.1}" stroke="{stroke}"/><text x="{:.1}" y="{:.1}" text-anchor="end">{}</text>"#,
                y_mark.0,
                y_mark.1,
                ml - 7.0,
                y + 4.0,
                esc(&label)
            );
        }
        let _ = write!(
            o,
            r#"<rect class="plot-area" x="{ml}" y="{mt}" width="{}" height="{}" fill="none" stroke="black"/>"#,
            self.pw, self.ph
        );
        let (cx, cy) = (ml + self.pw / 2.0, mt + self.ph / 2.0);
        let (x_size, y_size) = (
            fitted(&self.x.label, 13.0, 2.0 * (cx.min(W - cx) - EDGE)),
            fitted(&self.y.label, 13.0, 2.0 * (cy.min(H - cy) - EDGE)),
        );
        let _ = write!(
            o,
            r#"<text x="{cx:.1}" y="{}" text-anchor="middle" font-size="{x_size}">{}</text>"#,
            H - 14.0,
            esc(&self.x.label)
        );
        let _ = write!(
            o,
            r#"<text transform="translate(18,{cy:.1}) rotate(-90)" text-anchor="middle" font-size="{y_size}">{}</text>"#,
            esc(&self.y.label)
        );
        o
    }
}

/// The font size, at most `size`, at which `text` is no wider than `width`.
fn fitted(text: &str, size: f64, width: f64) -> f64 {
    let w = text.chars().count() as f64 * EM * size;
    if w <= width {
        size
    } else {
        (size * width / w * 10.0).floor() / 10.0
    }
}

/// A heat map: a value per cell of a grid, coloured on a scale, with a colour bar.
#[derive(Clone, Debug)]
pub struct Heatmap {
    /// Title above the map.
    pub title: String,
    /// Horizontal axis label.
    pub x_label: String,
    /// Vertical axis label.
    pub y_label: String,
    /// Colour-bar label.
    pub z_label: String,
    /// Cell centres along x (ascending).
    pub xs: Vec<f64>,
    /// Cell centres along y (ascending).
    pub ys: Vec<f64>,
    /// Values, `z[j][i]` at `(xs[i], ys[j])`; NaN cells are drawn grey.
    pub z: Vec<Vec<f64>>,
    /// Log scale on x.
    pub x_log: bool,
    /// Log scale on y.
    pub y_log: bool,
    /// Colour scale range.
    pub z_range: (f64, f64),
    /// What a grey (NaN) cell means, named by a grey key under the colour bar when the map has
    /// one (e.g. "refused").
    pub missing: String,
}

/// The colour of a cell without a value.
const GREY: &str = "#bdbdbd";

impl Heatmap {
    /// Renders the map as an SVG document.
    pub fn to_svg(&self) -> String {
        let (ex, ey) = (
            cell_edges(&self.xs, self.x_log),
            cell_edges(&self.ys, self.y_log),
        );
        let axis = |e: &[f64], log, label: &str| Axis {
            lo: e[0],
            hi: e[e.len() - 1],
            log,
            label: label.into(),
        };
        let f = Frame::new(
            &self.title,
            120.0,
            axis(&ex, self.x_log, &self.x_label),
            axis(&ey, self.y_log, &self.y_label),
        );
        let mut o = f.open(f.x.ticks(), false);
        let (ml, mt, pw, ph) = (f.ml, f.mt, f.pw, f.ph);
        let (px, py) = (
            |t: f64| ml + pw * f.x.at(t),
            |t: f64| mt + ph * (1.0 - f.y.at(t)),
        );
        for (j, row) in self.z.iter().enumerate().take(ey.len() - 1) {
            for (i, &v) in row.iter().enumerate().take(ex.len() - 1) {
                let fill = if v.is_finite() {
                    colour(v, self.z_range)
                } else {
                    GREY.to_string()
                };
                // A cell overlaps its neighbours by 0.3 px (no hairline gaps), inside the plot.
                let (xa, xb) = (px(ex[i]).max(ml), (px(ex[i + 1]) + 0.3).min(ml + pw));
                let (ya, yb) = ((py(ey[j + 1]) - 0.3).max(mt), py(ey[j]).min(mt + ph));
                let _ = write!(
                    o,
                    r#"<rect class="cell" x="{xa:.2}" y="{ya:.2}" width="{:.2}" height="{:.2}" fill="{fill}"/>"#,
                    xb - xa - 0.005,
                    yb - ya - 0.005
                );
            }
        }
        // The colour bar right of the map; under it a grey key naming the cells without a value.
        let missing = self.z.iter().flatten().any(|v| !v.is_finite());
        let (bx, ph) = (ml + pw + 24.0, if missing { ph - 30.0 } else { ph });
        let bar = Axis {
            lo: self.z_range.0,
            hi: self.z_range.1,
            log: false,
            label: String::new(),
        };
        for k in 0..50 {
            let v = bar.lo + (bar.hi - bar.lo) * (k as f64 + 0.5) / 50.0;
            let y = mt + ph * (1.0 - (k + 1) as f64 / 50.0);
            let _ = write!(
                o,
                r#"<rect x="{bx}" y="{y:.2}" width="18" height="{:.2}" fill="{}"/>"#,
                ph / 50.0 + 0.3,
                colour(v, self.z_range)
            );
        }
        let _ = write!(
            o,
            r#"<rect x="{bx}" y="{mt}" width="18" height="{ph}" fill="none" stroke="black"/>"#
        );
        for (v, label) in bar.ticks() {
            let y = mt + ph * (1.0 - bar.frac(v)) + 4.0;
            let _ = write!(
                o,
                r#"<text x="{:.1}" y="{y:.1}">{}</text>"#,
                bx + 22.0,
                esc(&label)
            );
        }
        if missing {
            let y = f.mt + f.ph - 16.0;
            let _ = write!(
                o,
                r#"<rect x="{bx}" y="{y}" width="18" height="16" fill="{GREY}" stroke="black"/>"#
            );
            text_lines(&mut o, &self.missing, bx + 22.0, y + 12.0);
        }
        let size = fitted(&self.z_label, 12.0, ph - 2.0 * EDGE);
        let _ = write!(
            o,
            r#"<text transform="translate({:.1},{:.1}) rotate(-90)" text-anchor="middle" font-size="{size}">{}</text>"#,
            bx + 70.0,
            mt + ph / 2.0,
            esc(&self.z_label)
        );
        o + "</svg>\n"
    }
}

/// The cell edges of a heat map axis with cell centres `c`, in axis units (log10 on a log axis).
fn cell_edges(c: &[f64], log: bool) -> Vec<f64> {
    let t: Vec<f64> = c.iter().map(|&v| if log { v.log10() } else { v }).collect();
    let n = t.len();
    if n == 1 {
        return vec![t[0] - 0.5, t[0] + 0.5];
    }
    let mids = t.windows(2).map(|w| (w[0] + w[1]) / 2.0);
    let first = t[0] - (t[1] - t[0]) / 2.0;
    let last = t[n - 1] + (t[n - 1] - t[n - 2]) / 2.0;
    std::iter::once(first).chain(mids).chain([last]).collect()
}

/// A perceptually ordered colour (viridis-like) for `v` in `range`.
fn colour(v: f64, range: (f64, f64)) -> String {
    const STOPS: [[f64; 3]; 6] = [
        [68.0, 1.0, 84.0],
        [65.0, 68.0, 135.0],
        [42.0, 120.0, 142.0],
        [34.0, 168.0, 132.0],
        [122.0, 209.0, 81.0],
        [253.0, 231.0, 37.0],
    ];
    let t = ((v - range.0) / (range.1 - range.0)).clamp(0.0, 1.0) * 5.0;
    let i = (t.floor() as usize).min(4);
    let c = |k: usize| (STOPS[i][k] + (t - i as f64) * (STOPS[i + 1][k] - STOPS[i][k])).round();
    format!("rgb({},{},{})", c(0), c(1), c(2))
}

/// A marker of series `i` (circle, square, triangle in turn) at (`x`, `y`): a `g` of class
/// `class` (`point` in the plot, `key` in the legend) translated there.
fn marker(o: &mut String, class: &str, i: usize, x: f64, y: f64, c: &str) {
    let shape = match i % 3 {
        0 => format!(r#"<circle r="3.2" fill="{c}"/>"#),
        1 => format!(r#"<rect x="-3" y="-3" width="6" height="6" fill="{c}"/>"#),
        _ => format!(r#"<path d="M0,-4 L-3.6,3 L3.6,3 Z" fill="{c}"/>"#),
    };
    let _ = write!(
        o,
        r#"<g class="{class}" transform="translate({x:.2},{y:.2})">{shape}</g>"#
    );
}

/// Appends a pixel coordinate with two decimals, as `{:.2}` writes it but from the whole number
/// of hundredths, digit by digit (the paths write thousands of coordinates, and the formatting
/// machinery costs fig2 about 10 % more instructions). A coordinate is finite and inside the
/// canvas.
fn push_px(o: &mut String, v: f64) {
    let c = (v * 100.0).round();
    if c < 0.0 {
        o.push('-');
    }
    let (mut n, mut buf, mut i) = (c.abs() as u64, [b'0'; 24], 24);
    while n > 0 || i > 20 {
        i -= 1;
        if i == 21 {
            buf[i] = b'.';
            i -= 1;
        }
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
    }
    o.push_str(std::str::from_utf8(&buf[i..]).unwrap_or_default());
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// A linear or logarithmic axis over [lo, hi] (log10 of the values on a log axis), and its label.
struct Axis {
    lo: f64,
    hi: f64,
    log: bool,
    label: String,
}

impl Axis {
    /// The axis over `values` (non-finite ones, and non-positive ones on a log axis, left out),
    /// padded by 4 % of its span.
    fn fit(values: impl Iterator<Item = f64>, log: bool, label: &str) -> Axis {
        let v = values.filter(|v| v.is_finite() && (!log || *v > 0.0));
        let (lo, hi) = v.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        let axis = |v: f64| if log { v.log10() } else { v };
        let (lo, hi) = if lo > hi {
            (0.0, 1.0)
        } else {
            (axis(lo), axis(hi))
        };
        let pad = match hi - lo {
            span if span > 0.0 => span * 0.04,
            _ if log => 0.5,
            _ if lo == 0.0 => 1.0,
            _ => lo.abs() * 0.1,
        };
        let label = label.to_string();
        Axis {
            lo: lo - pad,
            hi: hi + pad,
            log,
            label,
        }
    }
    /// The place of `t` (in axis units) along the axis, 0 to 1.
    fn at(&self, t: f64) -> f64 {
        (t - self.lo) / (self.hi - self.lo)
    }
    /// The place of the value `v` along the axis.
    fn frac(&self, v: f64) -> f64 {
        self.at(if self.log { v.log10() } else { v })
    }
    /// The ticks inside the axis, (value, label).
    fn ticks(&self) -> Vec<(f64, String)> {
        let (lo, hi) = (self.lo, self.hi);
        if !self.log {
            return linear_ticks(lo, hi);
        }
        let step = [1, 2, 5, 10, 20, 50, 100]
            .into_iter()
            .find(|&s| s as f64 >= (hi - lo) / 8.0)
            .unwrap_or(200);
        let decades = (lo / step as f64).ceil() as i64..=(hi / step as f64).floor() as i64;
        if decades.end() - decades.start() >= 2 {
            return decades
                .map(|j| (10f64.powi((j * step) as i32), log_label(1, j * step)))
                .collect();
        }
        let t: Vec<(f64, String)> = (lo.floor() as i64..=hi.ceil() as i64)
            .flat_map(|e| [1, 2, 5].map(|m| (m as f64 * 10f64.powi(e as i32), log_label(m, e))))
            .filter(|(v, _)| (lo..=hi).contains(&v.log10()))
            .collect();
        // Under a decade: linear steps between the ends, placed on the log scale.
        if t.len() >= 3 {
            t
        } else {
            linear_ticks(10f64.powf(lo), 10f64.powf(hi))
        }
    }
}

/// Ticks in 1-2-2.5-5 steps inside [lo, hi], about six to ten of them.
fn linear_ticks(lo: f64, hi: f64) -> Vec<(f64, String)> {
    let raw = (hi - lo) / 8.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .map(|m| m * mag)
        .into_iter()
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    // As many decimals as the step has (2.5 needs one, 0.25 two).
    let decimals = (0..=12)
        .find(|&d| {
            (step * 10f64.powi(d) - (step * 10f64.powi(d)).round()).abs()
                <= 1e-9 * step * 10f64.powi(d)
        })
        .unwrap_or(12) as usize;
    let label = |v: f64| match v.abs() {
        0.0 => "0".to_string(),
        a if !(1e-3..1e5).contains(&a) => format!("{v:.1e}"),
        _ => format!("{v:.decimals$}"),
    };
    ((lo / step).ceil() as i64..=(hi / step).floor() as i64)
        .map(|k| (k as f64 * step, label(k as f64 * step)))
        .collect()
}

/// The label of m·10^e on a log axis: plain from 0.001 to 9999, else `me±n`.
fn log_label(m: i64, e: i64) -> String {
    if (-3..=3).contains(&e) {
        let decimals = (-e).max(0) as usize;
        format!("{:.decimals$}", m as f64 * 10f64.powi(e as i32))
    } else {
        format!("{m}e{e}")
    }
}

#[cfg(test)]
#[path = "../../tests/unit/svg.rs"]
mod tests;
