//! Line plots as standalone SVG: linear or logarithmic axes, tick labels, a legend.
//!
//! Written by hand rather than with a plotting crate: the plots are simple (a few series of
//! points), and plain SVG text keeps the output diffable and the dependency tree small.

use std::fmt::Write;

/// How an axis maps values.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Linear.
    Linear,
    /// Base-10 logarithmic (non-positive values are left out).
    Log,
}

/// One named series of `(x, y)` points, drawn as a polyline with markers.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The legend entry.
    pub name: String,
    /// The points, in drawing order.
    pub points: Vec<(f64, f64)>,
    /// Join the points with a line (else markers only).
    pub line: bool,
}

/// A series of `(x, y)` points collected one at a time in memory bounded whatever their
/// number: up to [`DecimatedSeries::MAX_BUCKETS`] points are kept as given; past that the points
/// are grouped into buckets of consecutive points (the bucket size doubling each time the
/// bound is reached) and each bucket keeps its lowest and highest point, in x order — so a
/// plot of a million output steps keeps every peak and trough in at most `2 × MAX_BUCKETS`
/// points, and a plot of a short run is unchanged.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DecimatedSeries {
    /// Closed buckets: their lowest and highest points in x order (equal for one point).
    buckets: Vec<[(f64, f64); 2]>,
    /// The bucket being filled, and how many points it holds.
    open: Option<([(f64, f64); 2], usize)>,
    /// Points per bucket (a power of two).
    stride: usize,
}

impl DecimatedSeries {
    /// The most buckets kept (each drawn as at most two points).
    pub const MAX_BUCKETS: usize = 16_384;

    /// An empty series.
    pub fn new() -> Self {
        Self {
            buckets: Vec::new(),
            open: None,
            stride: 1,
        }
    }

    /// Adds the next point (x increasing).
    pub fn push(&mut self, point: (f64, f64)) {
        let stride = self.stride.max(1);
        let (extremes, count) = match self.open.take() {
            None => ([point, point], 1),
            Some((extremes, count)) => (merge(extremes, [point, point]), count + 1),
        };
        if count < stride {
            self.open = Some((extremes, count));
            return;
        }
        self.buckets.push(extremes);
        if self.buckets.len() >= Self::MAX_BUCKETS {
            self.buckets = self
                .buckets
                .chunks(2)
                .map(|pair| pair.iter().copied().reduce(merge).unwrap_or(pair[0]))
                .collect();
            self.stride = stride * 2;
        }
    }

    /// The points to draw, in x order.
    pub fn points(&self) -> Vec<(f64, f64)> {
        let mut out: Vec<(f64, f64)> = Vec::with_capacity(2 * self.buckets.len() + 2);
        for [a, b] in self.buckets.iter().chain(self.open.iter().map(|(e, _)| e)) {
            out.push(*a);
            if b != a {
                out.push(*b);
            }
        }
        out
    }
}

/// The lowest and highest of two buckets' extremes, in x order (the earlier point wins a tie).
fn merge(a: [(f64, f64); 2], b: [(f64, f64); 2]) -> [(f64, f64); 2] {
    let all = [a[0], a[1], b[0], b[1]];
    let low = all
        .iter()
        .copied()
        .reduce(|m, p| if p.1 < m.1 { p } else { m });
    let high = all
        .iter()
        .copied()
        .reduce(|m, p| if p.1 > m.1 { p } else { m });
    let (low, high) = (low.unwrap_or(a[0]), high.unwrap_or(a[0]));
    if low.0 <= high.0 {
        [low, high]
    } else {
        [high, low]
    }
}

/// A plot: title, axis labels and scales, series.
#[derive(Debug, Clone, PartialEq)]
pub struct Plot {
    /// The title above the plot.
    pub title: String,
    /// The x axis label (with units).
    pub x_label: String,
    /// The y axis label (with units).
    pub y_label: String,
    /// The x axis scale.
    pub x_scale: Scale,
    /// The y axis scale.
    pub y_scale: Scale,
    /// The data.
    pub series: Vec<Series>,
    /// A line of text under the legend (what was left out), if any.
    pub note: Option<String>,
}

/// The most series a plot draws: one per colour and marker shape, as many as the legend's
/// column holds.
pub const MAX_SERIES: usize = 3 * COLOURS.len();

const WIDTH: f64 = 960.0;
const HEIGHT: f64 = 600.0;
const LEFT: f64 = 90.0;
const RIGHT: f64 = 250.0;
const TOP: f64 = 50.0;
const BOTTOM: f64 = 70.0;
/// A colour-blind-safe palette (Okabe & Ito), cycled with marker shapes for more series.
const COLOURS: [&str; 8] = [
    "#0072B2", "#E69F00", "#009E73", "#D55E00", "#CC79A7", "#56B4E9", "#F0E442", "#000000",
];

impl Plot {
    /// Keeps the `max` series whose largest `|y|` is largest (ties to the earlier), in their
    /// order, and returns how many it left out and how many of those were zero throughout (a
    /// contact that never touched). A plot of a model with thousands of contacts would
    /// otherwise draw them all, one legend entry each, in tens of megabytes.
    pub fn keep_largest(&mut self, max: usize) -> (usize, usize) {
        if self.series.len() <= max {
            return (0, 0);
        }
        let peak = |s: &Series| {
            s.points
                .iter()
                .map(|p| p.1.abs())
                .filter(|y| y.is_finite())
                .fold(0.0, f64::max)
        };
        let peaks: Vec<f64> = self.series.iter().map(peak).collect();
        let mut order: Vec<usize> = (0..self.series.len()).collect();
        order.sort_by(|&a, &b| peaks[b].total_cmp(&peaks[a]).then(a.cmp(&b)));
        let mut keep = vec![false; self.series.len()];
        for &k in &order[..max] {
            keep[k] = true;
        }
        let silent = order[max..].iter().filter(|&&k| peaks[k] == 0.0).count();
        let mut index = 0;
        self.series.retain(|_| {
            index += 1;
            keep[index - 1]
        });
        (order.len() - max, silent)
    }

    /// Renders the plot as an SVG document. Points that cannot be drawn (non-finite, or
    /// non-positive on a log axis) are left out; a plot with no drawable point says so.
    pub fn to_svg(&self) -> String {
        let series = self.drawable_series();
        let all: Vec<(f64, f64)> = series.iter().flat_map(|(_, p)| p.iter().copied()).collect();
        let mut svg = String::new();
        let _ = writeln!(
            svg,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" viewBox="0 0 {WIDTH} {HEIGHT}" font-family="sans-serif" font-size="13">"#
        );
        let _ = writeln!(svg, r#"<rect width="100%" height="100%" fill="white"/>"#);
        let _ = writeln!(
            svg,
            r#"<text x="{}" y="28" text-anchor="middle" font-size="17">{}</text>"#,
            (LEFT + WIDTH - RIGHT) / 2.0,
            escape(&self.title)
        );
        if all.is_empty() {
            let _ = writeln!(
                svg,
                r#"<text x="{}" y="{}" text-anchor="middle">no data to draw</text></svg>"#,
                WIDTH / 2.0,
                HEIGHT / 2.0
            );
            return svg;
        }
        let frame = Frame::around(&all);
        self.write_axes(&mut svg, &frame);
        for (k, pts) in &series {
            self.write_series(&mut svg, &frame, *k, pts);
        }
        if let Some(note) = &self.note {
            let _ = writeln!(
                svg,
                r#"<text x="{}" y="{}">{}</text>"#,
                WIDTH - RIGHT + 16.0,
                TOP + 14.0 + 20.0 * self.series.len() as f64,
                escape(note)
            );
        }
        svg.push_str("</svg>\n");
        svg
    }

    /// Each series' drawable points, transformed to the axes' scales, with its index.
    fn drawable_series(&self) -> Vec<(usize, Vec<(f64, f64)>)> {
        let drawable = |x: f64, s: Scale| x.is_finite() && (s == Scale::Linear || x > 0.0);
        self.series
            .iter()
            .enumerate()
            .map(|(k, s)| {
                let pts = s
                    .points
                    .iter()
                    .copied()
                    .filter(|&(x, y)| drawable(x, self.x_scale) && drawable(y, self.y_scale))
                    .map(|(x, y)| (transform(x, self.x_scale), transform(y, self.y_scale)))
                    .collect();
                (k, pts)
            })
            .collect()
    }

    /// The plot area's border, the grid lines with their tick labels, and the axis labels.
    fn write_axes(&self, svg: &mut String, f: &Frame) {
        let (pw, ph) = (f.width, f.height);
        let _ = writeln!(
            svg,
            r##"<rect x="{LEFT}" y="{TOP}" width="{pw}" height="{ph}" fill="none" stroke="#444"/>"##
        );
        for (v, label) in ticks(f.x0, f.x1, self.x_scale) {
            let x = f.sx(v);
            let _ = writeln!(
                svg,
                r##"<line x1="{x:.1}" y1="{TOP}" x2="{x:.1}" y2="{:.1}" stroke="#ddd"/>"##,
                TOP + ph
            );
            let _ = writeln!(
                svg,
                r#"<text x="{x:.1}" y="{:.1}" text-anchor="middle">{label}</text>"#,
                TOP + ph + 18.0
            );
        }
        for (v, label) in ticks(f.y0, f.y1, self.y_scale) {
            let y = f.sy(v);
            let _ = writeln!(
                svg,
                r##"<line x1="{LEFT}" y1="{y:.1}" x2="{:.1}" y2="{y:.1}" stroke="#ddd"/>"##,
                LEFT + pw
            );
            let _ = writeln!(
                svg,
                r#"<text x="{:.1}" y="{:.1}" text-anchor="end">{label}</text>"#,
                LEFT - 6.0,
                y + 4.0
            );
        }
        let _ = writeln!(
            svg,
            r#"<text x="{}" y="{}" text-anchor="middle">{}</text>"#,
            LEFT + pw / 2.0,
            HEIGHT - 20.0,
            escape(&self.x_label)
        );
        let _ = writeln!(
            svg,
            r#"<text x="20" y="{0}" text-anchor="middle" transform="rotate(-90 20 {0})">{1}</text>"#,
            TOP + ph / 2.0,
            escape(&self.y_label)
        );
    }

    /// Series `k`: its line (when drawn as one), its markers and its legend entry.
    fn write_series(&self, svg: &mut String, f: &Frame, k: usize, pts: &[(f64, f64)]) {
        let colour = COLOURS[k % COLOURS.len()];
        if self.series[k].line && pts.len() > 1 {
            let path: Vec<String> = pts
                .iter()
                .map(|&(x, y)| format!("{:.1},{:.1}", f.sx(x), f.sy(y)))
                .collect();
            let _ = writeln!(
                svg,
                r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-width="2"/>"#,
                path.join(" ")
            );
        }
        for &(x, y) in pts {
            let _ = writeln!(
                svg,
                "{}",
                marker(k / COLOURS.len(), f.sx(x), f.sy(y), colour)
            );
        }
        let ly = TOP + 10.0 + 20.0 * k as f64;
        let lx = WIDTH - RIGHT + 16.0;
        let _ = writeln!(
            svg,
            r#"<line x1="{lx}" y1="{ly}" x2="{}" y2="{ly}" stroke="{colour}" stroke-width="2"/>"#,
            lx + 22.0
        );
        let _ = writeln!(svg, "{}", marker(k / COLOURS.len(), lx + 11.0, ly, colour));
        let _ = writeln!(
            svg,
            r#"<text x="{}" y="{}">{}</text>"#,
            lx + 28.0,
            ly + 4.0,
            escape(&self.series[k].name)
        );
    }
}

/// The data ranges (padded, in the axes' scales) and the plot area they map onto.
struct Frame {
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
    width: f64,
    height: f64,
}

impl Frame {
    fn around(points: &[(f64, f64)]) -> Self {
        let (x0, x1) = padded_range(points.iter().map(|p| p.0));
        let (y0, y1) = padded_range(points.iter().map(|p| p.1));
        Self {
            x0,
            x1,
            y0,
            y1,
            width: WIDTH - LEFT - RIGHT,
            height: HEIGHT - TOP - BOTTOM,
        }
    }

    /// The SVG x of a data x.
    fn sx(&self, x: f64) -> f64 {
        LEFT + (x - self.x0) / (self.x1 - self.x0) * self.width
    }

    /// The SVG y of a data y (up is smaller).
    fn sy(&self, y: f64) -> f64 {
        TOP + self.height - (y - self.y0) / (self.y1 - self.y0) * self.height
    }
}

fn transform(v: f64, s: Scale) -> f64 {
    match s {
        Scale::Linear => v,
        Scale::Log => v.log10(),
    }
}

fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    let span = hi - lo;
    let pad = if span > 0.0 {
        0.05 * span
    } else {
        0.5 * lo.abs().max(1.0)
    };
    (lo - pad, hi + pad)
}

/// Tick positions (in transformed units) with their labels.
fn ticks(lo: f64, hi: f64, s: Scale) -> Vec<(f64, String)> {
    match s {
        Scale::Log => {
            let step = ((hi - lo) / 8.0).ceil().max(1.0);
            let mut out = Vec::new();
            let mut e = (lo / step).ceil() * step;
            while e <= hi {
                out.push((e, format!("1e{}", e.round() as i64)));
                e += step;
            }
            out
        }
        Scale::Linear => {
            let raw = (hi - lo) / 6.0;
            let magnitude = 10f64.powf(raw.log10().floor());
            let step = [1.0, 2.0, 5.0, 10.0]
                .iter()
                .map(|m| m * magnitude)
                .find(|&s| s >= raw)
                .unwrap_or(10.0 * magnitude);
            let mut out = Vec::new();
            let mut v = (lo / step).ceil() * step;
            while v <= hi {
                out.push((v, format!("{}", (v / step).round() * step)));
                v += step;
            }
            out
        }
    }
}

fn marker(shape: usize, x: f64, y: f64, colour: &str) -> String {
    match shape % 3 {
        0 => format!(r#"<circle cx="{x:.1}" cy="{y:.1}" r="4" fill="{colour}"/>"#),
        1 => format!(
            r#"<rect x="{:.1}" y="{:.1}" width="8" height="8" fill="{colour}"/>"#,
            x - 4.0,
            y - 4.0
        ),
        _ => format!(
            r#"<path d="M{x:.1},{:.1} L{:.1},{:.1} L{:.1},{:.1} Z" fill="{colour}"/>"#,
            y - 5.0,
            x + 5.0,
            y + 4.0,
            x - 5.0,
            y + 4.0
        ),
    }
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_log_plot_has_decade_ticks_a_legend_and_every_point() {
        let plot = Plot {
            title: "error <against> time".into(),
            x_label: "time (ns)".into(),
            y_label: "error".into(),
            x_scale: Scale::Log,
            y_scale: Scale::Log,
            note: None,
            series: vec![
                Series {
                    name: "a".into(),
                    points: vec![(1e2, 1e-3), (1e3, 1e-5), (1e4, 1e-7)],
                    line: true,
                },
                Series {
                    name: "b".into(),
                    points: vec![(5e2, 0.0), (2e3, 1e-4)],
                    line: false,
                },
            ],
        };
        let svg = plot.to_svg();
        assert!(svg.starts_with("<svg") && svg.ends_with("</svg>\n"));
        assert!(svg.contains("error &lt;against&gt; time"));
        assert!(svg.contains(">1e3<") && svg.contains(">1e-5<"));
        // 3 + 1 drawable points (0 is not drawable on a log axis) + 2 legend markers.
        assert_eq!(svg.matches("<circle").count(), 6);
        assert!(svg.contains(">a<") && svg.contains(">b<"));
    }

    #[test]
    fn a_decimated_series_keeps_short_series_and_bounds_long_ones_with_their_extremes() {
        let mut short = DecimatedSeries::new();
        let points: Vec<(f64, f64)> = (0..1000).map(|k| (k as f64, (k % 7) as f64)).collect();
        for p in &points {
            short.push(*p);
        }
        assert_eq!(short.points(), points);

        let mut long = DecimatedSeries::new();
        for k in 0..1_000_000u32 {
            let x = f64::from(k);
            let y = if k == 777_777 {
                1e9
            } else if k == 3 {
                -1e9
            } else {
                x.sin()
            };
            long.push((x, y));
        }
        let kept = long.points();
        assert!(
            kept.len() <= 2 * DecimatedSeries::MAX_BUCKETS + 2,
            "{}",
            kept.len()
        );
        assert!(kept.windows(2).all(|w| w[0].0 < w[1].0));
        assert!(kept.contains(&(777_777.0, 1e9)) && kept.contains(&(3.0, -1e9)));
    }

    #[test]
    fn an_empty_plot_says_so() {
        let plot = Plot {
            title: "t".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Log,
            note: None,
            series: vec![Series {
                name: "s".into(),
                points: vec![(1.0, -1.0)],
                line: true,
            }],
        };
        assert!(plot.to_svg().contains("no data to draw"));
    }

    /// A plot of `count` series; series `k` peaks at `|y| = peak(k)` at one of its points.
    fn plot_of(count: usize, peak: impl Fn(usize) -> f64) -> Plot {
        Plot {
            title: "many".into(),
            x_label: "t".into(),
            y_label: "y".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series: (0..count)
                .map(|k| Series {
                    name: format!("s{k}"),
                    points: vec![(0.0, 0.0), (1.0, -peak(k)), (2.0, 0.0)],
                    line: true,
                })
                .collect(),
            note: None,
        }
    }

    #[test]
    fn a_plot_of_many_series_keeps_the_largest_in_their_order() {
        // 40 series: every fourth zero throughout, the others peaking at 1 + (k·7 mod 40).
        let peak = |k: usize| {
            if k.is_multiple_of(4) {
                0.0
            } else {
                1.0 + ((k * 7) % 40) as f64
            }
        };
        let mut plot = plot_of(40, peak);
        assert_eq!(plot.keep_largest(MAX_SERIES), (40 - MAX_SERIES, 10));
        let mut expected: Vec<usize> = (0..40).filter(|&k| peak(k) > 0.0).collect();
        expected.sort_by(|&a, &b| peak(b).total_cmp(&peak(a)));
        expected.truncate(MAX_SERIES);
        expected.sort_unstable();
        let kept: Vec<String> = plot.series.iter().map(|s| s.name.clone()).collect();
        let names: Vec<String> = expected.iter().map(|k| format!("s{k}")).collect();
        assert_eq!(kept, names);
        plot.note = Some("+ 16 more".into());
        let svg = plot.to_svg();
        assert!(svg.contains(">+ 16 more</text>"));
        assert_eq!(svg.matches("<polyline").count(), MAX_SERIES);
    }

    #[test]
    fn a_plot_within_the_limit_is_left_as_it_is() {
        let mut plot = plot_of(MAX_SERIES, |k| k as f64);
        let before = plot.clone();
        assert_eq!(plot.keep_largest(MAX_SERIES), (0, 0));
        assert_eq!(plot, before);
    }
}
