//! The velocity-velocity diagram (lecture Figs. 1.3, 2.3, 2.5): the (V1, V2) plane drawn to equal
//! scales, so 45 degrees looks like 45 degrees and an ellipse's radii can be read off.

use super::svg::{Svg, f, short as num, ticks};
use super::{EllipseShape, Picture};

const WIDTH: f64 = 820.0;
const HEIGHT: f64 = 580.0;
/// The square plot area.
const LEFT: f64 = 70.0;
const TOP: f64 = 60.0;
const SIDE: f64 = 460.0;

/// The data-to-screen map: `X = ox + s x`, `Y = oy - s y`.
#[derive(Clone, Copy, Debug)]
pub struct Map {
    pub ox: f64,
    pub oy: f64,
    pub s: f64,
    /// The data box.
    pub x: (f64, f64),
    pub y: (f64, f64),
}

impl Map {
    pub fn at(&self, (x, y): (f64, f64)) -> (f64, f64) {
        (self.ox + self.s * x, self.oy - self.s * y)
    }

    /// A square data box around everything the picture shows (origin included), with a margin,
    /// drawn as the square of `side` at screen `(left, top)`.
    pub fn fit(p: &Picture, (left, top): (f64, f64), side: f64) -> Map {
        let mut pts = vec![(0.0, 0.0), p.v_in, p.v_com, p.v_fin];
        for e in p.ellipses() {
            let (hx, hy) = e.extent();
            pts.extend([(hx, hy), (-hx, -hy)]);
        }
        for (_, i, c, fin) in &p.others {
            pts.extend([*i, *c, *fin]);
        }
        let (mut x0, mut x1, mut y0, mut y1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for (x, y) in pts
            .into_iter()
            .filter(|(x, y)| x.is_finite() && y.is_finite())
        {
            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
        }
        // Everything at the origin (no motion at all): a unit box.
        let span = (x1 - x0).max(y1 - y0);
        let span = if span > 0.0 && span.is_finite() {
            span * 1.12
        } else {
            2.0
        };
        let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
        let x = (cx - span / 2.0, cx + span / 2.0);
        let y = (cy - span / 2.0, cy + span / 2.0);
        let s = side / span;
        Map {
            ox: left - s * x.0,
            oy: top + s * y.1,
            s,
            x,
            y,
        }
    }

    /// Whether the map can be drawn (the data range fits binary64).
    pub fn is_finite(&self) -> bool {
        [
            self.ox, self.oy, self.s, self.x.0, self.x.1, self.y.0, self.y.1,
        ]
        .iter()
        .all(|v| v.is_finite())
            && self.s > 0.0
    }

    /// The part of the line `k1 x + k2 y = c` inside the data box.
    pub fn clip(&self, (k1, k2, c): (f64, f64, f64)) -> Option<((f64, f64), (f64, f64))> {
        let mut hits = Vec::new();
        let inside =
            |v: f64, (lo, hi): (f64, f64)| v >= lo - 1e-9 * (hi - lo) && v <= hi + 1e-9 * (hi - lo);
        if k2 != 0.0 {
            for x in [self.x.0, self.x.1] {
                let y = (c - k1 * x) / k2;
                if inside(y, self.y) {
                    hits.push((x, y));
                }
            }
        }
        if k1 != 0.0 {
            for y in [self.y.0, self.y.1] {
                let x = (c - k2 * y) / k1;
                if inside(x, self.x) {
                    hits.push((x, y));
                }
            }
        }
        hits.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        hits.dedup();
        (hits.len() >= 2).then(|| (hits[0], hits[hits.len() - 1]))
    }
}

const INK: &str = "#1f2937";
const MOMENTUM: &str = "#2563eb";
const ENERGY_IN: &str = "#dc2626";
const ENERGY_COM: &str = "#059669";
const ENERGY_FIN: &str = "#d97706";

fn ellipse(svg: &mut Svg, map: &Map, id: &str, e: &EllipseShape, style: &str) {
    let (a, b) = e.radii;
    let angle = e.axes[0].1.atan2(e.axes[0].0).to_degrees();
    svg.ellipse(id, map.at((0.0, 0.0)), (a * map.s, b * map.s), angle, style);
}

/// The diagram as SVG.
pub fn svg(p: &Picture) -> String {
    let map = Map::fit(p, (LEFT, TOP), SIDE);
    let mut svg = Svg::new(WIDTH, HEIGHT);
    svg.attr("data-origin-x", f(map.ox));
    svg.attr("data-origin-y", f(map.oy));
    svg.attr("data-scale", format!("{:e}", map.s));
    svg.text(
        (LEFT, 28.0),
        "Velocity plane (V1, V2)",
        "font-size=\"17\" font-weight=\"600\"",
    );
    svg.text((LEFT, 47.0), &p.title, "fill=\"#4b5563\"");
    svg.raw(&format!("<defs><clipPath id=\"area\"><rect x=\"{LEFT}\" y=\"{TOP}\" width=\"{SIDE}\" height=\"{SIDE}\"/></clipPath></defs>"));
    svg.raw(&format!(
        "<rect x=\"{LEFT}\" y=\"{TOP}\" width=\"{SIDE}\" height=\"{SIDE}\" fill=\"none\" stroke=\"#d1d5db\"/>"
    ));
    svg.grid(
        (LEFT, TOP, SIDE, SIDE),
        ticks(map.x.0, map.x.1, 6)
            .into_iter()
            .map(|t| (map.at((t, 0.0)).0, t)),
        ticks(map.y.0, map.y.1, 6)
            .into_iter()
            .map(|t| (map.at((0.0, t)).1, t)),
    );
    svg.text(
        (LEFT + SIDE / 2.0, TOP + SIDE + 36.0),
        "V1",
        "text-anchor=\"middle\" font-weight=\"600\"",
    );
    svg.text((LEFT - 48.0, TOP + SIDE / 2.0), "V2", "font-weight=\"600\"");
    svg.raw("<g clip-path=\"url(#area)\">");
    // Axes through the origin, and the 45-degree line V1 = V2.
    svg.line(
        None,
        map.at((map.x.0, 0.0)),
        map.at((map.x.1, 0.0)),
        "stroke=\"#9ca3af\"",
    );
    svg.line(
        None,
        map.at((0.0, map.y.0)),
        map.at((0.0, map.y.1)),
        "stroke=\"#9ca3af\"",
    );
    let lo = map.x.0.max(map.y.0);
    let hi = map.x.1.min(map.y.1);
    svg.line(
        Some("diagonal"),
        map.at((lo, lo)),
        map.at((hi, hi)),
        "stroke=\"#6b7280\" stroke-dasharray=\"6 4\"",
    );
    // Energy ellipses.
    ellipse(
        &mut svg,
        &map,
        "ellipse-in",
        &p.ellipse_in,
        &format!("stroke=\"{ENERGY_IN}\" stroke-width=\"1.6\""),
    );
    ellipse(
        &mut svg,
        &map,
        "ellipse-com",
        &p.ellipse_com,
        &format!("stroke=\"{ENERGY_COM}\" stroke-width=\"1.6\""),
    );
    if let Some(e) = &p.ellipse_fin {
        ellipse(
            &mut svg,
            &map,
            "ellipse-fin",
            e,
            &format!("stroke=\"{ENERGY_FIN}\" stroke-width=\"1.6\" stroke-dasharray=\"5 3\""),
        );
    }
    // The momentum line through IN, COM and FIN.
    if let Some((a, b)) = map.clip(p.line) {
        svg.line(
            Some("momentum-line"),
            map.at(a),
            map.at(b),
            &format!("stroke=\"{MOMENTUM}\" stroke-width=\"1.8\""),
        );
    }
    // Other frames (Fig. 2.5): the same collision shifted along the diagonal.
    for (i, (name, vi, vc, vf)) in p.others.iter().enumerate() {
        let id = format!("frame-{i}");
        svg.line(
            Some(&id),
            map.at(*vi),
            map.at(*vf),
            "stroke=\"#a78bfa\" stroke-width=\"1.2\"",
        );
        for v in [vi, vc, vf] {
            svg.circle(None, map.at(*v), 3.0, "fill=\"#a78bfa\"");
        }
        // A number beside the frame's COM, across the segment (its name is in the legend): names
        // written on the picture overlapped each other and the lines.
        let (a, b) = (map.at(*vi), map.at(*vf));
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let len = dx.hypot(dy).max(1e-9);
        let (x, y) = map.at(*vc);
        svg.text(
            (x + 12.0 * dy / len - 3.0, y - 12.0 * dx / len + 4.0),
            &(i + 1).to_string(),
            "fill=\"#7c3aed\" font-size=\"11\" font-weight=\"600\"",
        );
        let _ = name;
    }
    svg.raw("</g>");
    let stuck = p.e == 0.0;
    let points: Vec<(&str, &str, (f64, f64))> = if stuck {
        vec![("in", "IN", p.v_in), ("com", "COM = FIN", p.v_com)]
    } else {
        vec![
            ("in", "IN", p.v_in),
            ("com", "COM", p.v_com),
            ("fin", "FIN", p.v_fin),
        ]
    };
    for (id, name, v) in points {
        let (x, y) = map.at(v);
        svg.circle(
            Some(&format!("point-{id}")),
            (x, y),
            5.0,
            &format!("fill=\"{INK}\" stroke=\"white\" stroke-width=\"1.5\""),
        );
        svg.text(
            (x + 8.0, y - 8.0),
            &format!("{name} ({}, {})", num(v.0), num(v.1)),
            "font-weight=\"600\"",
        );
    }
    // Legend.
    let lx = LEFT + SIDE + 24.0;
    let mut ly = TOP + 10.0;
    let mut entry = |svg: &mut Svg, style: &str, label: String| {
        svg.line(None, (lx, ly), (lx + 26.0, ly), style);
        svg.text((lx + 34.0, ly + 4.0), &label, "font-size=\"12\"");
        ly += 22.0;
    };
    let (k1, k2, c) = p.line;
    entry(
        &mut svg,
        &format!("stroke=\"{MOMENTUM}\" stroke-width=\"1.8\""),
        format!("momentum {} V1 + {} V2 = {}", num(k1), num(k2), num(c)),
    );
    entry(
        &mut svg,
        "stroke=\"#6b7280\" stroke-dasharray=\"6 4\"",
        "V1 = V2 (45 degrees)".into(),
    );
    let fin_too = if p.e == 1.0 { " = FIN" } else { "" };
    entry(
        &mut svg,
        &format!("stroke=\"{ENERGY_IN}\" stroke-width=\"1.6\""),
        format!("IN{fin_too} ellipse, KE {}", num(p.ellipse_in.ke)),
    );
    if let Some(e) = &p.ellipse_fin {
        entry(
            &mut svg,
            &format!("stroke=\"{ENERGY_FIN}\" stroke-width=\"1.6\" stroke-dasharray=\"5 3\""),
            format!("FIN ellipse, KE {}", num(e.ke)),
        );
    }
    let com_fin = if stuck { " = FIN" } else { "" };
    entry(
        &mut svg,
        &format!("stroke=\"{ENERGY_COM}\" stroke-width=\"1.6\""),
        format!("COM{com_fin} ellipse, KE {}", num(p.ellipse_com.ke)),
    );
    if !p.others.is_empty() {
        entry(
            &mut svg,
            "stroke=\"#a78bfa\"",
            "other frames (shifted by -w):".into(),
        );
        for (i, (name, ..)) in p.others.iter().enumerate() {
            svg.text(
                (lx + 34.0, ly + 4.0 - 6.0),
                &format!("{}  {name}", i + 1),
                "font-size=\"12\" fill=\"#7c3aed\"",
            );
            ly += 18.0;
        }
    }
    svg.finish(&format!("Velocity plane: {}", p.title))
}
