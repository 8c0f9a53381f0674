//! Space-time diagrams of the two world lines, meeting at the collision event (x = 0, t = 0):
//! Newton's (time across, position up) and Minkowski's (time up, position across). Before the
//! event body i moves at V_i^IN, after it at V_i^FIN.

use super::Picture;
use super::svg::{Svg, f, short as num, ticks};

const WIDTH: f64 = 720.0;
const HEIGHT: f64 = 560.0;
const LEFT: f64 = 80.0;
const TOP: f64 = 70.0;
const W: f64 = 560.0;
const H: f64 = 420.0;

/// The diagram; `minkowski` puts time up and position across.
pub fn svg(p: &Picture, minkowski: bool) -> String {
    // One unit of time each side of the event.
    let v = [p.v_in.0, p.v_in.1, p.v_fin.0, p.v_fin.1];
    // No motion at all: a unit range.
    let fastest = v.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let reach = if fastest > 0.0 { fastest * 1.1 } else { 1.0 };
    let (t_range, x_range) = ((-1.1, 1.1), (-reach, reach));
    // Screen axes: across and up.
    let (across, up) = if minkowski {
        (x_range, t_range)
    } else {
        (t_range, x_range)
    };
    let sx = W / (across.1 - across.0);
    let sy = H / (up.1 - up.0);
    let at = |t: f64, x: f64| {
        let (a, u) = if minkowski { (x, t) } else { (t, x) };
        (LEFT + (a - across.0) * sx, TOP + (up.1 - u) * sy)
    };
    let mut svg = Svg::new(WIDTH, HEIGHT);
    let name = if minkowski {
        "Minkowski diagram (time up)"
    } else {
        "Newton diagram (position against time)"
    };
    svg.text((LEFT, 30.0), name, "font-size=\"17\" font-weight=\"600\"");
    svg.text((LEFT, 50.0), &p.title, "fill=\"#4b5563\"");
    svg.raw(&format!("<rect x=\"{LEFT}\" y=\"{TOP}\" width=\"{W}\" height=\"{H}\" fill=\"none\" stroke=\"#d1d5db\"/>"));
    let (t_label, x_label) = ("t", "x");
    let (a_label, u_label) = if minkowski {
        (x_label, t_label)
    } else {
        (t_label, x_label)
    };
    svg.grid(
        (LEFT, TOP, W, H),
        ticks(across.0, across.1, 6)
            .into_iter()
            .map(|t| (LEFT + (t - across.0) * sx, t)),
        ticks(up.0, up.1, 6)
            .into_iter()
            .map(|t| (TOP + (up.1 - t) * sy, t)),
    );
    svg.text(
        (LEFT + W / 2.0, TOP + H + 36.0),
        a_label,
        "text-anchor=\"middle\" font-weight=\"600\" font-style=\"italic\"",
    );
    svg.text(
        (LEFT - 50.0, TOP + H / 2.0),
        u_label,
        "font-weight=\"600\" font-style=\"italic\"",
    );
    let colours = ["#2563eb", "#dc2626"];
    for (i, colour) in colours.iter().enumerate() {
        let (vin, vfin) = if i == 0 {
            (p.v_in.0, p.v_fin.0)
        } else {
            (p.v_in.1, p.v_fin.1)
        };
        let pts = [at(-1.0, -vin), at(0.0, 0.0), at(1.0, vfin)];
        let style = format!("stroke=\"{}\" stroke-width=\"2\"", colour);
        svg.polyline(Some(&format!("world-line-{}", i + 1)), &pts, &style);
        // Labels at the two ends, anchored toward the middle so they stay inside.
        let anchor = |x: f64| {
            if x > LEFT + W / 2.0 {
                ("end", -6.0)
            } else {
                ("start", 6.0)
            }
        };
        let (x, y) = pts[0];
        let (a, dx) = anchor(x);
        svg.text(
            (x + dx, y - 6.0),
            &format!(
                "body {} (M{} = {}) at V{} = {}",
                i + 1,
                i + 1,
                num(p.masses[i]),
                i + 1,
                num(vin)
            ),
            &format!("text-anchor=\"{a}\" fill=\"{}\" font-size=\"12\"", colour),
        );
        let (x, y) = pts[2];
        let (a, dx) = anchor(x);
        svg.text(
            (x + dx, y + 16.0),
            &format!("then V{} = {}", i + 1, num(vfin)),
            &format!("text-anchor=\"{a}\" fill=\"{}\" font-size=\"12\"", colour),
        );
    }
    let (x, y) = at(0.0, 0.0);
    svg.circle(Some("event"), (x, y), 5.0, "fill=\"#1f2937\"");
    svg.text((x + 8.0, y + 18.0), "collision", "font-weight=\"600\"");
    svg.attr("data-event", format!("{},{}", f(x), f(y)));
    svg.finish(&format!("{name}: {}", p.title))
}
