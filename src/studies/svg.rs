//! A small SVG chart writer for the studies: line and scatter charts with linear or log axes,
//! labelled axes, grid, legend; and heat maps with a colour bar. No dependency: the charts are
//! plain SVG 1.1 text.
//!
//! The rules every chart follows live here, once:
//! * **Axes fitted to the data.** An axis spans its data (widened to a range the chart asks
//!   for, never narrowed), padded by [`PAD`] of its span (of its decades on a log axis): every
//!   point drawn lies inside the plot area, and no axis starts a decade or more before its data.
//! * **Ticks** in 1-2-5 steps on a linear axis; on a log axis at decades (every 1, 2, 5, 10 …
//!   decades), with 2 and 5 between them when the axis spans under three decades, or in
//!   linear steps when it spans under one. A chart may set its own x ticks.
//! * **Text inside the canvas.** Text widths are estimated at [`TEXT_EM`] of the font size a
//!   character: a title too wide for the canvas is broken into lines (the plot moves down), a
//!   legend label is broken at the legend's width, an axis label too long for its side is set
//!   smaller.
//! * **Marked for checking** (tests/charts.rs reads every committed chart): the plot area is the
//!   `rect` of class `plot-area`, each data line a `path` of class `line` (absolute `M`/`L`
//!   commands), each marker a `g` of class `point` translated to its data point, each heat-map
//!   cell a `rect` of class `cell`.
//!
//! No item of this module implements a formula of the paper: they draw the studies' results (each
//! study names its equations); coordinates are written to a tenth or a hundredth of a pixel.

use std::fmt::Write;

/// The padding of a fitted axis, as a fraction of its span (of its decades on a log axis).
pub const PAD: f64 = 0.04;
/// The estimated width of a character, as a fraction of the font size (Helvetica's widest
/// common letters aside, its average is about 0.5).
pub const TEXT_EM: f64 = 0.6;
/// The least distance of any text from the canvas' edge, in pixels.
const EDGE: f64 = 4.0;
/// Font sizes of the title, the axis labels and the rest, in pixels.
const TITLE_SIZE: f64 = 15.0;
const LABEL_SIZE: f64 = 13.0;
const TEXT_SIZE: f64 = 12.0;
/// The width right of the plot area that holds the legend.
const LEGEND_WIDTH: f64 = 190.0;

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
    /// The points (non-finite points, and non-positive ones on a log axis, are skipped and break
    /// the line).
    pub points: Vec<(f64, f64)>,
    /// Drawing style.
    pub style: Style,
    /// The colour and marker by number (the series' place in the chart when `None`): a series
    /// keeps its look across charts where others are left out.
    pub look: Option<usize>,
}

impl Series {
    /// A series with the given label, points and style.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style) -> Series {
        Series {
            label: label.into(),
            points,
            style,
            look: None,
        }
    }
    /// The colour and marker of its place `i`, wherever it is drawn.
    pub fn look(mut self, i: usize) -> Series {
        self.look = Some(i);
        self
    }
}

/// A 2-D chart.
#[derive(Clone, Debug, Default)]
pub struct Chart {
    /// Title above the plot (broken into lines to fit the canvas).
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
    /// Ticks of the horizontal axis (value, label) in place of the automatic ones; those
    /// outside the fitted axis are left out.
    pub x_ticks: Option<Vec<(f64, String)>>,
    /// The series.
    pub series: Vec<Series>,
    /// Lines of text below the legend's keys: what is not drawn and why (refused routes).
    pub notes: Vec<String>,
}

/// The canvas of every chart and heat map, width × height in pixels.
const CANVAS: (f64, f64) = (760.0, 480.0);

const PALETTE: [&str; 10] = [
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
    "#7f7f7f", "#bcbd22",
];

impl Chart {
    /// An empty chart with a title and axis labels, linear axes, 760×480 px (`CANVAS`).
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
    pub fn log(mut self, x: bool, y: bool) -> Chart {
        self.x_log = x;
        self.y_log = y;
        self
    }
    /// Adds a series in place.
    pub fn push(&mut self, s: Series) {
        self.series.push(s);
    }

    fn usable(&self, x: f64, y: f64) -> bool {
        x.is_finite() && y.is_finite() && (!self.x_log || x > 0.0) && (!self.y_log || y > 0.0)
    }

    /// The range of the usable points along x (or y); `None` without any.
    fn data_range(&self, axis_x: bool) -> Option<(f64, f64)> {
        let values = (self.series.iter())
            .flat_map(|s| s.points.iter())
            .filter(|&&(x, y)| self.usable(x, y))
            .map(|&(x, y)| if axis_x { x } else { y });
        values.fold(None, |r, v| match r {
            None => Some((v, v)),
            Some((lo, hi)) => Some((v.min(lo), v.max(hi))),
        })
    }

    /// Renders the chart as an SVG document.
    pub fn to_svg(&self) -> String {
        let f = Frame::new(CANVAS, LEGEND_WIDTH, &self.title);
        let xa = Axis::fit(self.data_range(true), self.x_range, self.x_log);
        let ya = Axis::fit(self.data_range(false), self.y_range, self.y_log);
        let px = |x: f64| f.ml + f.pw * xa.frac(x);
        let py = |y: f64| f.mt + f.ph * (1.0 - ya.frac(y));
        let mut o = f.open();
        // The frame, ticks and legend take a few kilobytes, each point of a path about 16 bytes:
        // the text is grown once, not doubled as it is written.
        let points: usize = self.series.iter().map(|s| s.points.len()).sum();
        o.reserve(8192 + 16 * points);
        let x_ticks = match &self.x_ticks {
            Some(t) => (t.iter())
                .filter(|&(v, _)| (0.0..=1.0).contains(&xa.frac(*v)))
                .cloned()
                .collect(),
            None => xa.ticks(),
        };
        // Grid and ticks.
        let (ml, mt, pw, ph) = (f.ml, f.mt, f.pw, f.ph);
        for (v, label) in x_ticks {
            let (x, bottom) = (px(v), mt + ph);
            let _ = write!(
                o,
                r##"<line x1="{x:.1}" y1="{mt}" x2="{x:.1}" y2="{bottom:.1}" stroke="#e6e6e6"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
                bottom + 16.0,
                esc(&label)
            );
        }
        for (v, label) in ya.ticks() {
            let (y, right) = (py(v), ml + pw);
            let _ = write!(
                o,
                r##"<line x1="{ml}" y1="{y:.1}" x2="{right:.1}" y2="{y:.1}" stroke="#e6e6e6"/><text x="{:.1}" y="{:.1}" text-anchor="end">{}</text>"##,
                ml - 6.0,
                y + 4.0,
                esc(&label)
            );
        }
        f.border(&mut o);
        f.axis_labels(&mut o, &self.x_label, &self.y_label);
        self.curves(&mut o, &px, &py);
        self.legend(&mut o, &f);
        o.push_str("</svg>\n");
        o
    }

    /// The series; every usable point lies inside the plot area (the axes are fitted to them).
    fn curves(&self, o: &mut String, px: &dyn Fn(f64) -> f64, py: &dyn Fn(f64) -> f64) {
        for (i, s) in self.series.iter().enumerate() {
            let i = s.look.unwrap_or(i);
            let c = PALETTE[i % PALETTE.len()];
            if !s.points.iter().any(|&(x, y)| self.usable(x, y)) {
                // Refused by `studies::write_text`: a chart never shows an empty series.
                let _ = write!(o, "<!-- {EMPTY_SERIES}: {} -->", esc(&s.label));
            }
            if s.style != Style::Markers {
                let mut path = String::with_capacity(16 * s.points.len());
                let mut pen_up = true;
                for &(x, y) in &s.points {
                    if !self.usable(x, y) {
                        pen_up = true;
                        continue;
                    }
                    path.push(if pen_up { 'M' } else { 'L' });
                    push_px(&mut path, px(x));
                    path.push(',');
                    push_px(&mut path, py(y));
                    path.push(' ');
                    pen_up = false;
                }
                let _ = write!(
                    o,
                    r#"<path class="line" d="{path}" fill="none" stroke="{c}" stroke-width="1.8"{}/>"#,
                    dash(s.style)
                );
            }
            if matches!(s.style, Style::Markers | Style::LineMarkers) {
                for &(x, y) in &s.points {
                    if self.usable(x, y) {
                        o.push_str(&marker("point", i, px(x), py(y), c));
                    }
                }
            }
        }
    }

    /// The legend, right of the plot area: a key and its label (broken into lines at the
    /// legend's width) a series, then the notes.
    fn legend(&self, o: &mut String, f: &Frame) {
        let lx = f.ml + f.pw + 14.0;
        let mut y = f.mt + 10.0;
        for (i, s) in self.series.iter().enumerate() {
            let i = s.look.unwrap_or(i);
            let c = PALETTE[i % PALETTE.len()];
            if s.style != Style::Markers {
                let _ = write!(
                    o,
                    r#"<line x1="{lx}" y1="{y}" x2="{}" y2="{y}" stroke="{c}" stroke-width="1.8"{}/>"#,
                    lx + 22.0,
                    dash(s.style)
                );
            }
            if matches!(s.style, Style::Markers | Style::LineMarkers) {
                o.push_str(&marker("key", i, lx + 11.0, y, c));
            }
            y = text_lines(o, &s.label, lx + 28.0, y + 4.0, f.w - EDGE) - 1.0;
        }
        for note in &self.notes {
            y = text_lines(o, note, lx, y + 4.0, f.w - EDGE) - 1.0;
        }
    }
}

/// Writes `text` left-aligned at (`x`, `y`) in the default size, broken into lines that end
/// before `right`; the baseline of the line after the last.
fn text_lines(o: &mut String, text: &str, x: f64, y: f64, right: f64) -> f64 {
    let mut y = y;
    for line in wrap(text, TEXT_SIZE, right - x) {
        let _ = write!(o, r#"<text x="{x:.1}" y="{y:.1}">{}</text>"#, esc(&line));
        y += 15.0;
    }
    y
}

/// The estimated width of `text` set at `size` pixels ([`TEXT_EM`] a character).
pub fn text_width(text: &str, size: f64) -> f64 {
    text.chars().count() as f64 * TEXT_EM * size
}

/// `text` broken at spaces into lines no wider than `width` at `size` (a word longer than a
/// line is broken inside).
fn wrap(text: &str, size: f64, width: f64) -> Vec<String> {
    let per_line = ((width / (TEXT_EM * size)).floor() as usize).max(1);
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        let mut word: Vec<char> = word.chars().collect();
        while word.len() > per_line {
            if !line.is_empty() {
                lines.push(std::mem::take(&mut line));
            }
            lines.push(word.drain(..per_line).collect());
        }
        let n = line.chars().count();
        if n > 0 && n + 1 + word.len() > per_line {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.extend(word);
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

/// The font size, at most `size`, at which `text` is no wider than `width`.
fn fitted_size(text: &str, size: f64, width: f64) -> f64 {
    let w = text_width(text, size);
    if w <= width {
        size
    } else {
        (size * width / w * 10.0).floor() / 10.0
    }
}

/// The mark an SVG carries for a series without a usable point (see `studies::write_text`).
pub const EMPTY_SERIES: &str = "empty series";

/// The dash attribute of a series' line.
fn dash(style: Style) -> &'static str {
    if style == Style::Dashed {
        r#" stroke-dasharray="6,4""#
    } else {
        ""
    }
}

/// A chart's canvas (w × h), plot area (left and top margins, width and height) and title lines.
struct Frame {
    w: f64,
    h: f64,
    ml: f64,
    mt: f64,
    pw: f64,
    ph: f64,
    title: Vec<String>,
}

impl Frame {
    /// The canvas `w` × `h` with the standard left and bottom margins, `right` for the legend
    /// or colour bar, and a top margin that holds `title` broken into lines.
    fn new((w, h): (f64, f64), right: f64, title: &str) -> Frame {
        let title = wrap(title, TITLE_SIZE, w - 2.0 * EDGE);
        let (ml, mb) = (78.0, 58.0);
        let mt = 40.0 + 18.0 * (title.len() - 1) as f64;
        Frame {
            w,
            h,
            ml,
            mt,
            pw: w - ml - right,
            ph: h - mt - mb,
            title,
        }
    }

    /// The SVG document's opening, white background and title (centred on the canvas).
    fn open(&self) -> String {
        let (w, h) = (self.w, self.h);
        let mut o = String::new();
        let _ = write!(
            o,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="Helvetica, Arial, sans-serif" font-size="{TEXT_SIZE}">"#
        );
        let _ = write!(o, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
        for (i, line) in self.title.iter().enumerate() {
            let _ = write!(
                o,
                r#"<text x="{}" y="{}" text-anchor="middle" font-size="{TITLE_SIZE}">{}</text>"#,
                w / 2.0,
                22.0 + 18.0 * i as f64,
                esc(line)
            );
        }
        o
    }

    /// The plot area's border (the `plot-area` rectangle).
    fn border(&self, o: &mut String) {
        let _ = write!(
            o,
            r#"<rect class="plot-area" x="{}" y="{}" width="{}" height="{}" fill="none" stroke="black"/>"#,
            self.ml, self.mt, self.pw, self.ph
        );
    }

    /// The axis labels below and left of the plot area, centred on it, each set smaller where
    /// it would not fit the canvas.
    fn axis_labels(&self, o: &mut String, x_label: &str, y_label: &str) {
        let cx = self.ml + self.pw / 2.0;
        let size = fitted_size(x_label, LABEL_SIZE, 2.0 * (cx.min(self.w - cx) - EDGE));
        let _ = write!(
            o,
            r#"<text x="{cx:.1}" y="{:.1}" text-anchor="middle" font-size="{size}">{}</text>"#,
            self.h - 14.0,
            esc(x_label)
        );
        let cy = self.mt + self.ph / 2.0;
        let size = fitted_size(y_label, LABEL_SIZE, 2.0 * (cy.min(self.h - cy) - EDGE));
        let _ = write!(
            o,
            r#"<text transform="translate(18,{cy:.1}) rotate(-90)" text-anchor="middle" font-size="{size}">{}</text>"#,
            esc(y_label)
        );
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
    /// Renders the map as an SVG document (760×480 px, `CANVAS`).
    pub fn to_svg(&self) -> String {
        let f = Frame::new(CANVAS, 120.0, &self.title);
        let ex = cell_edges(&self.xs, self.x_log);
        let ey = cell_edges(&self.ys, self.y_log);
        let (x0, x1) = (ex[0], *ex.last().unwrap_or(&1.0));
        let (y0, y1) = (ey[0], *ey.last().unwrap_or(&1.0));
        let px = |t: f64| f.ml + f.pw * (t - x0) / (x1 - x0);
        let py = |t: f64| f.mt + f.ph * (1.0 - (t - y0) / (y1 - y0));
        let mut o = f.open();
        let (ml, mt, pw, ph) = (f.ml, f.mt, f.pw, f.ph);
        for (j, row) in self.z.iter().enumerate() {
            for (i, &v) in row.iter().enumerate() {
                if i + 1 >= ex.len() || j + 1 >= ey.len() {
                    continue;
                }
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
                    yb - ya - 0.005,
                );
            }
        }
        f.border(&mut o);
        for t in ticks_within(x0, x1, self.x_log) {
            let x = px(t.0);
            let _ = write!(
                o,
                r#"<line x1="{x:.1}" y1="{:.1}" x2="{x:.1}" y2="{:.1}" stroke="black"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
                mt + ph,
                mt + ph + 5.0,
                mt + ph + 18.0,
                esc(&t.1)
            );
        }
        for t in ticks_within(y0, y1, self.y_log) {
            let y = py(t.0);
            let _ = write!(
                o,
                r#"<line x1="{:.1}" y1="{y:.1}" x2="{ml}" y2="{y:.1}" stroke="black"/><text x="{:.1}" y="{:.1}" text-anchor="end">{}</text>"#,
                ml - 5.0,
                ml - 7.0,
                y + 4.0,
                esc(&t.1)
            );
        }
        f.axis_labels(&mut o, &self.x_label, &self.y_label);
        self.colour_bar(&mut o, &f);
        o.push_str("</svg>\n");
        o
    }

    /// The colour bar and its label, right of the map; under it a grey key naming the cells
    /// without a value, when there are any.
    fn colour_bar(&self, o: &mut String, f: &Frame) {
        let missing = self.z.iter().flatten().any(|v| !v.is_finite());
        let mt = f.mt;
        let ph = if missing { f.ph - 30.0 } else { f.ph };
        let bx = f.ml + f.pw + 24.0;
        let n = 50;
        for k in 0..n {
            let v =
                self.z_range.0 + (self.z_range.1 - self.z_range.0) * (k as f64 + 0.5) / n as f64;
            let y = mt + ph * (1.0 - (k + 1) as f64 / n as f64);
            let _ = write!(
                o,
                r#"<rect x="{bx}" y="{y:.2}" width="18" height="{:.2}" fill="{}"/>"#,
                ph / n as f64 + 0.3,
                colour(v, self.z_range)
            );
        }
        let _ = write!(
            o,
            r#"<rect x="{bx}" y="{mt}" width="18" height="{ph}" fill="none" stroke="black"/>"#
        );
        let (lo, hi) = self.z_range;
        let bar = Axis { lo, hi, log: false };
        for (v, label) in bar.ticks() {
            let y = mt + ph * (1.0 - bar.frac(v));
            let _ = write!(
                o,
                r#"<text x="{:.1}" y="{:.1}">{}</text>"#,
                bx + 22.0,
                y + 4.0,
                esc(&label)
            );
        }
        if missing {
            let y = f.mt + f.ph - 16.0;
            let _ = write!(
                o,
                r#"<rect x="{bx}" y="{y}" width="18" height="16" fill="{GREY}" stroke="black"/>"#
            );
            text_lines(o, &self.missing, bx + 22.0, y + 12.0, f.w - EDGE);
        }
        let size = fitted_size(&self.z_label, TEXT_SIZE, ph - 2.0 * EDGE);
        let _ = write!(
            o,
            r#"<text transform="translate({:.1},{:.1}) rotate(-90)" text-anchor="middle" font-size="{size}">{}</text>"#,
            bx + 70.0,
            mt + ph / 2.0,
            esc(&self.z_label)
        );
    }
}

/// The cell edges of a heat map axis with cell centres `c` (in log10 on a log axis).
fn cell_edges(c: &[f64], log: bool) -> Vec<f64> {
    let t: Vec<f64> = c.iter().map(|&v| if log { v.log10() } else { v }).collect();
    let n = t.len();
    if n == 1 {
        return vec![t[0] - 0.5, t[0] + 0.5];
    }
    let mut e = Vec::with_capacity(n + 1);
    e.push(t[0] - (t[1] - t[0]) / 2.0);
    for i in 0..n - 1 {
        e.push((t[i] + t[i + 1]) / 2.0);
    }
    e.push(t[n - 1] + (t[n - 1] - t[n - 2]) / 2.0);
    e
}

/// The ticks of a heat map axis spanning [t0, t1] (log10 values on a log axis), as positions
/// on that scale with their labels.
fn ticks_within(t0: f64, t1: f64, log: bool) -> Vec<(f64, String)> {
    let (lo, hi) = (t0.min(t1), t0.max(t1));
    (Axis { lo, hi, log }.ticks().into_iter())
        .map(|(v, label)| (if log { v.log10() } else { v }, label))
        .collect()
}

/// A perceptually ordered colour (viridis-like) for `v` in `range`.
fn colour(v: f64, range: (f64, f64)) -> String {
    const STOPS: [(f64, f64, f64); 6] = [
        (68.0, 1.0, 84.0),
        (65.0, 68.0, 135.0),
        (42.0, 120.0, 142.0),
        (34.0, 168.0, 132.0),
        (122.0, 209.0, 81.0),
        (253.0, 231.0, 37.0),
    ];
    let t = ((v - range.0) / (range.1 - range.0)).clamp(0.0, 1.0) * (STOPS.len() - 1) as f64;
    let i = (t.floor() as usize).min(STOPS.len() - 2);
    let f = t - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    format!(
        "rgb({},{},{})",
        (a.0 + f * (b.0 - a.0)).round(),
        (a.1 + f * (b.1 - a.1)).round(),
        (a.2 + f * (b.2 - a.2)).round()
    )
}

/// Appends a pixel coordinate with two decimals, as `{:.2}` writes it but from the whole
/// number of hundredths, digit by digit (the paths write thousands of coordinates, and the
/// formatting machinery cost several times the digits). The rounding is of x·100, which can
/// differ from `{:.2}` in the last digit within the product's rounding of a tie; a value that
/// rounds to zero is written without a sign. Implements no equation.
fn push_px(o: &mut String, v: f64) {
    let c = (v * 100.0).round();
    if c.is_nan() || c.abs() >= 1e15 {
        let _ = write!(o, "{v:.2}");
        return;
    }
    if c < 0.0 {
        o.push('-');
    }
    // At most 15 digits and the point; at least "0.00".
    let mut n = c.abs() as u64;
    let mut buf = [0u8; 20];
    let mut i = buf.len();
    let mut digits = 0;
    while n > 0 || digits < 3 {
        i -= 1;
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
        digits += 1;
        if digits == 2 {
            i -= 1;
            buf[i] = b'.';
        }
    }
    o.push_str(std::str::from_utf8(&buf[i..]).unwrap_or_default());
}

/// A marker of series `i` (circle, square, triangle in turn) centred at (`x`, `y`): a `g` of
/// class `class` (`point` in the plot, `key` in the legend) translated there.
fn marker(class: &str, i: usize, x: f64, y: f64, c: &str) -> String {
    let shape = match i % 3 {
        0 => format!(r#"<circle r="3.2" fill="{c}"/>"#),
        1 => format!(r#"<rect x="-3" y="-3" width="6" height="6" fill="{c}"/>"#),
        _ => format!(r#"<path d="M0,-4 L-3.6,3 L3.6,3 Z" fill="{c}"/>"#),
    };
    format!(r#"<g class="{class}" transform="translate({x:.2},{y:.2})">{shape}</g>"#)
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// A linear or logarithmic axis over [lo, hi] (log10 of the values on a log axis).
struct Axis {
    lo: f64,
    hi: f64,
    log: bool,
}

impl Axis {
    /// The axis fitted to `data` (the range of the points drawn) widened to `want`, padded by
    /// [`PAD`] of its span; on a log axis non-positive bounds of `want` are ignored.
    fn fit(data: Option<(f64, f64)>, want: Option<(f64, f64)>, log: bool) -> Axis {
        let to_axis = |v: f64| if log { v.log10() } else { v };
        let ok = |v: f64| v.is_finite() && (!log || v > 0.0);
        let mut range: Option<(f64, f64)> = None;
        let mut add = |v: f64| {
            if ok(v) {
                let t = to_axis(v);
                range = Some(range.map_or((t, t), |(lo, hi)| (t.min(lo), t.max(hi))));
            }
        };
        for (a, b) in data.into_iter().chain(want) {
            add(a);
            add(b);
        }
        let (lo, hi) = range.unwrap_or((0.0, 1.0));
        let span = hi - lo;
        let pad = if span > 0.0 {
            span * PAD
        } else if log {
            0.5
        } else if lo == 0.0 {
            1.0
        } else {
            lo.abs() * 0.1
        };
        Axis {
            lo: lo - pad,
            hi: hi + pad,
            log,
        }
    }
    fn frac(&self, v: f64) -> f64 {
        let t = if self.log { v.log10() } else { v };
        (t - self.lo) / (self.hi - self.lo)
    }
    /// The ticks inside the axis, (value, label).
    fn ticks(&self) -> Vec<(f64, String)> {
        if !self.log {
            return linear_ticks(self.lo, self.hi);
        }
        let (lo, hi) = (self.lo, self.hi);
        let raw = (hi - lo) / 8.0;
        let step =
            (([1, 2, 5, 10, 20, 50, 100].into_iter()).find(|&s| s as f64 >= raw)).unwrap_or(200);
        let (first, last) = (
            (lo / step as f64).ceil() as i64,
            (hi / step as f64).floor() as i64,
        );
        if last - first >= 2 {
            return (first..=last)
                .map(|j| (10f64.powi((j * step) as i32), log_label(1, j * step)))
                .collect();
        }
        let mut t: Vec<(f64, String)> = Vec::new();
        for e in lo.floor() as i64..=hi.ceil() as i64 {
            for m in [1, 2, 5] {
                let v = m as f64 * 10f64.powi(e as i32);
                if (lo..=hi).contains(&v.log10()) {
                    t.push((v, log_label(m, e)));
                }
            }
        }
        if t.len() >= 3 {
            return t;
        }
        // Under a decade: linear steps between the ends, placed on the log scale.
        linear_ticks(10f64.powf(lo), 10f64.powf(hi))
    }
}

/// The smallest of 1, 2, 2.5, 5 × 10^n at least `raw`.
fn nice_step(raw: f64) -> f64 {
    let mag = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag)
}

/// Ticks in 1-2-5 steps inside [lo, hi], about six to ten of them.
fn linear_ticks(lo: f64, hi: f64) -> Vec<(f64, String)> {
    let step = nice_step((hi - lo) / 8.0);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last)
        .map(|k| {
            let v = k as f64 * step;
            (v, fmt_tick(v, step))
        })
        .collect()
}

/// The label of m·10^e on a log axis: plain from 0.001 to 9999, else `me±n`.
fn log_label(m: i64, e: i64) -> String {
    if (-3..=3).contains(&e) {
        let v = m as f64 * 10f64.powi(e as i32);
        let decimals = (-e).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{m}e{e}")
    }
}

fn fmt_tick(v: f64, step: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    if v.abs() >= 1e5 || v.abs() < 1e-3 {
        return format!("{v:.1e}");
    }
    // As many decimals as the step has (2.5 needs one, 0.25 two).
    let decimals = (0..=12)
        .find(|&d| {
            let s = step * 10f64.powi(d);
            (s - s.round()).abs() <= 1e-9 * s
        })
        .unwrap_or(12) as usize;
    format!("{v:.decimals$}")
}

#[cfg(test)]
#[path = "../../tests/unit/svg.rs"]
mod tests;
