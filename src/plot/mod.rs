//! Pictures (`collide plot`, `--plot` on `solve`, `[plot]` in scenes): the velocity-velocity
//! diagram of the lecture's figures, and space-time diagrams of the two world lines, as SVG and in
//! the terminal.

pub mod accuracy;
pub mod plane;
pub mod rigid;
pub mod spacetime;
pub mod svg;
pub mod term;
pub mod velocity;
pub mod work;

use crate::line::case::Case;
use crate::line::frame::Frame;
use crate::solver::Solver;
use crate::solver::binary64::Binary64;

/// Which picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    /// The (V1, V2) plane: momentum line, energy ellipses, IN, COM, FIN
    Velocity,
    /// Position against time (time across)
    Newton,
    /// Time up, position across
    Minkowski,
}

/// One energy ellipse `1/2 V.M.V = KE`: radii along unit axes.
#[derive(Clone, Debug, PartialEq)]
pub struct EllipseShape {
    pub ke: f64,
    pub radii: (f64, f64),
    pub axes: [(f64, f64); 2],
}

impl EllipseShape {
    /// Half the width and height of the box around it.
    pub fn extent(&self) -> (f64, f64) {
        let (a, b) = self.radii;
        let [q1, q2] = self.axes;
        ((a * q1.0).hypot(b * q2.0), (a * q1.1).hypot(b * q2.1))
    }

    /// Points around it, for polylines and the terminal.
    pub fn points(&self, n: usize) -> Vec<(f64, f64)> {
        let (a, b) = self.radii;
        let [q1, q2] = self.axes;
        (0..=n)
            .map(|i| {
                let s = std::f64::consts::TAU * i as f64 / n as f64;
                let (c, d) = (a * s.cos(), b * s.sin());
                (c * q1.0 + d * q2.0, c * q1.1 + d * q2.1)
            })
            .collect()
    }
}

/// A frame's name with its IN, COM and FIN points.
pub type Shifted = (String, (f64, f64), (f64, f64), (f64, f64));

/// What the pictures show, in the chosen frame.
#[derive(Clone, Debug)]
pub struct Picture {
    pub title: String,
    pub frame: Frame,
    pub w: f64,
    pub e: f64,
    pub masses: [f64; 2],
    pub v_in: (f64, f64),
    pub v_com: (f64, f64),
    pub v_fin: (f64, f64),
    /// Momentum line `k1 V1 + k2 V2 = p`.
    pub line: (f64, f64, f64),
    pub ellipse_in: EllipseShape,
    pub ellipse_com: EllipseShape,
    /// Only when `0 < e < 1` (elastic: the IN ellipse; stuck: the COM ellipse).
    pub ellipse_fin: Option<EllipseShape>,
    /// The standard frames' IN, COM, FIN, shifted (`--frames`).
    pub others: Vec<Shifted>,
}

impl Picture {
    pub fn new(case: &Case, frame: &Frame, overlay_frames: bool) -> Picture {
        let c = &case.collision;
        let seen = Binary64::new(c, frame);
        let pair = |p: [f64; 2]| (p[0], p[1]);
        let m = c.inertia.matrix();
        let axes = if c.inertia.is_diagonal() {
            [(m[(0, 0)], (1.0, 0.0)), (m[(1, 1)], (0.0, 1.0))]
        } else {
            let [(l1, q1), (l2, q2)] = c.inertia.principal_axes();
            [(l1, (q1.x, q1.y)), (l2, (q2.x, q2.y))]
        };
        // Radii as the report computes them, sqrt(2 KE) / sqrt(lambda): no overflow on the way.
        let shape = |ke: f64| {
            let root = crate::line::ellipse::root_2ke(ke);
            EllipseShape {
                ke,
                radii: (root / axes[0].0.sqrt(), root / axes[1].0.sqrt()),
                axes: [axes[0].1, axes[1].1],
            }
        };
        let e = c.restitution.value();
        let (k1, k2, _) = seen.momentum_line();
        let vc = seen.v_com();
        let others = if overlay_frames {
            Frame::standard()
                .into_iter()
                .filter(|f| f != frame)
                .map(|f| {
                    let o = Binary64::new(c, &f);
                    (
                        f.describe(),
                        pair(o.v_in()),
                        (o.v_com(), o.v_com()),
                        pair(o.v_fin()),
                    )
                })
                .collect()
        } else {
            Vec::new()
        };
        let frame_note = if *frame == Frame::Lab {
            String::new()
        } else {
            format!(", {} frame", frame.describe())
        };
        Picture {
            title: format!(
                "M = {}, V_IN = ({}, {}), e = {}{frame_note}",
                c.inertia.describe(),
                case.velocities[0],
                case.velocities[1],
                c.restitution
            ),
            frame: frame.clone(),
            w: seen.w.value(),
            e,
            masses: [m[(0, 0)], m[(1, 1)]],
            v_in: pair(seen.v_in()),
            v_com: (vc, vc),
            v_fin: pair(seen.v_fin()),
            line: (k1, k2, seen.total_momentum()),
            ellipse_in: shape(seen.ke_in()),
            ellipse_com: shape(seen.ke_com()),
            ellipse_fin: (e > 0.0 && e < 1.0).then(|| shape(seen.ke_fin())),
            others,
        }
    }
}

impl Picture {
    /// The energy ellipses drawn: IN, COM, and FIN when it is a third one.
    pub fn ellipses(&self) -> impl Iterator<Item = &EllipseShape> {
        [
            Some(&self.ellipse_in),
            Some(&self.ellipse_com),
            self.ellipse_fin.as_ref(),
        ]
        .into_iter()
        .flatten()
    }
}

/// The SVG of `kind`.
pub fn svg(case: &Case, frame: &Frame, kind: Kind, overlay_frames: bool) -> String {
    let p = Picture::new(case, frame, overlay_frames);
    match kind {
        Kind::Velocity => velocity::svg(&p),
        Kind::Newton => spacetime::svg(&p, false),
        Kind::Minkowski => spacetime::svg(&p, true),
    }
}
