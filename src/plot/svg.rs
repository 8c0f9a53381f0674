//! A small SVG writer: self-contained output, fixed number formatting (two decimals), so the
//! same picture is always the same bytes.

use std::fmt::Write;

/// Fonts people have: the system UI font, then common sans-serif fallbacks.
pub const FONTS: &str =
    "system-ui, -apple-system, 'Segoe UI', Roboto, 'Helvetica Neue', Arial, sans-serif";

/// Escapes text for XML.
pub fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A screen coordinate, two decimals.
pub fn f(x: f64) -> String {
    let s = format!("{x:.2}");
    if s == "-0.00" { "0.00".into() } else { s }
}

/// An SVG document under construction.
pub struct Svg {
    width: f64,
    height: f64,
    attrs: Vec<(String, String)>,
    body: String,
}

impl Svg {
    pub fn new(width: f64, height: f64) -> Svg {
        Svg {
            width,
            height,
            attrs: Vec::new(),
            body: String::new(),
        }
    }

    /// An attribute on the root element (`data-*` attributes record the data-to-screen map).
    pub fn attr(&mut self, name: &str, value: String) {
        self.attrs.push((name.into(), value));
    }

    pub fn raw(&mut self, s: &str) {
        self.body.push_str(s);
        self.body.push('\n');
    }

    pub fn line(
        &mut self,
        id: Option<&str>,
        (x1, y1): (f64, f64),
        (x2, y2): (f64, f64),
        style: &str,
    ) {
        let id = id.map(|i| format!(" id=\"{i}\"")).unwrap_or_default();
        let _ = writeln!(
            self.body,
            "<line{id} x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" {style}/>",
            f(x1),
            f(y1),
            f(x2),
            f(y2)
        );
    }

    pub fn polyline(&mut self, id: Option<&str>, points: &[(f64, f64)], style: &str) {
        let id = id.map(|i| format!(" id=\"{i}\"")).unwrap_or_default();
        let pts: Vec<String> = points
            .iter()
            .map(|(x, y)| format!("{},{}", f(*x), f(*y)))
            .collect();
        let _ = writeln!(
            self.body,
            "<polyline{id} points=\"{}\" fill=\"none\" {style}/>",
            pts.join(" ")
        );
    }

    pub fn circle(&mut self, id: Option<&str>, (x, y): (f64, f64), r: f64, style: &str) {
        let id = id.map(|i| format!(" id=\"{i}\"")).unwrap_or_default();
        let _ = writeln!(
            self.body,
            "<circle{id} cx=\"{}\" cy=\"{}\" r=\"{}\" {style}/>",
            f(x),
            f(y),
            f(r)
        );
    }

    /// An ellipse with radii `rx`, `ry` along axes turned `angle` degrees (counterclockwise on
    /// screen).
    pub fn ellipse(
        &mut self,
        id: &str,
        (x, y): (f64, f64),
        (rx, ry): (f64, f64),
        angle: f64,
        style: &str,
    ) {
        let turn = if angle.abs() > 1e-9 {
            format!(" transform=\"rotate({} {} {})\"", f(-angle), f(x), f(y))
        } else {
            String::new()
        };
        let _ = writeln!(
            self.body,
            "<ellipse id=\"{id}\" cx=\"{}\" cy=\"{}\" rx=\"{}\" ry=\"{}\"{turn} fill=\"none\" {style}/>",
            f(x),
            f(y),
            f(rx),
            f(ry)
        );
    }

    pub fn text(&mut self, (x, y): (f64, f64), s: &str, style: &str) {
        let _ = writeln!(
            self.body,
            "<text x=\"{}\" y=\"{}\" {style}>{}</text>",
            f(x),
            f(y),
            esc(s)
        );
    }

    /// The grid and tick labels of the plot area `(left, top, width, height)`: a vertical line at
    /// each screen x of `across` and a horizontal one at each screen y of `up`, each labelled
    /// with its value.
    pub fn grid(
        &mut self,
        (left, top, width, height): (f64, f64, f64, f64),
        across: impl IntoIterator<Item = (f64, f64)>,
        up: impl IntoIterator<Item = (f64, f64)>,
    ) {
        let style = "stroke=\"#f3f4f6\"";
        for (x, value) in across {
            self.line(None, (x, top), (x, top + height), style);
            self.text(
                (x, top + height + 16.0),
                &short(value),
                "text-anchor=\"middle\" fill=\"#6b7280\" font-size=\"11\"",
            );
        }
        for (y, value) in up {
            self.line(None, (left, y), (left + width, y), style);
            self.text(
                (left - 6.0, y + 4.0),
                &short(value),
                "text-anchor=\"end\" fill=\"#6b7280\" font-size=\"11\"",
            );
        }
    }

    /// The document.
    /// A picture's title and its grey subtitle, at `left`.
    pub fn heading(&mut self, left: f64, title: &str, subtitle: &str) {
        self.text((left, 30.0), title, "font-size=\"17\" font-weight=\"600\"");
        self.text((left, 46.0), subtitle, "fill=\"#4b5563\" font-size=\"12\"");
    }

    /// The grey box of a plot area `(left, top, width, height)`.
    pub fn frame(&mut self, (left, top, w, h): (f64, f64, f64, f64)) {
        self.raw(&format!(
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#d1d5db\"/>",
            f(left),
            f(top),
            f(w),
            f(h)
        ));
    }

    /// A log time axis: a grid line and a label (`1e{d} ns`) at each decade `d` from `t0` to
    /// `t1`, at `x(10^d)`, under a plot area from `top` of height `h`.
    pub fn time_decades(
        &mut self,
        (t0, t1): (f64, f64),
        x: impl Fn(f64) -> f64,
        (top, h): (f64, f64),
    ) {
        for d in (t0 as i32)..=(t1 as i32) {
            let px = x(10f64.powi(d));
            self.line(None, (px, top), (px, top + h), "stroke=\"#f3f4f6\"");
            self.text(
                (px, top + h + 16.0),
                &format!("1e{d} ns"),
                "text-anchor=\"middle\" fill=\"#6b7280\" font-size=\"11\"",
            );
        }
    }

    pub fn finish(self, title: &str) -> String {
        let mut out = String::new();
        let attrs: String = self
            .attrs
            .iter()
            .map(|(k, v)| format!(" {k}=\"{}\"", esc(v)))
            .collect();
        let _ = writeln!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" \
             font-family=\"{FONTS}\" font-size=\"13\"{attrs}>",
            w = f(self.width),
            h = f(self.height)
        );
        let _ = writeln!(out, "<title>{}</title>", esc(title));
        let _ = writeln!(out, "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>");
        out.push_str(&self.body);
        out.push_str("</svg>\n");
        out
    }
}

/// A number for a label in a picture: 4 significant digits (the text and JSON outputs have
/// them all).
pub fn short(x: f64) -> String {
    let r: f64 = format!("{x:.3e}").parse().unwrap_or(x);
    crate::values::number::num(r)
}

/// "Nice" tick positions covering `[lo, hi]`: steps of 1, 2 or 5 times a power of ten.
pub fn ticks(lo: f64, hi: f64, about: usize) -> Vec<f64> {
    let span = hi - lo;
    if span.is_nan() || span <= 0.0 || !span.is_finite() {
        return vec![lo];
    }
    let raw = span / about.max(1) as f64;
    let p = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * p)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * p);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_round() {
        assert_eq!(ticks(0.0, 100.0, 5), [0.0, 20.0, 40.0, 60.0, 80.0, 100.0]);
        // Span 14 in about 5 steps: 2.8, rounded up to the nice step 5.
        assert_eq!(ticks(-7.0, 7.0, 5), [-5.0, 0.0, 5.0]);
        assert_eq!(ticks(-7.0, 7.0, 7), [-6.0, -4.0, -2.0, 0.0, 2.0, 4.0, 6.0]);
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(esc("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
        assert_eq!(f(-0.001), "0.00");
        assert_eq!(short(0.08333333333333334), "0.08333");
        assert_eq!(short(11.493055555555555), "11.49");
        assert_eq!(short(7250.0), "7250");
    }
}
