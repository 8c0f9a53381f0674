//! The picture of a rigid impact in the plane: on the left the bodies at the instant of impact
//! (rods and doors along y, round bodies as circles, boxes as rectangles, walls and floors as
//! hatched lines, pivots as small triangles), the contact point and the normal, each body's
//! velocity before (solid) and after (dashed) and its spin before and after; on the right the
//! impulse plane of Routh's method (normal impulse across, tangential up): the friction cone
//! `|P_t| = mu P_n`, the compression line (`w_n = 0`), the sticking line (`w_t = 0`) and the
//! path of the impulse with the end of compression (C), the stick (S) and the end (F).

use crate::rigid::algebra::dot;
use crate::rigid::body::Mobility;
use crate::rigid::laws::Tangential;
use crate::rigid::outcome::Outcome;
use crate::rigid::routh::Event;
use crate::rigid::shape::Kind;
use crate::values::rational::{Q, to_f64};

use super::plane::arrow;
use super::svg::{Svg, f, short};

const WIDTH: f64 = 880.0;
const HEIGHT: f64 = 500.0;
const SIDE: f64 = 380.0;
const TOP: f64 = 80.0;
const LEFTS: [f64; 2] = [40.0, 470.0];
const COLOURS: [&str; 2] = ["#2563eb", "#dc2626"];

fn x(q: &Q) -> f64 {
    to_f64(q).unwrap_or(0.0)
}

fn pt(v: &[Q]) -> (f64, f64) {
    (x(&v[0]), x(&v[1]))
}

/// A map from data to a square panel, one scale for both axes, y up.
#[derive(Clone, Copy, Debug)]
struct Map {
    left: f64,
    centre: (f64, f64),
    scale: f64,
}

impl Map {
    fn fit(left: f64, points: &[(f64, f64)]) -> Map {
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for (x, y) in points.iter().filter(|p| p.0.is_finite() && p.1.is_finite()) {
            x0 = x0.min(*x);
            x1 = x1.max(*x);
            y0 = y0.min(*y);
            y1 = y1.max(*y);
        }
        if x0 > x1 {
            (x0, x1, y0, y1) = (-1.0, 1.0, -1.0, 1.0);
        }
        let span = (x1 - x0).max(y1 - y0);
        let span = if span > 0.0 { span } else { 1.0 };
        Map {
            left,
            centre: ((x0 + x1) / 2.0, (y0 + y1) / 2.0),
            scale: SIDE * 0.8 / span,
        }
    }

    fn at(&self, (px, py): (f64, f64)) -> (f64, f64) {
        (
            self.left + SIDE / 2.0 + (px - self.centre.0) * self.scale,
            TOP + SIDE / 2.0 - (py - self.centre.1) * self.scale,
        )
    }

    /// The data box the panel shows.
    fn bounds(&self) -> (f64, f64, f64, f64) {
        let half = SIDE / 2.0 / self.scale;
        (
            self.centre.0 - half,
            self.centre.0 + half,
            self.centre.1 - half,
            self.centre.1 + half,
        )
    }
}

/// The SVG of a rigid impact (the impulse plane only in the plane).
pub fn svg(o: &Outcome) -> String {
    let mut svg = Svg::new(WIDTH, HEIGHT);
    let p = &o.problem;
    let sub = match &p.tangential {
        Tangential::Coulomb(mu) => format!(
            "e = {}, mu = {}, law {}; contact: {}",
            short(x(&p.e)),
            short(x(mu)),
            p.law.name(),
            o.impact.mode.name()
        ),
        Tangential::Rough { beta, .. } => format!(
            "e = {}, rough (beta = {}); contact: {}",
            short(x(&p.e)),
            short(x(beta)),
            o.impact.mode.name()
        ),
        Tangential::Smooth => format!("e = {}, no friction", short(x(&p.e))),
        Tangential::Join => "joined: e = 0, no slip".into(),
    };
    svg.heading(
        LEFTS[0],
        "Rigid impact",
        &format!("{sub}   (solid: before, dashed: after)"),
    );
    bodies(&mut svg, o);
    if o.dim() == 2 {
        impulse_plane(&mut svg, o);
    }
    svg.finish("collide: rigid impact")
}

/// The left panel.
fn bodies(svg: &mut Svg, o: &Outcome) {
    let c = pt(&o.problem.pair.contact.point);
    let n = pt(&o.problem.pair.contact.normal);
    let nl = n.0.hypot(n.1);
    let nh = (n.0 / nl, n.1 / nl);
    // The geometry's size: the bodies' extents and the distance between them.
    let mut size: f64 = 0.0;
    for b in o.bodies() {
        let q = pt(&b.position);
        size = size.max((q.0 - c.0).hypot(q.1 - c.1));
        if let Some(s) = &b.shape {
            size = size.max(x(&s.half_height())).max(x(&s.radius()));
        }
    }
    let size = if size > 0.0 { size } else { 1.0 };
    // Velocities to scale: the fastest arrow is 0.8 of the geometry's size.
    let speeds = o
        .v_in()
        .iter()
        .chain(&o.fin)
        .map(|m| {
            let v = pt(&m.v);
            v.0.hypot(v.1)
        })
        .fold(0.0f64, f64::max);
    let vscale = if speeds > 0.0 {
        0.8 * size / speeds
    } else {
        0.0
    };
    // The panel holds every body's outline, pivot and arrows, and the normal.
    let mut pts = vec![c, (c.0 + nh.0 * size * 0.5, c.1 + nh.1 * size * 0.5)];
    for (i, b) in o.bodies().iter().enumerate() {
        let q = pt(&b.position);
        let (hx, hy) = match &b.shape {
            Some(s) if s.kind == Kind::Rod => (0.0, x(&s.half_height())),
            Some(s) if s.kind == Kind::Box => (x(&s.sizes[0]) / 2.0, x(&s.sizes[1]) / 2.0),
            Some(s) => (x(&s.radius()), x(&s.radius())),
            None => (0.0, 0.0),
        };
        pts.extend([(q.0 - hx, q.1 - hy), (q.0 + hx, q.1 + hy)]);
        if let Some(pv) = b.pivot() {
            pts.push(pt(pv));
        }
        if b.immovable().is_none() {
            for m in [&o.v_in()[i], &o.fin[i]] {
                let v = pt(&m.v);
                pts.push((q.0 + v.0 * vscale, q.1 + v.1 * vscale));
            }
        }
    }
    let map = Map::fit(LEFTS[0], &pts);
    svg.frame((LEFTS[0], TOP, SIDE, SIDE));
    svg.text(
        (LEFTS[0], TOP - 10.0),
        "Bodies at the impact: velocities and spins",
        "font-size=\"12\" fill=\"#374151\"",
    );
    svg.raw(&format!(
        "<clipPath id=\"bodies-clip\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n<g clip-path=\"url(#bodies-clip)\">",
        f(LEFTS[0]),
        f(TOP),
        f(SIDE),
        f(SIDE)
    ));
    for (i, b) in o.bodies().iter().enumerate() {
        let colour = COLOURS[i];
        let centre = pt(&b.position);
        let style = format!("fill=\"{colour}\" fill-opacity=\"0.12\" stroke=\"{colour}\"");
        match (&b.mobility, &b.shape) {
            (Mobility::Immovable { word }, _) => {
                let t = (-nh.1, nh.0);
                let a = map.at((c.0 - t.0 * size * 2.0, c.1 - t.1 * size * 2.0));
                let z = map.at((c.0 + t.0 * size * 2.0, c.1 + t.1 * size * 2.0));
                svg.line(
                    Some(&format!("body-{}", i + 1)),
                    a,
                    z,
                    "stroke=\"#374151\" stroke-width=\"3\"",
                );
                let label = map.at((c.0 + nh.0 * size * 0.3, c.1 + nh.1 * size * 0.3));
                svg.text(label, word, "fill=\"#374151\" font-size=\"12\"");
            }
            (_, Some(s)) if s.kind == Kind::Rod => {
                let h = x(&s.half_height());
                svg.line(
                    Some(&format!("body-{}", i + 1)),
                    map.at((centre.0, centre.1 - h)),
                    map.at((centre.0, centre.1 + h)),
                    &format!("stroke=\"{colour}\" stroke-width=\"5\""),
                );
            }
            (_, Some(s)) if s.kind == Kind::Box => {
                let (w, h) = (x(&s.sizes[0]), x(&s.sizes[1]));
                let a = map.at((centre.0 - w / 2.0, centre.1 + h / 2.0));
                svg.raw(&format!(
                    "<rect id=\"body-{}\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" {style}/>",
                    i + 1,
                    f(a.0),
                    f(a.1),
                    f(w * map.scale),
                    f(h * map.scale)
                ));
            }
            (_, Some(s)) => {
                svg.circle(
                    Some(&format!("body-{}", i + 1)),
                    map.at(centre),
                    x(&s.radius()) * map.scale,
                    &style,
                );
            }
            (_, None) => {
                svg.circle(
                    Some(&format!("body-{}", i + 1)),
                    map.at(centre),
                    5.0,
                    &format!("fill=\"{colour}\""),
                );
            }
        }
        if let Some(pv) = b.pivot() {
            let q = map.at(pt(pv));
            svg.raw(&format!(
                "<polygon id=\"pivot-{}\" points=\"{},{} {},{} {},{}\" fill=\"#111827\"/>",
                i + 1,
                f(q.0),
                f(q.1),
                f(q.0 - 7.0),
                f(q.1 + 11.0),
                f(q.0 + 7.0),
                f(q.1 + 11.0)
            ));
        }
        if b.immovable().is_some() {
            continue;
        }
        let from = map.at(centre);
        for (k, m) in [&o.v_in()[i], &o.fin[i]].into_iter().enumerate() {
            let v = pt(&m.v);
            if v == (0.0, 0.0) {
                continue;
            }
            let to = map.at((centre.0 + v.0 * vscale, centre.1 + v.1 * vscale));
            arrow(
                svg,
                &format!("v{}{}", i + 1, if k == 0 { "" } else { "-fin" }),
                from,
                to,
                colour,
                k == 1,
            );
        }
        let w = |m: &crate::rigid::body::Motion| {
            m.omega
                .iter()
                .map(|q| short(x(q)))
                .collect::<Vec<_>>()
                .join(", ")
        };
        if b.inertia().is_some() || b.pivot().is_some() {
            svg.text(
                (from.0 - 8.0, from.1 - 10.0),
                &format!("ω{} = {} → {}", i + 1, w(&o.v_in()[i]), w(&o.fin[i])),
                &format!("text-anchor=\"end\" fill=\"{colour}\" font-size=\"11\""),
            );
        }
    }
    let cp = map.at(c);
    let tip = map.at((c.0 + nh.0 * size * 0.5, c.1 + nh.1 * size * 0.5));
    arrow(svg, "normal", cp, tip, "#6b7280", false);
    svg.text(
        (tip.0 + 4.0, tip.1 - 4.0),
        "n",
        "fill=\"#6b7280\" font-size=\"12\" font-style=\"italic\"",
    );
    svg.circle(Some("contact"), cp, 3.5, "fill=\"#111827\"");
    svg.raw("</g>");
    svg.attr("data-bodies-scale", f(map.scale));
}

/// Where the line `a x + b y = c` crosses the box `(x0, x1, y0, y1)`: its two ends.
fn clip(a: f64, b: f64, c: f64, (x0, x1, y0, y1): (f64, f64, f64, f64)) -> Option<[(f64, f64); 2]> {
    let mut ends = Vec::new();
    if b != 0.0 {
        for xx in [x0, x1] {
            let yy = (c - a * xx) / b;
            if (y0..=y1).contains(&yy) {
                ends.push((xx, yy));
            }
        }
    }
    if a != 0.0 {
        for yy in [y0, y1] {
            let xx = (c - b * yy) / a;
            if (x0..=x1).contains(&xx) {
                ends.push((xx, yy));
            }
        }
    }
    (ends.len() >= 2).then(|| [ends[0], ends[ends.len() - 1]])
}

/// The right panel: Routh's impulse plane.
fn impulse_plane(svg: &mut Svg, o: &Outcome) {
    let pair = &o.problem.pair;
    let n = &pair.contact.normal;
    let t = pair.tangent();
    let k = pair.collision_matrix();
    let kk = |a: &[Q], b: &[Q]| x(&dot(a, &crate::rigid::algebra::apply(&k, b)));
    let w = pair.relative_velocity(&o.problem.motions);
    let len = x(&dot(n, n)).sqrt();
    // In (P_n, P_t) = |n| (l_n, l_t): w~ = |n| (v_n, v_t) and K~ = |n|^2 K(unit), so the lines
    // K~ l = w~ read the same in P with K~/|n|.
    let (knn, knt, ktt) = (kk(n, n), kk(n, &t), kk(&t, &t));
    let (wn, wt) = (x(&dot(n, &w)), x(&dot(&t, &w)));
    let corners: Vec<((f64, f64), Event)> = match &o.impact.path {
        Some(path) => path
            .iter()
            .map(|c| ((x(&c.at[0]) * len, x(&c.at[1]) * len), c.event))
            .collect(),
        None => {
            let pn = x(&o.normal_impulse());
            let tt = o.tangential_impulse();
            let end = ((pn, x(&tt[0])), Event::End);
            match o.problem.tangential {
                Tangential::Rough { .. } | Tangential::Join => {
                    vec![((0.0, 0.0), Event::Start), end]
                }
                _ => vec![
                    ((0.0, 0.0), Event::Start),
                    ((x(&o.compression_impulse()), 0.0), Event::Compression),
                    end,
                ],
            }
        }
    };
    let mut pts: Vec<(f64, f64)> = corners.iter().map(|c| c.0).collect();
    pts.push((0.0, 0.0));
    let last = corners.last().map_or((1.0, 0.0), |c| c.0);
    let reach = last.0.abs().max(last.1.abs()).max(1e-300);
    pts.push((reach * 1.1, reach * 0.3));
    pts.push((0.0, -reach * 0.3));
    let map = Map::fit(LEFTS[1], &pts);
    svg.frame((LEFTS[1], TOP, SIDE, SIDE));
    svg.text(
        (LEFTS[1], TOP - 10.0),
        "Impulse plane (Routh): normal P_n across, tangential P_t up",
        "font-size=\"12\" fill=\"#374151\"",
    );
    let bounds = map.bounds();
    let (x0, x1, y0, y1) = bounds;
    svg.line(
        Some("axis-n"),
        map.at((x0, 0.0)),
        map.at((x1, 0.0)),
        "stroke=\"#9ca3af\"",
    );
    if (x0..=x1).contains(&0.0) {
        svg.line(
            Some("axis-t"),
            map.at((0.0, y0)),
            map.at((0.0, y1)),
            "stroke=\"#9ca3af\"",
        );
    }
    let mut line = |id: &str, a: f64, b: f64, c: f64, colour: &str, label: &str| {
        if let Some([p, q]) = clip(a, b, c, bounds) {
            svg.line(
                Some(id),
                map.at(p),
                map.at(q),
                &format!("stroke=\"{colour}\" stroke-dasharray=\"5 4\""),
            );
            let at = map.at(q);
            svg.text(
                (
                    at.0 - 4.0,
                    at.1 + if at.1 < TOP + 20.0 { 14.0 } else { -4.0 },
                ),
                label,
                &format!("text-anchor=\"end\" fill=\"{colour}\" font-size=\"11\""),
            );
        }
    };
    // w~ - K~ l = 0 in P = |n| l: K~ P / |n| = w~.
    line(
        "compression-line",
        knn / len,
        knt / len,
        wn,
        "#059669",
        "w_n = 0",
    );
    if !matches!(o.problem.tangential, Tangential::Smooth) {
        line(
            "sticking-line",
            knt / len,
            ktt / len,
            wt,
            "#7c3aed",
            "w_t = 0",
        );
    }
    if let Tangential::Coulomb(mu) = &o.problem.tangential {
        let m = x(mu);
        line("cone-up", m, -1.0, 0.0, "#9ca3af", "P_t = mu P_n");
        line("cone-down", m, 1.0, 0.0, "#9ca3af", "P_t = -mu P_n");
    }
    let screen: Vec<(f64, f64)> = corners.iter().map(|c| map.at(c.0)).collect();
    svg.polyline(
        Some("impulse-path"),
        &screen,
        "stroke=\"#111827\" stroke-width=\"2.2\"",
    );
    for ((p, event), s) in corners.iter().zip(&screen) {
        let label = match event {
            Event::Start => continue,
            Event::Compression => "C",
            Event::Stick => "S",
            Event::End => "F",
        };
        svg.circle(None, *s, 3.5, "fill=\"#111827\"");
        let below = if *event == Event::End { 18.0 } else { -6.0 };
        svg.text(
            (s.0 + 6.0, s.1 + below),
            &format!("{label} ({}, {})", short(p.0), short(p.1)),
            "font-size=\"11\"",
        );
    }
    svg.attr("data-impulse-scale", f(map.scale));
}
