//! The table of units (issue 8): each unit's names and its exact size in SI, and the lookup of a
//! typed name with the nearest names for a mistyped one. The bottom of the units: heights,
//! typed quantities and a case's units all read it.

use crate::values::number::{Number, printable};
use crate::values::rational::Q;

/// What a unit measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dimension {
    Mass,
    Velocity,
    Time,
    Length,
}

impl Dimension {
    /// "mass" or "velocity".
    pub fn name(self) -> &'static str {
        match self {
            Dimension::Mass => "mass",
            Dimension::Velocity => "velocity",
            Dimension::Time => "time",
            Dimension::Length => "length",
        }
    }
}

/// A unit: the names it is typed as, and its size in SI as an exact decimal or fraction.
#[derive(Debug, PartialEq)]
pub struct Unit {
    pub dimension: Dimension,
    /// The first name is how it is printed.
    pub names: &'static [&'static str],
    /// Size in kg or m/s.
    pub si: &'static str,
}

impl Unit {
    pub fn name(&self) -> &'static str {
        self.names[0]
    }
    pub fn si(&self) -> Q {
        self.si
            .parse::<Number>()
            .map(|n| n.exact())
            .unwrap_or_default()
    }
}

/// The units collide knows, each with the spellings sources use (`fps`, `ft/sec`, `km/hr`,
/// `kts`, ...; issue 45 §5): the first name is the one printed.
pub const UNITS: &[Unit] = &[
    Unit {
        dimension: Dimension::Mass,
        names: &["kg"],
        si: "1",
    },
    Unit {
        dimension: Dimension::Mass,
        names: &["g"],
        si: "0.001",
    },
    Unit {
        dimension: Dimension::Mass,
        names: &["mg"],
        si: "0.000001",
    },
    // The dalton (unified atomic mass unit), CODATA 2022.
    Unit {
        dimension: Dimension::Mass,
        names: &["u", "Da", "amu"],
        si: "1.66053906892e-27",
    },
    // The slug: 1 lbf s^2/ft = 4.4482216152605 N / (0.3048 m/s^2), exact.
    Unit {
        dimension: Dimension::Mass,
        names: &["slug", "slugs"],
        si: "4.4482216152605/0.3048",
    },
    Unit {
        dimension: Dimension::Mass,
        names: &["t", "tonne", "tonnes"],
        si: "1000",
    },
    Unit {
        dimension: Dimension::Mass,
        names: &["ton", "tons", "short ton"],
        si: "907.18474",
    },
    Unit {
        dimension: Dimension::Mass,
        names: &["long ton", "long tons"],
        si: "1016.0469088",
    },
    Unit {
        dimension: Dimension::Mass,
        names: &["lb", "lbs"],
        si: "0.45359237",
    },
    Unit {
        dimension: Dimension::Mass,
        names: &["oz"],
        si: "0.028349523125",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["m/s", "m/sec"],
        si: "1",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["km/h", "kph", "km/hr"],
        si: "1000/3600",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["km/s", "km/sec"],
        si: "1000",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["mph", "mi/h", "mi/hr"],
        si: "0.44704",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["ft/s", "fps", "ft/sec"],
        si: "0.3048",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["knot", "knots", "kn", "kts"],
        si: "1852/3600",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["cm/s", "cm/sec"],
        si: "0.01",
    },
    Unit {
        dimension: Dimension::Time,
        names: &["s"],
        si: "1",
    },
    Unit {
        dimension: Dimension::Length,
        names: &["m"],
        si: "1",
    },
    Unit {
        dimension: Dimension::Length,
        names: &["cm"],
        si: "0.01",
    },
    Unit {
        dimension: Dimension::Length,
        names: &["mm"],
        si: "0.001",
    },
    Unit {
        dimension: Dimension::Length,
        names: &["km"],
        si: "1000",
    },
    Unit {
        dimension: Dimension::Length,
        names: &["ft", "feet", "foot"],
        si: "0.3048",
    },
    Unit {
        dimension: Dimension::Length,
        names: &["in", "inch", "inches"],
        si: "0.0254",
    },
    Unit {
        dimension: Dimension::Time,
        names: &["ms"],
        si: "0.001",
    },
    Unit {
        dimension: Dimension::Time,
        names: &["us", "µs"],
        si: "0.000001",
    },
];

/// Names that could mean several things, with how to be explicit.
const AMBIGUOUS: &[(&str, &str)] = &[
    (
        "T",
        "'T' could be a tonne or a short ton: write 't' (1000 kg) or 'ton' (907.18474 kg)",
    ),
    (
        "kt",
        "'kt' could be a knot or a kiloton: write 'knot' (or 'kn') for speed",
    ),
    ("m", "'m' is a length: velocities take m/s"),
    ("mi", "'mi' is a length: velocities take mph"),
    ("km", "'km' is a length: velocities take km/h"),
];

/// Why a name is not a unit of the dimension asked for.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum UnitError {
    #[error("ambiguous unit: {0}")]
    Ambiguous(&'static str),
    #[error("'{}' is a unit of {is}, not of {wanted}", printable(.name), is = .is.name(), wanted = .wanted.name())]
    WrongDimension {
        name: String,
        is: Dimension,
        wanted: Dimension,
    },
    #[error("unknown {} unit '{}': did you mean '{near}'? (known: {known})", .wanted.name(), printable(.name))]
    DidYouMean {
        name: String,
        wanted: Dimension,
        near: &'static str,
        known: String,
    },
    #[error("unknown {} unit '{}': expected one of {known}", .wanted.name(), printable(.name))]
    Unknown {
        name: String,
        wanted: Dimension,
        known: String,
    },
}

/// Edits between two names, a swap of neighbouring letters counting as one (the likeliest typo:
/// "mhp" for "mph").
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            d[i][j] = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d[i][j] = d[i][j].min(d[i - 2][j - 2] + 1);
            }
        }
    }
    d[a.len()][b.len()]
}

/// The unit called `name` for `dimension`, or an error naming the nearest ones.
pub fn lookup(name: &str, dimension: Dimension) -> Result<&'static Unit, UnitError> {
    let fits: Vec<&Unit> = UNITS.iter().filter(|u| u.dimension == dimension).collect();
    if let Some(u) = fits.iter().find(|u| u.names.contains(&name)) {
        return Ok(u);
    }
    if let Some((_, why)) = AMBIGUOUS.iter().find(|(n, _)| *n == name) {
        return Err(UnitError::Ambiguous(why));
    }
    if let Some(u) = UNITS.iter().find(|u| u.names.contains(&name)) {
        return Err(UnitError::WrongDimension {
            name: name.to_string(),
            is: u.dimension,
            wanted: dimension,
        });
    }
    let mut near: Vec<(usize, &'static str)> = fits
        .iter()
        .flat_map(|u| u.names.iter())
        .map(|n| (edit_distance(&name.to_lowercase(), n), *n))
        .filter(|(d, _)| *d <= 2)
        .collect();
    near.sort();
    let known = fits.iter().map(|u| u.name()).collect::<Vec<_>>().join(", ");
    let name = name.to_string();
    Err(match near.first() {
        Some((_, n)) => UnitError::DidYouMean {
            name,
            wanted: dimension,
            near: n,
            known,
        },
        None => UnitError::Unknown {
            name,
            wanted: dimension,
            known,
        },
    })
}
