//! The velocity diagram in the terminal, drawn with Unicode braille (2 x 4 dots a character, so
//! dots are square on a usual 1:2 character cell and 45 degrees looks like 45 degrees).

use super::Picture;
use super::velocity::Map;
use crate::values::number::num;

/// A braille canvas of `cols` x `rows` characters.
struct Canvas {
    cols: usize,
    rows: usize,
    dots: Vec<u8>,
    marks: Vec<Option<char>>,
}

impl Canvas {
    fn new(cols: usize, rows: usize) -> Canvas {
        Canvas {
            cols,
            rows,
            dots: vec![0; cols * rows],
            marks: vec![None; cols * rows],
        }
    }

    /// Sets the dot at (px, py), px across, py down, in dots.
    fn dot(&mut self, px: f64, py: f64) {
        if !(px >= 0.0 && py >= 0.0) {
            return;
        }
        let (px, py) = (px as usize, py as usize);
        let (c, r) = (px / 2, py / 4);
        if c >= self.cols || r >= self.rows {
            return;
        }
        const BITS: [[u8; 4]; 2] = [[0x01, 0x02, 0x04, 0x40], [0x08, 0x10, 0x20, 0x80]];
        self.dots[r * self.cols + c] |= BITS[px % 2][py % 4];
    }

    fn line(&mut self, a: (f64, f64), b: (f64, f64)) {
        // Only the part on the canvas (Liang-Barsky), so a huge segment costs nothing.
        let Some((a, b)) = self.clip(a, b) else {
            return;
        };
        let n = ((b.0 - a.0).abs().max((b.1 - a.1).abs()) * 2.0)
            .ceil()
            .max(1.0) as usize;
        for i in 0..=n {
            let t = i as f64 / n as f64;
            self.dot(a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
        }
    }

    /// The part of segment `a`-`b` inside the canvas, in dots.
    fn clip(&self, a: (f64, f64), b: (f64, f64)) -> Option<((f64, f64), (f64, f64))> {
        let (w, h) = ((self.cols * 2) as f64, (self.rows * 4) as f64);
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, q) in [(-dx, a.0), (dx, w - a.0), (-dy, a.1), (dy, h - a.1)] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else {
                let r = q / p;
                if p < 0.0 {
                    t0 = t0.max(r)
                } else {
                    t1 = t1.min(r)
                }
            }
        }
        (t0 <= t1 && t0.is_finite() && t1.is_finite()).then_some((
            (a.0 + t0 * dx, a.1 + t0 * dy),
            (a.0 + t1 * dx, a.1 + t1 * dy),
        ))
    }

    fn mark(&mut self, (px, py): (f64, f64), ch: char) {
        if px >= 0.0 && py >= 0.0 {
            let (c, r) = ((px as usize) / 2, (py as usize) / 4);
            if c < self.cols && r < self.rows {
                self.marks[r * self.cols + c] = Some(ch);
            }
        }
    }

    fn render(&self) -> String {
        let mut out = String::new();
        for r in 0..self.rows {
            for c in 0..self.cols {
                let i = r * self.cols + c;
                out.push(self.marks[i].unwrap_or_else(|| {
                    char::from_u32(0x2800 + self.dots[i] as u32).unwrap_or(' ')
                }));
            }
            out.push('\n');
        }
        out
    }
}

/// The diagram for a terminal `width` characters wide (the canvas at most 110; the lines under
/// it wrapped to `width`).
pub fn render(p: &Picture, width: usize) -> String {
    let cols = width.clamp(30, 120) - 10;
    let rows = cols / 2;
    let side = (cols * 2).min(rows * 4) as f64;
    let map = Map::fit(p, (0.0, 0.0), side);
    let mut cv = Canvas::new(cols, rows);
    let to = |v: (f64, f64)| map.at(v);
    cv.line(to((map.x.0, 0.0)), to((map.x.1, 0.0)));
    cv.line(to((0.0, map.y.0)), to((0.0, map.y.1)));
    let lo = map.x.0.max(map.y.0);
    let hi = map.x.1.min(map.y.1);
    for k in 0..40 {
        // The 45-degree line, dotted.
        let a = lo + (hi - lo) * k as f64 / 40.0;
        let b = lo + (hi - lo) * (k as f64 + 0.4) / 40.0;
        cv.line(to((a, a)), to((b, b)));
    }
    if let Some((a, b)) = map.clip(p.line) {
        cv.line(to(a), to(b));
    }
    for e in p.ellipses() {
        let pts = e.points(400);
        for w in pts.windows(2) {
            cv.line(to(w[0]), to(w[1]));
        }
    }
    cv.line(to(p.v_in), to(p.v_fin));
    cv.mark(to(p.v_in), 'I');
    cv.mark(to(p.v_com), 'C');
    if p.e > 0.0 {
        cv.mark(to(p.v_fin), 'F');
    }
    let fit = |text: String| crate::values::terminal::wrap(&text, width, "  ");
    let mut out = fit(format!("Velocity plane (V1 across, V2 up), {}", p.title));
    out.push_str(&cv.render());
    let (k1, k2, c) = p.line;
    out.push_str(&fit(format!(
        "I = IN ({}, {})   C = COM ({}, {})   F = FIN ({}, {})",
        num(p.v_in.0),
        num(p.v_in.1),
        num(p.v_com.0),
        num(p.v_com.1),
        num(p.v_fin.0),
        num(p.v_fin.1)
    )));
    out.push_str(&fit(format!(
        "momentum line {} V1 + {} V2 = {}; ellipses KE_IN = {}, KE_COM = {}",
        num(k1),
        num(k2),
        num(c),
        num(p.ellipse_in.ke),
        num(p.ellipse_com.ke),
    )));
    out.push_str(&fit(format!(
        "V1 from {} to {}, V2 from {} to {}",
        num(map.x.0),
        num(map.x.1),
        num(map.y.0),
        num(map.y.1)
    )));
    out
}
