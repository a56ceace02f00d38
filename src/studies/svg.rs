//! A small SVG chart writer for the studies: line and scatter charts with linear or log axes,
//! labelled axes, grid, legend; and heat maps with a colour bar. No dependency: the charts are
//! plain SVG 1.1 text.
//!
//! No item of this module implements a formula of the paper: they draw the studies' results (each
//! study names its equations); coordinates are written to a tenth or a hundredth of a pixel.

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
    /// The points (non-finite points, and non-positive ones on a log axis, are skipped and break
    /// the line).
    pub points: Vec<(f64, f64)>,
    /// Drawing style.
    pub style: Style,
}

impl Series {
    /// A series with the given label, points and style.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style) -> Series {
        Series {
            label: label.into(),
            points,
            style,
        }
    }
}

/// A 2-D chart.
#[derive(Clone, Debug)]
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
    /// Fixed horizontal range (otherwise from the data).
    pub x_range: Option<(f64, f64)>,
    /// Fixed vertical range (otherwise from the data).
    pub y_range: Option<(f64, f64)>,
    /// The series.
    pub series: Vec<Series>,
    /// Width in pixels.
    pub width: f64,
    /// Height in pixels.
    pub height: f64,
}

const PALETTE: [&str; 10] = [
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
    "#7f7f7f", "#bcbd22",
];

impl Chart {
    /// An empty chart with a title and axis labels, linear axes, 760×480 px.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Chart {
        Chart {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            x_log: false,
            y_log: false,
            x_range: None,
            y_range: None,
            series: Vec::new(),
            width: 760.0,
            height: 480.0,
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

    fn data_range(&self, axis_x: bool) -> (f64, f64) {
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for s in &self.series {
            for &(x, y) in &s.points {
                if self.usable(x, y) {
                    let v = if axis_x { x } else { y };
                    lo = lo.min(v);
                    hi = hi.max(v);
                }
            }
        }
        if !lo.is_finite() {
            return (0.0, 1.0);
        }
        if lo == hi {
            let d = if lo == 0.0 { 1.0 } else { lo.abs() * 0.1 };
            return (lo - d, hi + d);
        }
        (lo, hi)
    }

    /// Renders the chart as an SVG document.
    pub fn to_svg(&self) -> String {
        let f = Frame::new(self.width, self.height, 190.0);
        let xr = self.x_range.unwrap_or_else(|| self.data_range(true));
        let yr = self.y_range.unwrap_or_else(|| self.data_range(false));
        let xa = Axis::new(xr, self.x_log);
        let ya = Axis::new(yr, self.y_log);
        let px = |x: f64| f.ml + f.pw * xa.frac(x);
        let py = |y: f64| f.mt + f.ph * (1.0 - ya.frac(y));
        let mut o = f.open(&self.title);
        // The frame, ticks and legend take a few kilobytes, each point of a path about 16 bytes:
        // the text is grown once, not doubled as it is written.
        let points: usize = self.series.iter().map(|s| s.points.len()).sum();
        o.reserve(8192 + 16 * points);
        // Grid and ticks.
        let (ml, mt, pw, ph) = (f.ml, f.mt, f.pw, f.ph);
        for (v, label) in xa.ticks() {
            let x = px(v);
            let _ = write!(
                o,
                r##"<line x1="{x:.1}" y1="{mt}" x2="{x:.1}" y2="{:.1}" stroke="#e6e6e6"/>"##,
                mt + ph
            );
            let _ = write!(
                o,
                r#"<text x="{x:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
                mt + ph + 16.0,
                esc(&label)
            );
        }
        for (v, label) in ya.ticks() {
            let y = py(v);
            let _ = write!(
                o,
                r##"<line x1="{ml}" y1="{y:.1}" x2="{:.1}" y2="{y:.1}" stroke="#e6e6e6"/>"##,
                ml + pw
            );
            let _ = write!(
                o,
                r#"<text x="{:.1}" y="{:.1}" text-anchor="end">{}</text>"#,
                ml - 6.0,
                y + 4.0,
                esc(&label)
            );
        }
        f.border(&mut o);
        f.axis_labels(&mut o, &self.x_label, &self.y_label);
        self.curves(&mut o, &f, &px, &py);
        self.legend(&mut o, &f);
        o.push_str("</svg>\n");
        o
    }

    /// The series, clipped to the plot area.
    fn curves(&self, o: &mut String, f: &Frame, px: &dyn Fn(f64) -> f64, py: &dyn Fn(f64) -> f64) {
        let _ = write!(
            o,
            r#"<clipPath id="plot"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath><g clip-path="url(#plot)">"#,
            f.ml, f.mt, f.pw, f.ph
        );
        for (i, s) in self.series.iter().enumerate() {
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
                    r#"<path d="{path}" fill="none" stroke="{c}" stroke-width="1.8"{}/>"#,
                    dash(s.style)
                );
            }
            if matches!(s.style, Style::Markers | Style::LineMarkers) {
                for &(x, y) in &s.points {
                    if self.usable(x, y) {
                        let _ = write!(o, "{}", marker(i, px(x), py(y), c));
                    }
                }
            }
        }
        o.push_str("</g>");
    }

    /// The legend, right of the plot area.
    fn legend(&self, o: &mut String, f: &Frame) {
        let lx = f.ml + f.pw + 14.0;
        for (i, s) in self.series.iter().enumerate() {
            let c = PALETTE[i % PALETTE.len()];
            let y = f.mt + 10.0 + 18.0 * i as f64;
            if s.style != Style::Markers {
                let _ = write!(
                    o,
                    r#"<line x1="{lx}" y1="{y}" x2="{}" y2="{y}" stroke="{c}" stroke-width="1.8"{}/>"#,
                    lx + 22.0,
                    dash(s.style)
                );
            }
            if matches!(s.style, Style::Markers | Style::LineMarkers) {
                let _ = write!(o, "{}", marker(i, lx + 11.0, y, c));
            }
            let _ = write!(
                o,
                r#"<text x="{}" y="{}">{}</text>"#,
                lx + 28.0,
                y + 4.0,
                esc(&s.label)
            );
        }
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

/// A chart's canvas (w × h) and plot area (left and top margins, width and height).
struct Frame {
    w: f64,
    h: f64,
    ml: f64,
    mt: f64,
    pw: f64,
    ph: f64,
}

impl Frame {
    /// The canvas `w` × `h` with the standard left, top and bottom margins and `right` for
    /// the legend or colour bar.
    fn new(w: f64, h: f64, right: f64) -> Frame {
        let (ml, mt, mb) = (78.0, 40.0, 58.0);
        Frame {
            w,
            h,
            ml,
            mt,
            pw: w - ml - right,
            ph: h - mt - mb,
        }
    }

    /// The SVG document's opening, white background and title.
    fn open(&self, title: &str) -> String {
        let (w, h) = (self.w, self.h);
        let mut o = String::new();
        let _ = write!(
            o,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="Helvetica, Arial, sans-serif" font-size="12">"#
        );
        let _ = write!(o, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
        let _ = write!(
            o,
            r#"<text x="{}" y="22" text-anchor="middle" font-size="15">{}</text>"#,
            self.ml + self.pw / 2.0,
            esc(title)
        );
        o
    }

    /// The plot area's border.
    fn border(&self, o: &mut String) {
        let _ = write!(
            o,
            r#"<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="black"/>"#,
            self.ml, self.mt, self.pw, self.ph
        );
    }

    /// The axis labels below and left of the plot area.
    fn axis_labels(&self, o: &mut String, x_label: &str, y_label: &str) {
        let _ = write!(
            o,
            r#"<text x="{:.1}" y="{:.1}" text-anchor="middle" font-size="13">{}</text>"#,
            self.ml + self.pw / 2.0,
            self.h - 14.0,
            esc(x_label)
        );
        let _ = write!(
            o,
            r#"<text transform="translate(18,{:.1}) rotate(-90)" text-anchor="middle" font-size="13">{}</text>"#,
            self.mt + self.ph / 2.0,
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
}

impl Heatmap {
    /// Renders the map as an SVG document (760×480 px).
    pub fn to_svg(&self) -> String {
        let f = Frame::new(760.0, 480.0, 120.0);
        let ex = cell_edges(&self.xs, self.x_log);
        let ey = cell_edges(&self.ys, self.y_log);
        let (x0, x1) = (ex[0], *ex.last().unwrap_or(&1.0));
        let (y0, y1) = (ey[0], *ey.last().unwrap_or(&1.0));
        let px = |t: f64| f.ml + f.pw * (t - x0) / (x1 - x0);
        let py = |t: f64| f.mt + f.ph * (1.0 - (t - y0) / (y1 - y0));
        let mut o = f.open(&self.title);
        for (j, row) in self.z.iter().enumerate() {
            for (i, &v) in row.iter().enumerate() {
                if i + 1 >= ex.len() || j + 1 >= ey.len() {
                    continue;
                }
                let (xa, xb) = (px(ex[i]), px(ex[i + 1]));
                let (ya, yb) = (py(ey[j + 1]), py(ey[j]));
                let fill = if v.is_finite() {
                    colour(v, self.z_range)
                } else {
                    "#bdbdbd".to_string()
                };
                let _ = write!(
                    o,
                    r#"<rect x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="{fill}"/>"#,
                    xa,
                    ya,
                    (xb - xa).abs() + 0.3,
                    (yb - ya).abs() + 0.3
                );
            }
        }
        f.border(&mut o);
        let (ml, mt, ph) = (f.ml, f.mt, f.ph);
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

    /// The colour bar and its label, right of the map.
    fn colour_bar(&self, o: &mut String, f: &Frame) {
        let (mt, ph) = (f.mt, f.ph);
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
        for (v, label) in Axis::new(self.z_range, false).ticks() {
            let y = mt + ph * (1.0 - (v - self.z_range.0) / (self.z_range.1 - self.z_range.0));
            let _ = write!(
                o,
                r#"<text x="{:.1}" y="{:.1}">{}</text>"#,
                bx + 22.0,
                y + 4.0,
                esc(&label)
            );
        }
        let _ = write!(
            o,
            r#"<text transform="translate({:.1},{:.1}) rotate(-90)" text-anchor="middle">{}</text>"#,
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
    let range = if log {
        (10f64.powf(t0), 10f64.powf(t1))
    } else {
        (t0, t1)
    };
    Axis::new(range, log)
        .ticks()
        .into_iter()
        .map(|(v, label)| (if log { v.log10() } else { v }, label))
        .filter(|(t, _)| *t >= t0.min(t1) - 1e-9 && *t <= t0.max(t1) + 1e-9)
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

fn marker(i: usize, x: f64, y: f64, c: &str) -> String {
    match i % 3 {
        0 => format!(r#"<circle cx="{x:.2}" cy="{y:.2}" r="3.2" fill="{c}"/>"#),
        1 => format!(
            r#"<rect x="{:.2}" y="{:.2}" width="6" height="6" fill="{c}"/>"#,
            x - 3.0,
            y - 3.0
        ),
        _ => format!(
            r#"<path d="M{:.2},{:.2} L{:.2},{:.2} L{:.2},{:.2} Z" fill="{c}"/>"#,
            x,
            y - 4.0,
            x - 3.6,
            y + 3.0,
            x + 3.6,
            y + 3.0
        ),
    }
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// A linear or logarithmic axis over a range.
struct Axis {
    lo: f64,
    hi: f64,
    log: bool,
}

impl Axis {
    fn new((lo, hi): (f64, f64), log: bool) -> Axis {
        if log {
            let (l, h) = (
                lo.max(1e-300).log10().floor(),
                hi.max(1e-300).log10().ceil(),
            );
            let h = if h <= l { l + 1.0 } else { h };
            Axis { lo: l, hi: h, log }
        } else {
            let span = hi - lo;
            let pad = if span > 0.0 { span * 0.04 } else { 1.0 };
            Axis {
                lo: lo - pad,
                hi: hi + pad,
                log,
            }
        }
    }
    fn frac(&self, v: f64) -> f64 {
        let t = if self.log { v.log10() } else { v };
        (t - self.lo) / (self.hi - self.lo)
    }
    fn ticks(&self) -> Vec<(f64, String)> {
        if self.log {
            let span = (self.hi - self.lo) as i64;
            let step = ((span as f64) / 10.0).ceil().max(1.0) as i64;
            (self.lo as i64..=self.hi as i64)
                .filter(|e| (e - self.lo as i64) % step == 0)
                .map(|e| (10f64.powi(e as i32), format!("1e{e}")))
                .collect()
        } else {
            let span = self.hi - self.lo;
            let raw = span / 8.0;
            let mag = 10f64.powf(raw.log10().floor());
            let step = [1.0, 2.0, 2.5, 5.0, 10.0]
                .iter()
                .map(|m| m * mag)
                .find(|s| *s >= raw)
                .unwrap_or(10.0 * mag);
            let first = (self.lo / step).ceil() as i64;
            let last = (self.hi / step).floor() as i64;
            (first..=last)
                .map(|k| {
                    let v = k as f64 * step;
                    (v, fmt_tick(v, step))
                })
                .collect()
        }
    }
}

fn fmt_tick(v: f64, step: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    if v.abs() >= 1e5 || v.abs() < 1e-3 {
        return format!("{v:.1e}");
    }
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    format!("{v:.decimals$}")
}

#[cfg(test)]
mod tests {
    use super::push_px;

    fn px(v: f64) -> String {
        let mut s = String::new();
        push_px(&mut s, v);
        s
    }

    /// `push_px` writes what `{:.2}` writes, except within the product's rounding of a tie of x·100,
    /// where it may differ by one in the last digit; the sign of a value that rounds to zero is dropped.
    #[test]
    fn px_writes_two_decimals_as_format_does() {
        let mut x = 0.000_123_f64;
        let mut differ = 0;
        for j in 0..20_000 {
            for v in [x, -x, x * 1e3, 1e12 + x] {
                let (got, want) = (px(v), format!("{v:.2}"));
                if got != want {
                    let (g, w): (f64, f64) = (got.parse().unwrap(), want.parse().unwrap());
                    // Within the rounding of the product x·100 of a tie.
                    let tie = ((v * 100.0).fract().abs() - 0.5).abs() <= (v * 100.0).abs() * 4e-16;
                    assert!(
                        (tie && (g - w).abs() < 0.015) || (g == 0.0 && w == 0.0),
                        "{v}: {got} against {want} (case {j})"
                    );
                    differ += 1;
                }
            }
            x = x * 1.003 + 0.0037;
        }
        assert!(differ < 800, "{differ} of 80000 differ"); // rare: under 1 %
        assert_eq!(px(1e300), format!("{:.2}", 1e300));
        assert_eq!(px(-0.004), "0.00");
        assert_eq!(px(1.005), "1.00"); // 1.005 is 1.00499999999999989… in binary
        assert_eq!(px(-12.345678), "-12.35");
    }
}
