//! Angles as homework writes them: `30deg`, `30°`, `-45 deg`, `0.5rad`, and compass bearings
//! (`N`, `NE`, `N30E`: 30 degrees east of north; `S20W`). Every angle is measured from +x
//! (east) counterclockwise, so a bearing `N30E` is 60 degrees.
//!
//! Degrees are kept exact (the typed number); a direction is rational when the angle is a
//! multiple of 90 degrees (unit vectors `(1, 0)`, `(0, 1)`, ...), and a line is rational for
//! multiples of 45 degrees (`(1, 1)` has the direction of 45 degrees, and a line of impact
//! matters only through `n n^T / n.n`).

use std::fmt;

use num_traits::Zero;

use crate::values::number::{Number, NumberError};
use crate::values::rational::{Q, from_f64, int, to_f64};

/// An angle from +x, counterclockwise.
#[derive(Clone, Debug, PartialEq)]
pub struct Angle {
    value: Value,
    /// As typed (`N30E`, `30deg`), for headers.
    pub typed: String,
}

#[derive(Clone, Debug, PartialEq)]
enum Value {
    /// Exact degrees.
    Degrees(Q),
    /// Radians as typed (their degrees are irrational but for 0).
    Radians(f64),
}

/// Why a text is not an angle.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum AngleError {
    #[error(
        "angle '{0}': give its unit (30deg, 30°, 0.5rad) or a compass bearing (N, NE, N30E, \
         S20W)"
    )]
    NoUnit(String),
    #[error("angle '{text}': {error}")]
    Number { text: String, error: NumberError },
    #[error(
        "bearing '{0}': expected a compass point (N, NE, E, SE, S, SW, W, NW) or a turn from N \
         or S toward E or W (N30E, S20W), or from E or W toward N or S (E10N)"
    )]
    Bearing(String),
}

impl Angle {
    /// An angle of exact degrees.
    pub fn degrees(q: Q) -> Angle {
        let typed = format!("{}deg", crate::values::quantity::fraction(&q));
        Angle {
            value: Value::Degrees(q),
            typed,
        }
    }

    /// Whether it was typed as a compass bearing (`N30E`, `SW`).
    pub fn is_bearing(&self) -> bool {
        self.typed.starts_with(['N', 'S', 'E', 'W'])
    }

    /// The angle in degrees, exact when it is (typed in degrees or as a bearing).
    pub fn exact_degrees(&self) -> Option<&Q> {
        match &self.value {
            Value::Degrees(q) => Some(q),
            Value::Radians(r) if *r == 0.0 => None,
            Value::Radians(_) => None,
        }
    }

    /// In radians (binary64).
    pub fn radians(&self) -> f64 {
        match &self.value {
            Value::Radians(r) => *r,
            Value::Degrees(q) => {
                let reduced = reduce(q);
                to_f64(&reduced).unwrap_or(0.0).to_radians()
            }
        }
    }

    /// The unit vector `(cos a, sin a)`: exact for multiples of 90 degrees (the third value),
    /// else the binary64 values of the cosine and sine (`sin_cos_degrees`, rational values such
    /// as sin 30 deg = 1/2 exactly).
    pub fn unit(&self) -> (f64, f64, Option<[Q; 2]>) {
        if let Some(q) = self.exact_degrees() {
            let r = reduce(q);
            for (deg, c, s) in [(0, 1, 0), (90, 0, 1), (180, -1, 0), (270, 0, -1)] {
                if r == int(deg) {
                    return (c as f64, s as f64, Some([int(c), int(s)]));
                }
            }
            let (c, s) = sin_cos_degrees(&r);
            return (c, s, None);
        }
        let a = self.radians();
        (libm::cos(a), libm::sin(a), None)
    }

    /// The unit vector `(cos a, sin a)` as rationals, and whether it is rounded: exact for
    /// multiples of 90 degrees, else the binary64 cosine and sine of [`Angle::unit`].
    pub fn unit_rational(&self) -> (Vec<Q>, bool) {
        match self.unit() {
            (_, _, Some(u)) => (u.to_vec(), false),
            (c, s, None) => (vec![from_f64(c), from_f64(s)], true),
        }
    }

    /// `size` along the angle, `(size cos a, size sin a)`, and whether it is rounded: exact for
    /// multiples of 90 degrees, else each component the binary64 nearest `size` times the
    /// binary64 cosine or sine. The one reading of `speed @ angle` in every mode (the plane,
    /// rigid bodies, scenes).
    pub fn along(&self, size: &Q) -> (Vec<Q>, bool) {
        let (unit, rounded) = self.unit_rational();
        let parts = unit
            .iter()
            .map(|c| {
                let q = size * c;
                if rounded {
                    from_f64(to_f64(&q).unwrap_or(0.0))
                } else {
                    q
                }
            })
            .collect();
        (parts, rounded)
    }

    /// A vector along the angle's line (any length) and whether it is rounded: rational for
    /// multiples of 45 degrees ([`Angle::rational_direction`]), else the rounded unit vector.
    pub fn direction(&self) -> (Vec<Q>, bool) {
        match self.rational_direction() {
            Some(d) => (d.to_vec(), false),
            None => self.unit_rational(),
        }
    }

    /// A rational vector along the angle's line (any length), for multiples of 45 degrees: a
    /// line of impact needs only its direction.
    pub fn rational_direction(&self) -> Option<[Q; 2]> {
        let q = self.exact_degrees()?;
        let r = reduce(q);
        let table = [
            (0, 1, 0),
            (45, 1, 1),
            (90, 0, 1),
            (135, -1, 1),
            (180, -1, 0),
            (225, -1, -1),
            (270, 0, -1),
            (315, 1, -1),
        ];
        table
            .iter()
            .find(|(d, _, _)| r == int(*d))
            .map(|(_, c, s)| [int(*c), int(*s)])
    }
}

/// `(cos, sin)` of `d` degrees in [0, 360): reduced exactly to an angle `t` in [0, 45] by the
/// symmetries of the octants, then `sin` and `cos` of `t pi/180` taken in double-double
/// (`sin(hi + lo) = sin hi + lo cos hi`), so the radian's rounding (sin(30 deg) from the binary64
/// of pi/6 is 0.49999999999999994) does not add to the library's own error; the values with a
/// rational or a square-root form (30, 45, 60 degrees) are the nearest binary64 exactly, the
/// others within an ulp.
fn sin_cos_degrees(d: &Q) -> (f64, f64) {
    // pi/180 as a double-double.
    const PI_180: crate::values::compensated::Dd = crate::values::compensated::Dd {
        hi: 0.017453292519943295,
        lo: 2.9486522708701687e-19,
    };
    let octant = (d / int(45)).floor();
    let k = i64::try_from(&octant).unwrap_or(0).rem_euclid(8);
    let rest = d - Q::from(octant) * int(45);
    // t in [0, 45] with (cos d, sin d) = a signed permutation of (cos t, sin t).
    let t = if k % 2 == 0 { rest } else { int(45) - rest };
    let (c, s) = if t.is_zero() {
        (1.0, 0.0)
    } else if t == int(45) {
        (0.5f64.sqrt(), 0.5f64.sqrt())
    } else if t == int(30) {
        (0.75f64.sqrt(), 0.5)
    } else {
        let tf = to_f64(&t).unwrap_or(0.0);
        let r = crate::values::compensated::Dd::new(tf) * PI_180;
        (
            libm::cos(r.hi) - r.lo * libm::sin(r.hi),
            libm::sin(r.hi) + r.lo * libm::cos(r.hi),
        )
    };
    // Octant k covers [45 k, 45 (k + 1)).
    match k {
        0 => (c, s),
        1 => (s, c),
        2 => (-s, c),
        3 => (-c, s),
        4 => (-c, -s),
        5 => (-s, -c),
        6 => (s, -c),
        _ => (c, -s),
    }
}

/// Degrees reduced to [0, 360), exactly.
fn reduce(q: &Q) -> Q {
    let full = int(360);
    let turns = (q / &full).floor();
    let r = q - Q::from(turns) * &full;
    if r < Q::zero() { r + full } else { r }
}

impl fmt::Display for Angle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.typed)
    }
}

impl std::str::FromStr for Angle {
    type Err = AngleError;

    fn from_str(text: &str) -> Result<Angle, AngleError> {
        let t = text.trim();
        if t.starts_with(['N', 'S', 'E', 'W']) {
            return bearing(t).map(|q| Angle {
                value: Value::Degrees(q),
                typed: t.to_string(),
            });
        }
        let number = |s: &str| {
            s.trim()
                .parse::<Number>()
                .map_err(|error| AngleError::Number {
                    text: t.to_string(),
                    error,
                })
        };
        for unit in ["degrees", "degree", "deg", "°"] {
            if let Some(n) = t.strip_suffix(unit) {
                return Ok(Angle {
                    value: Value::Degrees(number(n)?.exact()),
                    typed: t.to_string(),
                });
            }
        }
        for unit in ["radians", "radian", "rad"] {
            if let Some(n) = t.strip_suffix(unit) {
                return Ok(Angle {
                    value: Value::Radians(number(n)?.value()),
                    typed: t.to_string(),
                });
            }
        }
        Err(AngleError::NoUnit(t.to_string()))
    }
}

/// The compass bearing of the direction `(x, y)` (east, north; any size), the way it is typed:
/// `N30E` for 60 degrees from +x, `S20W` for -110, `NE` for 45, `W` for 180. The turn from N or
/// S toward E or W is `atan2(|x|, |y|)`, from the components themselves (not `90 - angle`, which
/// cancels near north and south), and is written by `show`; a turn that `show` writes as 0, 45
/// or 90 is a compass point.
pub fn compass(x: f64, y: f64, show: impl Fn(f64) -> String) -> String {
    let from = if y >= 0.0 { 'N' } else { 'S' };
    let to = if x >= 0.0 { 'E' } else { 'W' };
    let turn = libm::atan2(x.abs(), y.abs()).to_degrees();
    match show(turn).as_str() {
        "0" => from.to_string(),
        "90" => to.to_string(),
        "45" => format!("{from}{to}"),
        turn => format!("{from}{turn}{to}"),
    }
}

/// A compass bearing in degrees from +x (east), counterclockwise.
fn bearing(t: &str) -> Result<Q, AngleError> {
    let bad = || AngleError::Bearing(t.to_string());
    let heading = |c: char| match c {
        'E' => Some(0i64),
        'N' => Some(90),
        'W' => Some(180),
        'S' => Some(270),
        _ => None,
    };
    let points = [
        ("N", 90),
        ("NE", 45),
        ("E", 0),
        ("SE", 315),
        ("S", 270),
        ("SW", 225),
        ("W", 180),
        ("NW", 135),
    ];
    if let Some((_, d)) = points.iter().find(|(p, _)| *p == t) {
        return Ok(int(*d));
    }
    // `N30E`: from the first letter, turn toward the last by the number between.
    let mut chars = t.chars();
    let from = chars.next().and_then(heading).ok_or_else(bad)?;
    let to = chars.next_back().and_then(heading).ok_or_else(bad)?;
    let middle = chars.as_str().trim();
    let middle = ["degrees", "degree", "deg", "°"]
        .iter()
        .find_map(|u| middle.strip_suffix(u))
        .unwrap_or(middle)
        .trim();
    let turn: Number = middle.parse().map_err(|_| bad())?;
    let turn = turn.exact();
    if turn < Q::zero() || turn > int(90) {
        return Err(bad());
    }
    // The two letters must be a quarter turn apart; the sign of the turn is the way from one to
    // the other.
    let sign = match (to - from).rem_euclid(360) {
        90 => 1,
        270 => -1,
        _ => return Err(bad()),
    };
    Ok(reduce(&(int(from) + int(sign) * turn)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compass_bearings_read_back_as_typed() {
        let show = |x: f64| crate::values::number::num(x);
        // Each bearing, parsed to degrees from +x and written back.
        let of = |a: f64| {
            let (c, s, _) = Angle::degrees(crate::values::rational::from_f64(a)).unit();
            compass(c, s, show)
        };
        for t in [
            "N", "NE", "E", "SE", "S", "SW", "W", "NW", "N30E", "S20W", "S10E", "N80W", "N12.5E",
        ] {
            let (c, s, _) = t.parse::<Angle>().unwrap().unit();
            assert_eq!(compass(c, s, show), t, "{t}");
        }
        // E10N is N80E typed the other way round: it reads back from north.
        assert_eq!(of(10.0), "N80E");
        // Directions a few ulps off a compass point still name it.
        assert_eq!(of(60.000000000000014), "N30E");
        assert_eq!(of(-179.99999999999997), "W");
        assert_eq!(of(-90.0), "S");
        assert_eq!(compass(6e-17, -1.0, show), "S3.43774677078494e-15E");
        // Near north the turn keeps its digits: (1e-15, 1) is atan(1e-15) east of north,
        // 5.72957795130823e-14 degrees (90 - its angle from +x would cancel to 5.68e-14).
        assert_eq!(compass(1e-15, 1.0, show), "N5.72957795130823e-14E");
        assert_eq!(compass(-1e-10, -1.0, show), "S5.72957795130823e-9W");
        assert!(Angle::degrees(int(30)).typed == "30deg");
        assert!("N30E".parse::<Angle>().unwrap().is_bearing());
        assert!(!"30deg".parse::<Angle>().unwrap().is_bearing());
    }

    fn deg(t: &str) -> f64 {
        to_f64(t.parse::<Angle>().unwrap().exact_degrees().unwrap()).unwrap()
    }

    #[test]
    fn bearings_are_measured_from_east_counterclockwise() {
        assert_eq!(deg("N"), 90.0);
        assert_eq!(deg("NE"), 45.0);
        assert_eq!(deg("N30E"), 60.0);
        assert_eq!(deg("N30W"), 120.0);
        assert_eq!(deg("S20W"), 250.0);
        assert_eq!(deg("S20E"), 290.0);
        assert_eq!(deg("E10N"), 10.0);
        assert_eq!(deg("W 15 S"), 195.0);
        assert_eq!(deg("N45°E"), 45.0);
        for bad in ["N30N", "X", "N100E", "N-5E", "NxE"] {
            assert!(bad.parse::<Angle>().is_err(), "{bad}");
        }
    }

    #[test]
    fn degrees_and_radians() {
        assert_eq!(deg("30deg"), 30.0);
        assert_eq!(deg("-45 deg"), -45.0);
        assert_eq!(deg("30°"), 30.0);
        let a: Angle = "0.5rad".parse().unwrap();
        assert_eq!(a.radians(), 0.5);
        let e = "30".parse::<Angle>().unwrap_err().to_string();
        assert!(e.contains("give its unit"), "{e}");
    }

    #[test]
    fn quarter_turns_are_exact_unit_vectors() {
        let a: Angle = "450deg".parse().unwrap();
        assert_eq!(a.unit().2, Some([int(0), int(1)]));
        let a: Angle = "-90deg".parse().unwrap();
        assert_eq!(a.unit().2, Some([int(0), int(-1)]));
        let a: Angle = "30deg".parse().unwrap();
        let (c, s, exact) = a.unit();
        assert!(exact.is_none());
        // sqrt(3)/2 = 0.866025403784438646..., nearest binary64 0.8660254037844386.
        assert_eq!((c, s), (0.8660254037844386, 0.5));
        let a: Angle = "240deg".parse().unwrap();
        assert_eq!(a.unit().0, -0.5);
        assert_eq!(a.unit().1, -0.8660254037844386);
        // cos 10 deg = 0.98480775301220805936..., sin 10 deg = 0.17364817766693034885...: within
        // an ulp (libm's sin of the reduced radian is itself rounded).
        let a: Angle = "10deg".parse().unwrap();
        let ulp = |x: f64| f64::from_bits(x.to_bits() + 1) - x;
        assert!((a.unit().0 - 0.984807753012208).abs() <= ulp(0.984807753012208));
        assert!((a.unit().1 - 0.17364817766693036).abs() <= ulp(0.17364817766693036));
        let a: Angle = "SW".parse().unwrap();
        assert_eq!(a.rational_direction(), Some([int(-1), int(-1)]));
    }
}
