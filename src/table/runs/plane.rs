//! Sweeps in the plane (`collide sweep` with vectors): two smooth bodies meeting along a line of
//! impact, one row per point of the grid, solved by the fast binary64 impact
//! ([`crate::space::impact::general`]: the exact impulse form correctly rounded) with the
//! classic scattering table in mind, the deflection against the impact parameter.
//!
//! Parameters: the masses `m1`, `m2`; the velocities' components `v1x`, `v1y`, `v2x`, `v2y`, or
//! `v1`, `v2` (a speed along the typed direction, `+x` for a body at rest); `e`; the line of
//! impact's angle `normal_deg` (from `+x`, counterclockwise), or with disks of radii `r1`, `r2`
//! the impact parameter `b` (physics.md section 7: `n` along `sqrt((R1+R2)^2 - b^2) d + b
//! d_perp`, `d = v1 - v2`, `d_perp` = `d` turned by +90 degrees, as `collide solve --radii
//! --impact-parameter` draws it).
//!
//! Columns: the final velocities, speeds and directions, how far each body turned, the angle
//! between the final velocities, the energies (`KE = 1/2 (m v).v`, the crunch from the reduced
//! mass, `1/2 mu (n.d)^2 / n.n`, `lost = (1 - e)(1 + e) crunch`), the impulse on body 2 and the
//! line of impact `n` used (as computed, not normalised). Every column `collide solve` also
//! prints is the exact value rounded once, as it prints it, bit for bit
//! ([`impact::general`], [`impact::angles`], [`impact::energies`]): `collide solve --normal
//! '(nx,ny)'` with the row's values gives the same numbers.

use super::{Kind, Knob};
use crate::line::inertia::Mass;
use crate::line::restitution::Restitution;
use crate::space::impact;
use crate::table::row::ValueProblem;
use crate::values::compensated::{Dd, exponent, pow2};
use crate::values::number::Number;

/// How the line of impact is given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Line {
    /// Its direction (any length).
    Normal([f64; 2]),
    /// Disks of radii `r`, body 2's centre at distance `b` from body 1's line of motion
    /// relative to body 2.
    Geometry { r: [f64; 2], b: f64 },
}

/// A collision in the plane to sweep: the base the grid's values go into.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneSweep {
    pub m: [f64; 2],
    pub v: [[f64; 2]; 2],
    pub line: Line,
    pub e: f64,
}

/// One row's results.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impact {
    pub v: [[f64; 2]; 2],
    pub fin: [[f64; 2]; 2],
    pub n: [f64; 2],
    pub m: [f64; 2],
    pub e: f64,
}

/// A column; bodies counted from 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Col {
    Fin(usize, usize),
    Speed(usize),
    Angle(usize),
    Turned(usize),
    Between,
    KeIn,
    KeFin,
    Crunch,
    Lost,
    Impulse(usize),
    Normal(usize),
}

const SCALARS: &[&str] = &[
    "e",
    "v1x",
    "v1y",
    "v2x",
    "v2y",
    "normal_deg",
    "nx",
    "ny",
    "b",
    "r1",
    "r2",
];

/// The columns by name.
pub const COLUMNS: [(&str, Col); 21] = [
    ("fin1x", Col::Fin(0, 0)),
    ("fin1y", Col::Fin(0, 1)),
    ("fin2x", Col::Fin(1, 0)),
    ("fin2y", Col::Fin(1, 1)),
    ("speed1", Col::Speed(0)),
    ("speed2", Col::Speed(1)),
    ("angle1_deg", Col::Angle(0)),
    ("angle2_deg", Col::Angle(1)),
    ("turned1_deg", Col::Turned(0)),
    ("turned2_deg", Col::Turned(1)),
    ("between_deg", Col::Between),
    ("ke_in", Col::KeIn),
    ("ke_fin", Col::KeFin),
    ("crunch", Col::Crunch),
    ("lost", Col::Lost),
    ("jx", Col::Impulse(0)),
    ("jy", Col::Impulse(1)),
    ("nx", Col::Normal(0)),
    ("ny", Col::Normal(1)),
    ("v1", Col::Speed(0)),
    ("v2", Col::Speed(1)),
];

/// The columns only a table in the plane has, with their help (`--help`, and the message for a
/// column neither table has).
pub const PLANE_HELP: [(&str, &str); 17] = [
    ("fin1x", "in the plane: FIN of body 1, x"),
    ("fin1y", "in the plane: FIN of body 1, y"),
    ("fin2x", "in the plane: FIN of body 2, x"),
    ("fin2y", "in the plane: FIN of body 2, y"),
    ("speed1", "in the plane: |v1'|"),
    ("speed2", "in the plane: |v2'|"),
    ("angle1_deg", "in the plane: direction of v1' from +x"),
    ("angle2_deg", "in the plane: direction of v2' from +x"),
    ("turned1_deg", "in the plane: angle from v1 to v1'"),
    ("turned2_deg", "in the plane: angle from v2 to v2'"),
    ("between_deg", "in the plane: angle between v1' and v2'"),
    ("jx", "in the plane: impulse on body 2, x"),
    ("jy", "in the plane: impulse on body 2, y"),
    ("nx", "in the plane: line of impact used, x"),
    ("ny", "in the plane: line of impact used, y"),
    (
        "normal_deg",
        "in the plane: line of impact's angle (a parameter)",
    ),
    ("b", "in the plane: impact parameter of disks (a parameter)"),
];

/// The names of the columns only the plane has, comma-separated.
pub fn plane_column_names() -> String {
    PLANE_HELP.map(|(n, _)| n).join(", ")
}

/// Names a planar `--vary` or `--columns` may use (what the 1D table does not know).
pub fn is_plane_name(name: &str) -> bool {
    let name = name.trim().replace('-', "_");
    SCALARS.contains(&name.as_str()) || name == "error" || COLUMNS.iter().any(|(n, _)| *n == name)
}

fn range(ok: bool, what: &str) -> Result<(), ValueProblem> {
    if ok {
        Ok(())
    } else {
        Err(ValueProblem::Range(what.into()))
    }
}

/// `a x b` and `a.b`, each rounded once (double-double sums of exact products).
// `#[inline(always)]` on a row's work (run, columns and their helpers): inlined into the row
// loop compiled for AVX2 and FMA where the processor has them (`super::chunk`).
#[inline(always)]
fn cross_dot(a: [f64; 2], b: [f64; 2]) -> (f64, f64) {
    let cross = Dd::prod(a[0], b[1]) - Dd::prod(a[1], b[0]);
    let dot = Dd::prod(a[0], b[0]) + Dd::prod(a[1], b[1]);
    (cross.value(), dot.value())
}

/// `a` times the power of two that makes its largest component about 1 (exact): its direction,
/// whose products neither underflow (1e-300) nor overflow (1e200).
#[inline(always)]
fn direction(a: [f64; 2]) -> [f64; 2] {
    let big = a[0].abs().max(a[1].abs());
    // floor(log2 big): a normal number's exponent field; a subnormal's from its highest bit
    // (its value is its bits times 2^-1074). Not `log2`, which the optimiser computes on every
    // call, to select after (2% of a planar row's instructions).
    let k = if big >= f64::MIN_POSITIVE {
        exponent(big)
    } else {
        63 - big.to_bits().leading_zeros() as i32 - 1074
    };
    // In two factors, each a normal power of two (k runs from -1074 to 1023).
    a.map(|x| x * pow2(-k / 2) * pow2(-k + k / 2))
}

/// The line of impact at `deg` degrees from `+x`, as `collide solve --normal DEGdeg` takes it:
/// a rational direction at multiples of 45 degrees, else the binary64 cosine and sine.
pub fn normal_at(deg: f64) -> [f64; 2] {
    use crate::values::rational::{from_f64, to_f64};
    let a = crate::space::angle::Angle::degrees(from_f64(deg));
    match a.rational_direction() {
        Some(d) => [to_f64(&d[0]).unwrap_or(0.0), to_f64(&d[1]).unwrap_or(0.0)],
        None => {
            let (c, s, _) = a.unit();
            [c, s]
        }
    }
}

impl PlaneSweep {
    /// The line of impact as a vector, for velocities `v`.
    #[inline(always)]
    fn normal(&self, v: &[[f64; 2]; 2]) -> Result<[f64; 2], String> {
        match self.line {
            Line::Normal(n) => Ok(n),
            Line::Geometry { r, b } => {
                let sum = r[0] + r[1];
                // Halved where the sum of two radii near 1.8e308 would overflow.
                let s = if sum.is_finite() {
                    b / sum
                } else {
                    (0.5 * b) / (0.5 * r[0] + 0.5 * r[1])
                };
                let Some((c, s)) = impact::disks(s) else {
                    return Err(format!(
                        "the disks miss: |b| = {} > R1 + R2 = {}",
                        crate::values::number::num(b.abs()),
                        crate::values::number::num(sum)
                    ));
                };
                let d = [v[0][0] - v[1][0], v[0][1] - v[1][1]];
                if d == [0.0, 0.0] {
                    return Err("the bodies do not move relative to each other".into());
                }
                if c == 0.0 {
                    return Err("a grazing contact: they do not approach along the line".into());
                }
                // The direction of d: no product leaves binary64.
                let d = direction(d);
                Ok([c * d[0] - s * d[1], c * d[1] + s * d[0]])
            }
        }
    }
}

impl Impact {
    #[inline(always)]
    fn value(&self, col: Col) -> Option<f64> {
        let speed = |w: [f64; 2]| libm::hypot(w[0], w[1]);
        Some(match col {
            Col::Fin(i, k) => self.fin[i][k],
            Col::Speed(i) => speed(self.fin[i]),
            Col::Angle(i) => {
                let w = self.fin[i];
                if w == [0.0, 0.0] {
                    return None;
                }
                libm::atan2(w[1], w[0]).to_degrees()
            }
            // From the impulse form, as `collide solve` prints them (never from the rounded
            // final velocities: a turn of 1e-13 rad leaves almost nothing in them).
            Col::Turned(i) => impact::angles(self.m, self.v, self.n, self.e).0[i],
            Col::Between => impact::angles(self.m, self.v, self.n, self.e).1?,
            // Each the exact value rounded once, as `collide solve` prints it.
            Col::KeIn => impact::energies(self.m, self.v, self.n, self.e).ke_in,
            Col::KeFin => impact::energies(self.m, self.v, self.n, self.e).ke_fin,
            Col::Crunch => impact::energies(self.m, self.v, self.n, self.e).crunch,
            Col::Lost => impact::energies(self.m, self.v, self.n, self.e).lost,
            // The impulse on body 2, `(1 + e) mu (n.d / n.n) n` (physics.md section 7), not
            // `m2 (v2' - v2)`, which cancels to nothing when body 2 barely changes.
            Col::Impulse(k) => impact::energies(self.m, self.v, self.n, self.e).impulse[k],
            Col::Normal(k) => self.n[k],
        })
    }
}

impl Kind for PlaneSweep {
    type Out = Impact;
    type Col = Col;

    fn scalars(&self) -> &'static [&'static str] {
        SCALARS
    }

    fn bodies(&self) -> usize {
        2
    }

    fn check(&self, knob: Knob, n: &Number) -> Result<(), ValueProblem> {
        let v = n.value();
        match knob {
            Knob::Mass(_) => drop(Mass::new(n.clone())?),
            Knob::Position(_) | Knob::Size(_) => range(
                false,
                "bodies in the plane have no position or size here: vary b (with --radii), \
                 normal_deg, v1x, v1y, v2x, v2y, v1, v2, m1, m2 or e",
            )?,
            Knob::Named("e") => drop(Restitution::new(n.clone())?),
            Knob::Named("b" | "r1" | "r2") if !matches!(self.line, Line::Geometry { .. }) => {
                range(false, "b, r1 and r2 need --radii and --impact-parameter")?
            }
            Knob::Named("r1" | "r2") => range(v > 0.0, "a radius must be > 0")?,
            Knob::Named(name @ ("normal_deg" | "nx" | "ny"))
                if matches!(self.line, Line::Geometry { .. }) =>
            {
                range(
                    false,
                    &format!(
                        "{name} sets the line of impact, which --radii and --impact-parameter \
                         give here: vary b"
                    ),
                )?
            }
            _ => {}
        }
        Ok(())
    }

    #[inline(always)]
    fn run(&self, point: &[(Knob, f64)]) -> Result<Impact, String> {
        let mut s = *self;
        for &(knob, x) in point {
            match knob {
                Knob::Mass(i) => s.m[i] = x,
                Knob::Velocity(i) => {
                    let w = s.v[i];
                    let len = libm::hypot(w[0], w[1]);
                    s.v[i] = if len > 0.0 {
                        [x * (w[0] / len), x * (w[1] / len)]
                    } else {
                        [x, 0.0]
                    };
                }
                Knob::Named("e") => s.e = x,
                Knob::Named("v1x") => s.v[0][0] = x,
                Knob::Named("v1y") => s.v[0][1] = x,
                Knob::Named("v2x") => s.v[1][0] = x,
                Knob::Named("v2y") => s.v[1][1] = x,
                Knob::Named("normal_deg") => s.line = Line::Normal(normal_at(x)),
                Knob::Named(name @ ("nx" | "ny")) => {
                    if let Line::Normal(n) = &mut s.line {
                        n[usize::from(name == "ny")] = x;
                    }
                }
                Knob::Named(name @ ("b" | "r1" | "r2")) => {
                    if let Line::Geometry { r, b } = &mut s.line {
                        match name {
                            "b" => *b = x,
                            "r1" => r[0] = x,
                            _ => r[1] = x,
                        }
                    }
                }
                other => return Err(format!("'{other:?}' is not a parameter in the plane")),
            }
        }
        let n = s.normal(&s.v)?;
        if n == [0.0, 0.0] {
            return Err("the line of impact is the zero vector".into());
        }
        let d = [s.v[0][0] - s.v[1][0], s.v[0][1] - s.v[1][1]];
        if cross_dot(n, d).1 <= 0.0 {
            return Err("they do not approach along the line of impact".into());
        }
        let fin = impact::general(s.m, s.v, n, s.e);
        if fin.iter().flatten().any(|x| !x.is_finite()) {
            return Err("a final velocity is beyond binary64".into());
        }
        Ok(Impact {
            v: s.v,
            fin,
            n,
            m: s.m,
            e: s.e,
        })
    }

    fn column(&self, name: &str) -> Option<Col> {
        COLUMNS.iter().find(|(n, _)| *n == name).map(|(_, c)| *c)
    }

    /// FIN, how far each moving body turned (a body at rest before has no direction to turn
    /// from: left out), the angle between the final velocities, the energy lost.
    fn defaults(&self) -> Vec<String> {
        let mut out: Vec<String> = ["fin1x", "fin1y", "fin2x", "fin2y"]
            .map(String::from)
            .to_vec();
        for (i, name) in ["turned1_deg", "turned2_deg"].iter().enumerate() {
            if self.v[i] != [0.0, 0.0] {
                out.push(name.to_string());
            }
        }
        out.extend(["between_deg".to_string(), "lost".to_string()]);
        out
    }

    fn column_forms(&self) -> String {
        COLUMNS
            .iter()
            .map(|(n, _)| *n)
            .filter(|n| !matches!(*n, "v1" | "v2"))
            .collect::<Vec<_>>()
            .join(", ")
    }

    #[inline(always)]
    fn value(&self, col: Col, out: &Impact) -> Option<f64> {
        out.value(col)
    }

    fn cheap(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A vector's direction is it times a power of two, its largest component in [1, 2):
    /// normal and subnormal components (2^-1074 is the smallest, 3 x 2^-1074 has its highest
    /// bit at 2^-1073).
    #[test]
    fn directions_by_powers_of_two() {
        let tiny = f64::from_bits(1);
        assert_eq!(direction([tiny, 0.0]), [1.0, 0.0]);
        assert_eq!(direction([3.0 * tiny, -tiny]), [1.5, -0.5]);
        assert_eq!(direction([-6.0, 1.0]), [-1.5, 0.25]);
        // 1e300 = 1.49 x 2^996.
        let scale = 2f64.powi(-996);
        assert_eq!(direction([1.0, 1e300]), [scale, 1e300 * scale]);
    }

    #[test]
    fn equal_disks_head_on_and_at_the_edge() {
        // Equal masses, elastic, target at rest: b = 0 is head-on (body 1 stops); the
        // deflection of body 1 is asin(b / (R1 + R2)) measured from... its turn is 90 degrees
        // less the angle of n: here b = 1, R1 + R2 = 2: n at 30 degrees off d, so body 1
        // leaves at 90 degrees to n, turned 60 degrees, and v1' = cos 60 (cos -60... ) in size.
        let s = PlaneSweep {
            m: [1.0, 1.0],
            v: [[1.0, 0.0], [0.0, 0.0]],
            line: Line::Geometry {
                r: [1.0, 1.0],
                b: 0.0,
            },
            e: 1.0,
        };
        let head_on = s.run(&[]).unwrap();
        assert_eq!(head_on.fin, [[0.0, 0.0], [1.0, 0.0]]);
        let off = s.run(&[(Knob::Named("b"), 1.0)]).unwrap();
        // n = (sqrt 3, 1): body 2 leaves along n at 30 degrees with speed cos 30; body 1 at
        // -60 degrees with speed cos 60 = 1/2; they part at 90 degrees.
        assert!((off.value(Col::Between).unwrap() - 90.0).abs() < 1e-12);
        assert!((off.value(Col::Turned(0)).unwrap() - 60.0).abs() < 1e-12);
        assert!((off.value(Col::Speed(0)).unwrap() - 0.5).abs() < 1e-15);
        assert!((off.value(Col::Lost).unwrap()).abs() < 1e-16);
        assert!(s.run(&[(Knob::Named("b"), 2.5)]).is_err());
    }

    /// The row loop compiled for x86-64-v3 (`cheap_chunk_v3`: AVX2, FMA) writes the bytes of
    /// the portable one, byte for byte: every planar column, over masses, velocities and lines
    /// of impact from 1e-300 to 1e300 (rows the double-double decides and rows it hands to
    /// exact arithmetic, rows that fail with their error), as CSV and JSON Lines.
    #[cfg(target_arch = "x86_64")]
    #[test]
    #[cfg_attr(
        not(has_avx2_fma),
        ignore = "needs a CPU with AVX2 and FMA (the x86-64-v3 row loop)"
    )]
    fn v3_writes_the_bytes_of_the_baseline() {
        use crate::table::runs::{Chunks, cells, cheap_chunk, cheap_chunk_v3, error_at};
        use crate::table::writer::{RowFormat, RowWriter, Sealed};
        use std::sync::atomic::AtomicU64;
        // Ignored where build.rs finds no AVX2 and FMA (the v3 loop cannot run there); where it
        // runs, the features are here.
        assert!(
            std::arch::is_x86_feature_detected!("avx2")
                && std::arch::is_x86_feature_detected!("fma")
        );
        let kind = PlaneSweep {
            m: [1.0, 1.0],
            v: [[1.0, 0.0], [0.0, 0.0]],
            line: Line::Normal([1.0, 0.0]),
            e: 1.0,
        };
        let names = ["m1", "m2", "v1x", "v1y", "v2x", "v2y", "nx", "ny", "e"];
        let params: Vec<Knob> = names
            .iter()
            .map(|n| crate::table::runs::knob(&kind, n).unwrap())
            .collect();
        let mut chosen: Vec<String> = names.iter().map(|n| n.to_string()).collect();
        // nx and ny are parameters here, and the line the impact used.
        chosen.extend(
            COLUMNS
                .iter()
                .filter(|(n, _)| !names.contains(n))
                .map(|(n, _)| n.to_string()),
        );
        chosen.push("error".into());
        let (cells, names) = cells(&kind, &params, &chosen).unwrap();
        // A linear congruential generator: signs, mantissas and exponents over all of it.
        let mut x: u64 = 25;
        let mut next = move |scale: i32| {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let u = (x >> 11) as f64 / (1u64 << 53) as f64;
            let power = ((x >> 3) % (2 * scale as u64 + 1)) as i32 - scale;
            (u - 0.5) * 10f64.powi(power)
        };
        // 4,000 points: a row the double-double cannot decide is solved in exact rationals,
        // about 0.6 ms (20,000 took 49 s of the suite's time).
        let points: Vec<Vec<(Knob, f64)>> = (0..4_000)
            .map(|i| {
                // Small integers a quarter of the time (exact ties, zero components), exponents
                // to 300 a quarter (overflows, the exact fallback), else to 20.
                let wide = [0, 300, 20, 20][i % 4];
                params
                    .iter()
                    .enumerate()
                    .map(|(k, p)| {
                        let v = match k {
                            0 | 1 => next(wide).abs().max(1e-300),
                            8 => next(0).abs() * 2.0,
                            _ if wide == 0 => (next(0) * 8.0).round(),
                            _ => next(wide),
                        };
                        (*p, v)
                    })
                    .collect()
            })
            .collect();
        for format in [RowFormat::Csv, RowFormat::Jsonl] {
            let writer = RowWriter::runs(names.clone(), error_at(&cells), format);
            let run = |v3: bool| {
                let mut items = points.iter();
                let next = |point: &mut Vec<(Knob, f64)>| {
                    point.clone_from(items.next()?);
                    Some(Ok(0))
                };
                let place = |_: u64, _: &[(Knob, f64)]| String::new();
                let errors = AtomicU64::new(0);
                let table = Chunks::new(&kind, &cells, &writer, false, &errors);
                let mut point = Vec::new();
                let out = if v3 {
                    // SAFETY: the features were detected above.
                    unsafe { cheap_chunk_v3(&table, &mut point, next, place) }
                } else {
                    cheap_chunk(&table, &mut point, next, place)
                };
                assert_eq!(out.rows, points.len() as u64);
                let Ok(Sealed::Bytes(bytes)) = out.body else {
                    panic!("a text table is bytes")
                };
                (bytes, errors.into_inner())
            };
            let (portable, failed) = run(false);
            let (v3, failed_v3) = run(true);
            // The cases reach what they should: failures, and mostly rows.
            // About half do not approach along their line; the widest overflow.
            assert!(failed > 400 && failed < 3_000, "{failed} rows failed");
            assert_eq!(failed, failed_v3);
            assert!(
                portable == v3,
                "{format:?}: the v3 row loop wrote other bytes"
            );
        }
    }
}
