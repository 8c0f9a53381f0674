//! The picture of a collision in the plane: the bodies' paths through the point of impact
//! (each comes in along its velocity and leaves along its final one, the line of impact dashed
//! through it), and the momentum triangles `p1 + p2 = P = p1' + p2'` (Axiom 1 as vectors).
//!
//! For two bodies in the plane with a line of impact, a third panel below is the lecture's own
//! diagram of the normal parts, `(v1.n, v2.n)` with `n` a unit vector: the tangential parts pass
//! unchanged, so along `n` the bodies collide as on a rail (physics.md section 7), and that rail's
//! velocity plane (`plot::velocity`, lecture Figs. 1.3, 2.3) is drawn from the same masses and e.
//!
//! Each panel is scaled to its own data and keeps angles: one scale for both axes, so a
//! velocity at 30 degrees is drawn at 30 degrees.

use crate::space::outcome::Outcome;

use super::svg::{Svg, f, short};

const WIDTH: f64 = 860.0;
const HEIGHT: f64 = 480.0;
const SIDE: f64 = 360.0;
const TOP: f64 = 80.0;
/// Left edges of the two panels.
const LEFTS: [f64; 2] = [50.0, 460.0];
/// The size of the normal parts' velocity plane (`plot::velocity`'s page).
const RAIL_WIDTH: f64 = super::velocity::WIDTH;
const RAIL_HEIGHT: f64 = super::velocity::HEIGHT;
/// Colours of bodies 1, 2, 3...: before solid, after dashed.
const COLOURS: [&str; 4] = ["#2563eb", "#dc2626", "#059669", "#7c3aed"];

/// A panel's map from data to screen: centre and scale (pixels per unit), y up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Panel {
    pub left: f64,
    pub centre: (f64, f64),
    pub scale: f64,
}

impl Panel {
    /// Fits the points (with the origin) into a square panel, one scale for both axes.
    fn fit(left: f64, points: &[(f64, f64)]) -> Panel {
        let (mut x0, mut x1, mut y0, mut y1) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for (x, y) in points {
            x0 = x0.min(*x);
            x1 = x1.max(*x);
            y0 = y0.min(*y);
            y1 = y1.max(*y);
        }
        let span = (x1 - x0).max(y1 - y0);
        let span = if span > 0.0 && span.is_finite() {
            span
        } else {
            1.0
        };
        Panel {
            left,
            centre: ((x0 + x1) / 2.0, (y0 + y1) / 2.0),
            scale: SIDE * 0.86 / span,
        }
    }

    /// Screen position of a data point.
    pub fn at(&self, (x, y): (f64, f64)) -> (f64, f64) {
        (
            self.left + SIDE / 2.0 + (x - self.centre.0) * self.scale,
            TOP + SIDE / 2.0 - (y - self.centre.1) * self.scale,
        )
    }
}

fn point(v: &[crate::values::rational::Q]) -> (f64, f64) {
    let g = |k: usize| {
        v.get(k)
            .and_then(crate::values::rational::to_f64)
            .unwrap_or(0.0)
    };
    (g(0), g(1))
}

/// The velocity plane of the normal parts (two bodies in the plane with a line of impact): the
/// masses, the velocities' components along the unit normal and the same e, as a 1D case. `None`
/// where there is no such rail or a value does not fit binary64.
fn normal_parts(o: &Outcome) -> Option<super::Picture> {
    use crate::line::case::Case;
    use crate::line::inertia::{InertiaTensor, Mass};
    use crate::line::restitution::Restitution;
    use crate::values::number::Number;
    if o.dim != 2 {
        return None;
    }
    let parts = o.normal_parts()?;
    let q = |x: &crate::values::rational::Q| {
        crate::values::rational::to_f64(x).filter(|v| v.is_finite())
    };
    let mass = |i: usize| Mass::from_f64(q(&o.masses[i])?).ok();
    let speed = |x: &crate::values::rational::Q| Number::from_f64(q(x)?).ok();
    let inertia = InertiaTensor::diagonal(&mass(0)?, &mass(1)?).ok()?;
    let e = Restitution::new(Number::from_f64(q(o.e.as_ref()?)?).ok()?).ok()?;
    let case = Case::new(inertia, [speed(&parts.v_in[0])?, speed(&parts.v_in[1])?], e);
    Some(super::Picture::new(
        &case,
        &crate::line::frame::Frame::Lab,
        false,
    ))
}

/// Places a whole SVG document `inner` (from [`Svg::finish`]) at `(x, y)` of `svg`, as a nested
/// `svg` element of its own size and viewBox, with the given id.
fn nest(svg: &mut Svg, id: &str, (x, y): (f64, f64), inner: &str) {
    let (head, body) = inner.split_once('>').unwrap_or(("", inner));
    let body = body.trim_end().trim_end_matches("</svg>");
    // The inner root's data-to-screen map (`data-*`) stays on the nested element.
    let data: String = head
        .split(" data-")
        .skip(1)
        .map(|a| format!(" data-{}", a.trim_end()))
        .collect();
    svg.raw(&format!(
        "<svg id=\"{id}\" x=\"{}\" y=\"{}\" width=\"{RAIL_WIDTH}\" height=\"{RAIL_HEIGHT}\" \
         viewBox=\"0 0 {RAIL_WIDTH} {RAIL_HEIGHT}\"{data}>{body}</svg>",
        f(x),
        f(y)
    ));
    svg.text(
        (x + 30.0, y - 8.0),
        "Along the line of impact: the normal parts (v1.n, v2.n), |n| = 1, collide as on a rail",
        "font-size=\"12\" fill=\"#374151\"",
    );
}

/// An arrow from `a` to `b` (screen), with a head, in `colour`.
pub fn arrow(svg: &mut Svg, id: &str, a: (f64, f64), b: (f64, f64), colour: &str, dashed: bool) {
    let dash = if dashed {
        " stroke-dasharray=\"6 4\""
    } else {
        ""
    };
    svg.line(
        Some(id),
        a,
        b,
        &format!("stroke=\"{colour}\" stroke-width=\"2.2\"{dash}"),
    );
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len = dx.hypot(dy);
    if len < 1.0 {
        return;
    }
    let (ux, uy) = (dx / len, dy / len);
    let size = 9.0f64.min(len / 2.0);
    let left = (
        b.0 - size * ux - size * 0.5 * uy,
        b.1 - size * uy + size * 0.5 * ux,
    );
    let right = (
        b.0 - size * ux + size * 0.5 * uy,
        b.1 - size * uy - size * 0.5 * ux,
    );
    svg.raw(&format!(
        "<polygon points=\"{},{} {},{} {},{}\" fill=\"{colour}\"/>",
        f(b.0),
        f(b.1),
        f(left.0),
        f(left.1),
        f(right.0),
        f(right.1)
    ));
}

/// The SVG of a planar outcome.
pub fn svg(o: &Outcome, title: &str) -> String {
    let n = o.bodies();
    let v_in: Vec<(f64, f64)> = o.v_in.iter().map(|v| point(v)).collect();
    let fin: Vec<(f64, f64)> = o.fin.iter().map(|v| point(v)).collect();
    let p_in: Vec<Vec<crate::values::rational::Q>> = o
        .v_in
        .iter()
        .zip(&o.masses)
        .map(|(v, m)| v.iter().map(|x| x * m).collect())
        .collect();
    let p_fin: Vec<Vec<crate::values::rational::Q>> = o
        .fin
        .iter()
        .zip(&o.masses)
        .map(|(v, m)| v.iter().map(|x| x * m).collect())
        .collect();
    let rail = normal_parts(o).map(|p| super::velocity::svg(&p));
    let height = HEIGHT
        + if rail.is_some() {
            RAIL_HEIGHT + 20.0
        } else {
            0.0
        };
    let mut svg = Svg::new(WIDTH, height);
    svg.heading(
        LEFTS[0],
        "Collision in the plane",
        &format!("{title}   (solid: before, dashed: after)"),
    );

    // Paths through the point of impact: in along -v (to the origin), out along v'.
    let mut path_points: Vec<(f64, f64)> = v_in.iter().map(|(x, y)| (-x, -y)).collect();
    path_points.extend(&fin);
    let paths = Panel::fit(LEFTS[0], &path_points);
    svg.frame((LEFTS[0], TOP, SIDE, SIDE));
    svg.text(
        (LEFTS[0], TOP - 10.0),
        "Paths through the point of impact (1 time unit each)",
        "font-size=\"12\" fill=\"#374151\"",
    );
    let origin = paths.at((0.0, 0.0));
    if let Some(nrm) = &o.normal {
        let (nx, ny) = point(nrm);
        let len = nx.hypot(ny);
        if len > 0.0 {
            let reach = SIDE / 2.0 / paths.scale;
            let (ux, uy) = (nx / len * reach, ny / len * reach);
            svg.line(
                Some("line-of-impact"),
                paths.at((-ux, -uy)),
                paths.at((ux, uy)),
                "stroke=\"#9ca3af\" stroke-width=\"1.2\" stroke-dasharray=\"2 4\"",
            );
            let tip = paths.at((ux * 0.92, uy * 0.92));
            svg.text(
                (tip.0 + 4.0, tip.1 - 4.0),
                "n",
                "fill=\"#6b7280\" font-size=\"12\" font-style=\"italic\"",
            );
        }
    }
    for i in 0..n {
        let colour = COLOURS[i % COLOURS.len()];
        let from = paths.at((-v_in[i].0, -v_in[i].1));
        if v_in[i] != (0.0, 0.0) {
            arrow(
                &mut svg,
                &format!("path-in-{}", i + 1),
                from,
                origin,
                colour,
                false,
            );
            svg.text(
                (from.0 + 4.0, from.1 - 6.0),
                &format!("v{} = ({}, {})", i + 1, short(v_in[i].0), short(v_in[i].1)),
                &format!("fill=\"{colour}\" font-size=\"11\""),
            );
        }
        if fin[i] != (0.0, 0.0) {
            let to = paths.at(fin[i]);
            arrow(
                &mut svg,
                &format!("path-fin-{}", i + 1),
                origin,
                to,
                colour,
                true,
            );
            svg.text(
                (to.0 + 4.0, to.1 + 14.0),
                &format!("v{}' = ({}, {})", i + 1, short(fin[i].0), short(fin[i].1)),
                &format!("fill=\"{colour}\" font-size=\"11\""),
            );
        }
    }
    svg.circle(Some("impact"), origin, 3.5, "fill=\"#111827\"");

    // Momentum triangles: p1, p2, ... tip to tail, before and after, to the same P.
    let tips = |ps: &[Vec<crate::values::rational::Q>]| -> Vec<(f64, f64)> {
        let mut acc = (0.0, 0.0);
        let mut out = vec![acc];
        for p in ps {
            let (x, y) = point(p);
            acc = (acc.0 + x, acc.1 + y);
            out.push(acc);
        }
        out
    };
    let before = tips(&p_in);
    let after = tips(&p_fin);
    let mut all = before.clone();
    all.extend(&after);
    let mom = Panel::fit(LEFTS[1], &all);
    svg.frame((LEFTS[1], TOP, SIDE, SIDE));
    svg.text(
        (LEFTS[1], TOP - 10.0),
        "Momentum: p1 + p2 = P = p1' + p2'",
        "font-size=\"12\" fill=\"#374151\"",
    );
    for (k, (pts, dashed)) in [(&before, false), (&after, true)].into_iter().enumerate() {
        for i in 0..n {
            let colour = COLOURS[i % COLOURS.len()];
            let id = format!("p{}{}", i + 1, if k == 0 { "" } else { "-fin" });
            arrow(
                &mut svg,
                &id,
                mom.at(pts[i]),
                mom.at(pts[i + 1]),
                colour,
                dashed,
            );
        }
    }
    let total = *before.last().unwrap_or(&(0.0, 0.0));
    arrow(
        &mut svg,
        "p-total",
        mom.at((0.0, 0.0)),
        mom.at(total),
        "#111827",
        false,
    );
    let tip = mom.at(total);
    svg.text(
        (tip.0 + 6.0, tip.1 - 6.0),
        &format!("P = ({}, {})", short(total.0), short(total.1)),
        "font-size=\"11\" fill=\"#111827\"",
    );
    // Legend: each body's colour and mass.
    let mut x = LEFTS[0];
    for i in 0..n {
        let colour = COLOURS[i % COLOURS.len()];
        let m = crate::values::rational::to_f64(&o.masses[i]).unwrap_or(f64::NAN);
        svg.raw(&format!(
            "<rect x=\"{}\" y=\"{}\" width=\"10\" height=\"10\" fill=\"{colour}\"/>",
            f(x),
            f(TOP + SIDE + 20.0)
        ));
        let label = format!("body {}, m = {}", i + 1, short(m));
        svg.text((x + 14.0, TOP + SIDE + 29.0), &label, "font-size=\"12\"");
        x += 24.0 + 7.0 * label.len() as f64;
    }
    if let Some(inner) = rail {
        nest(
            &mut svg,
            "normal-parts",
            (LEFTS[0] - 30.0, HEIGHT + 20.0),
            &inner,
        );
    }
    svg.attr("data-paths-scale", f(paths.scale));
    svg.attr("data-momentum-scale", f(mom.scale));
    svg.finish(&format!("collide: {title}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::values::rational::int;

    #[test]
    fn arrows_keep_their_angles_and_stay_inside() {
        let v = |xs: &[i64]| xs.iter().map(|x| int(*x)).collect::<Vec<_>>();
        let o = Outcome {
            dim: 2,
            masses: v(&[1, 1]),
            v_in: vec![v(&[4, 0]), v(&[0, 0])],
            fin: vec![v(&[2, -2]), v(&[2, 2])],
            normal: Some(v(&[1, 1])),
            e: Some(int(1)),
            approx: crate::space::outcome::Marks::default(),
        };
        let s = svg(&o, "test");
        let doc = roxmltree_free_parse(&s);
        // v2' = (2, 2) leaves the origin at 45 degrees (screen y down).
        let (x1, y1, x2, y2) = doc["path-fin-2"];
        assert!(((y1 - y2) / (x2 - x1) - 1.0).abs() < 0.02);
        for (x1, y1, x2, y2) in doc.values() {
            for (x, y) in [(x1, y1), (x2, y2)] {
                assert!((0.0..=WIDTH).contains(x) && (0.0..=HEIGHT).contains(y));
            }
        }
    }

    /// The `line` elements by id of the two top panels (the normal parts' panel below has its
    /// own coordinates): a parse of this writer's own fixed format.
    fn roxmltree_free_parse(s: &str) -> std::collections::HashMap<String, (f64, f64, f64, f64)> {
        let s = s.split("<svg id=\"normal-parts\"").next().unwrap_or(s);
        let attr = |l: &str, k: &str| -> f64 {
            let i = l.find(&format!(" {k}=\"")).unwrap() + k.len() + 3;
            l[i..].split('"').next().unwrap().parse().unwrap()
        };
        s.lines()
            .filter(|l| l.starts_with("<line id="))
            .map(|l| {
                let id = l[10..].split('"').next().unwrap().to_string();
                (
                    id,
                    (attr(l, "x1"), attr(l, "y1"), attr(l, "x2"), attr(l, "y2")),
                )
            })
            .collect()
    }
}
