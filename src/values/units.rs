//! Units (issue 8): a mass or velocity may be typed with a unit (`4 t`, `60mph`, `72 km/h`). A
//! table of units with exact factors to SI, not scattered constants. Numbers keep their units when
//! all masses share one and all velocities share one; otherwise (or with `--si`) everything is
//! converted exactly to kg and m/s.

use crate::values::rational::Q;

use crate::values::number::{FieldsError, Given, Number, NumberError, printable, split_fields};

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

/// The units collide knows.
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
        names: &["m/s"],
        si: "1",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["km/h", "kph"],
        si: "1000/3600",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["km/s"],
        si: "1000",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["mph", "mi/h"],
        si: "0.44704",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["ft/s"],
        si: "0.3048",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["knot", "knots", "kn"],
        si: "1852/3600",
    },
    Unit {
        dimension: Dimension::Velocity,
        names: &["cm/s"],
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

/// A duration in seconds, exactly: `2 ms`, `0.5 s`, or a bare number of seconds; it must be
/// above 0 (`--contact-time`).
pub fn seconds(text: &str) -> Result<Q, QuantityError> {
    let q = parse(text, Dimension::Time)?;
    let s = q.number.exact()
        * q.unit
            .map_or_else(|| crate::values::rational::int(1), Unit::si);
    if s <= Q::ZERO {
        return Err(QuantityError::NotPositive(text.trim().to_string()));
    }
    Ok(s)
}

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

/// A typed value: a number with an optional unit.
#[derive(Clone, Debug, PartialEq)]
pub struct Quantity {
    pub number: Number,
    pub unit: Option<&'static Unit>,
    /// A velocity typed as a height (`height 2 m`): `number` is the signed height in metres,
    /// to become the speed `sqrt(2 g h)` once `g` is known (`with_gravity`).
    pub height: bool,
}

use super::heights::parse_height;
pub use super::heights::{HeightScale, STANDARD_GRAVITY};

/// Why a text is not a quantity.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum QuantityError {
    #[error(transparent)]
    Number(#[from] NumberError),
    #[error(transparent)]
    Unit(#[from] UnitError),
    #[error(
        "contact time '{}' must be above 0 (a duration such as '2 ms' or '0.01 s')",
        printable(.0)
    )]
    NotPositive(String),
    #[error(
        "'{}': a height must be >= 0; give the direction as a sign: '-height 2 m' (down)",
        printable(.0)
    )]
    NegativeHeight(String),
    #[error(
        "'{}': a speed from a slide is 'slide D mu MU' (the distance friction MU > 0 stops it \
         in, e.g. 'slide 5 cm mu 0.62': sqrt(2 mu g d)); a sign gives the direction",
        printable(.0)
    )]
    Slide(String),
    #[error(
        "'{}': the height is {metres} m (mu d for a slide), beyond binary64 (it must be below \
         1.8e308 m and above 4.9e-324 m)",
        printable(.typed)
    )]
    HeightRange { typed: String, metres: String },
}

/// Splits `4 t`, `60mph`, `12 N s` or `1e3` into its number and the rest (a unit name, trimmed;
/// empty for a plain number).
pub fn split_number(t: &str) -> Result<(Number, &str), QuantityError> {
    let t = t.trim();
    // A whole number (or one that is out of range, or divides by zero) has no unit: its own
    // error is the one to report.
    match t.parse::<Number>() {
        Ok(number) => {
            return Ok((number, ""));
        }
        Err(e) if !matches!(e, NumberError::Syntax(_)) => return Err(e.into()),
        Err(_) => {}
    }
    // The longest prefix that is a number, followed by a unit name. Only the places where a
    // unit could start are tried (before a space or a letter), so a long text costs one parse
    // per such place, not one per character. The longest prefix that reads as a number out of
    // range is that number's error ('1e9999 m': too large, not the unit 'e9999 m').
    let cut = (1..=t.len())
        .rev()
        .filter(|&i| {
            t.is_char_boundary(i)
                && t[i..]
                    .chars()
                    .next()
                    .is_none_or(|c| c.is_whitespace() || c.is_alphabetic())
        })
        .find_map(|i| match t[..i].parse::<Number>() {
            Ok(_) => Some(Ok(i)),
            Err(NumberError::Syntax(_) | NumberError::Empty) => None,
            Err(e) => Some(Err(e)),
        })
        .transpose()?;
    let Some(i) = cut else {
        // No number at all: the number parser says why.
        return Err(t
            .parse::<Number>()
            .err()
            .unwrap_or(NumberError::Empty)
            .into());
    };
    let number: Number = t[..i].parse()?;
    Ok((number, t[i..].trim()))
}

/// Splits `4 t`, `60mph`, `2/3 m/s` or `1e3` into a number and a unit name.
pub fn parse(text: &str, dimension: Dimension) -> Result<Quantity, QuantityError> {
    let t = text.trim();
    if dimension == Dimension::Velocity
        && let Some(height) = parse_height(t)
    {
        return height;
    }
    let (number, rest) = split_number(t)?;
    let unit = if rest.is_empty() {
        None
    } else {
        Some(lookup(rest, dimension)?)
    };
    Ok(Quantity {
        number,
        unit,
        height: false,
    })
}

/// How values are measured in a case: the units kept (when shared), or SI.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Units {
    pub mass: Option<&'static str>,
    pub velocity: Option<&'static str>,
    /// The unit energies are printed in (`--energy-unit`), when not the case's own.
    pub energy_as: Option<&'static EnergyUnit>,
}

/// A unit energies may be printed in: its name and size in joules, exact.
#[derive(Debug, PartialEq)]
pub struct EnergyUnit {
    pub name: &'static str,
    pub joules: &'static str,
}

/// `--energy-unit` choices.
pub const ENERGY_UNITS: &[EnergyUnit] = &[
    EnergyUnit {
        name: "J",
        joules: "1",
    },
    EnergyUnit {
        name: "kJ",
        joules: "1000",
    },
    // The electronvolt, exact since the 2019 SI (e = 1.602176634e-19 C).
    EnergyUnit {
        name: "eV",
        joules: "1.602176634e-19",
    },
    EnergyUnit {
        name: "MeV",
        joules: "1.602176634e-13",
    },
    // The foot-pound force: 0.3048 m x 4.4482216152605 N, exact.
    EnergyUnit {
        name: "ft*lbf",
        joules: "1.35581794833140040",
    },
    // The thermochemical calorie.
    EnergyUnit {
        name: "cal",
        joules: "4.184",
    },
];

/// Why energies cannot be given in the unit asked for.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EnergyUnitError {
    #[error(
        "unknown energy unit '{}': expected one of J, kJ, eV, MeV, ft*lbf, cal",
        printable(.0)
    )]
    Unknown(String),
    #[error(
        "--energy-unit {0} needs units on the masses and velocities (e.g. '2 kg', '3 m/s'), \
         to know what the case's energies are in"
    )]
    NoUnits(&'static str),
}

/// The energy unit named `name` (`ft*lbf` also as `ft lbf`, `ft.lbf`).
pub fn energy_unit(name: &str) -> Result<&'static EnergyUnit, EnergyUnitError> {
    let n = name.trim().replace([' ', '.', '·'], "*");
    ENERGY_UNITS
        .iter()
        .find(|u| u.name == n)
        .ok_or_else(|| EnergyUnitError::Unknown(name.trim().to_string()))
}

impl Units {
    /// Energies to be printed in `unit`: refused unless the case has mass and velocity units.
    pub fn with_energy_unit(mut self, unit: &'static EnergyUnit) -> Result<Units, EnergyUnitError> {
        if self.mass.is_none() || self.velocity.is_none() {
            return Err(EnergyUnitError::NoUnits(unit.name));
        }
        self.energy_as = Some(unit);
        Ok(self)
    }

    /// The factor from the case's energy unit (mass unit x velocity unit^2) to the printed one,
    /// exact: `None` when energies are printed in the case's own unit.
    pub fn energy_scale(&self) -> Option<Q> {
        let unit = self.energy_as?;
        let si = |name: Option<&str>, d: Dimension| {
            name.and_then(|n| lookup(n, d).ok())
                .map_or_else(|| crate::values::rational::int(1), Unit::si)
        };
        let m = si(self.mass, Dimension::Mass);
        let v = si(self.velocity, Dimension::Velocity);
        let joules = unit.joules.parse::<Number>().ok()?.exact();
        Some(m * &v * &v / joules)
    }

    /// "ton mph^2", or the generic description when no units were given.
    pub fn energy(&self) -> String {
        if let Some(u) = self.energy_as {
            return u.name.to_string();
        }
        match (self.mass, self.velocity) {
            (Some(m), Some(v)) => {
                if m == "kg" && v == "m/s" {
                    "J".into()
                } else {
                    format!("{m} {}", squared(v))
                }
            }
            (Some(m), None) => format!("{m} x (velocity unit)^2"),
            (None, Some(v)) => format!("(mass unit) {}", squared(v)),
            (None, None) => "mass unit x velocity unit^2".into(),
        }
    }
}

/// `(m/s)^2` (an energy's velocity part; `m/s^2` would be an acceleration), `mph^2`.
fn squared(v: &str) -> String {
    if v.contains('/') {
        format!("({v})^2")
    } else {
        format!("{v}^2")
    }
}

impl Units {
    /// "N" for kg and m/s, else the impulse unit per second.
    pub fn force(&self) -> String {
        if self.force_scale().is_some() {
            "N".into()
        } else {
            format!("{} per second", self.impulse())
        }
    }

    /// The factor from the case's force unit (mass unit x velocity unit per second) to newtons,
    /// when both units are given: forces print in N whatever the units typed (issue 27: "1423000
    /// in g m/s per second" was 1.423 kN).
    pub fn force_scale(&self) -> Option<Q> {
        let m = lookup(self.mass?, Dimension::Mass).ok()?;
        let v = lookup(self.velocity?, Dimension::Velocity).ok()?;
        Some(m.si() * v.si())
    }

    /// The size of the case's energy unit (mass unit x velocity unit^2) in joules, when both
    /// units are given.
    pub fn energy_si(&self) -> Option<Q> {
        let v = lookup(self.velocity?, Dimension::Velocity).ok()?.si();
        Some(self.force_scale()? * v)
    }

    /// "kg m/s" (momentum, impulse), or the generic description.
    pub fn impulse(&self) -> String {
        match (self.mass, self.velocity) {
            (Some(m), Some(v)) => format!("{m} {v}"),
            (Some(m), None) => format!("{m} x velocity unit"),
            (None, Some(v)) => format!("mass unit x {v}"),
            (None, None) => "mass unit x velocity unit".into(),
        }
    }
}

/// Why a case's units cannot be resolved.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ResolveError {
    #[error("give a unit for every {} or for none (some have one, some not)", .0.name())]
    Mixed(Dimension),
    #[error("--si needs a unit on every mass and velocity")]
    SiNeedsUnits,
    #[error("mixed units need a unit on every mass and velocity")]
    MixedNeedsUnits,
    #[error(transparent)]
    Number(#[from] NumberError),
}

/// Resolved masses and velocities, with their units.
pub type Resolved = (Vec<Given<Number>>, Vec<Given<Number>>, Units);

/// Resolves a case's quantities: keeps the numbers when all masses share a unit (or none has one)
/// and all velocities share one, unless `si`; otherwise converts everything exactly to kg and m/s.
/// `?` placeholders stay unknown.
pub fn resolve(
    masses: &[Given<Quantity>],
    velocities: &[Given<Quantity>],
    si: bool,
) -> Result<Resolved, ResolveError> {
    fn common(
        qs: &[Given<Quantity>],
        dimension: Dimension,
    ) -> Result<(bool, Option<&'static Unit>), ResolveError> {
        // A bare 0 is 0 in any unit (`72 km/h,0`).
        let given: Vec<&Quantity> = qs
            .iter()
            .filter_map(Given::known)
            .filter(|q| !(q.unit.is_none() && q.number.value() == 0.0))
            .collect();
        let with = given.iter().filter(|q| q.unit.is_some()).count();
        if with != 0 && with != given.len() {
            return Err(ResolveError::Mixed(dimension));
        }
        let first = given.iter().find_map(|q| q.unit);
        let shared = given
            .iter()
            .all(|q| q.unit.map(Unit::name) == first.map(Unit::name));
        Ok((shared, first))
    }
    let (mass_shared, mass_unit) = common(masses, Dimension::Mass)?;
    let (vel_shared, vel_unit) = common(velocities, Dimension::Velocity)?;
    let any_unit = mass_unit.is_some() || vel_unit.is_some();
    let convert = si || !mass_shared || !vel_shared;
    if convert && (mass_unit.is_none() || vel_unit.is_none()) {
        return Err(if si {
            ResolveError::SiNeedsUnits
        } else {
            ResolveError::MixedNeedsUnits
        });
    }
    let to = |qs: &[Given<Quantity>]| -> Result<Vec<Given<Number>>, ResolveError> {
        qs.iter()
            .map(|q| match q {
                Given::Unknown => Ok(Given::Unknown),
                Given::Wall => Ok(Given::Wall),
                Given::Known(q) if convert => {
                    let si = q.number.exact()
                        * q.unit
                            .map(Unit::si)
                            .unwrap_or_else(|| crate::values::rational::int(1));
                    // A decimal when the converted value has one (10 g is 0.01 kg, not 1/100).
                    Ok(Given::Known(crate::values::quantity::number_of(&si)?))
                }
                Given::Known(q) => Ok(Given::Known(q.number.clone())),
            })
            .collect()
    };
    let units = if convert {
        Units {
            mass: Some("kg"),
            velocity: Some("m/s"),
            energy_as: None,
        }
    } else if any_unit {
        Units {
            mass: mass_unit.map(Unit::name),
            velocity: vel_unit.map(Unit::name),
            energy_as: None,
        }
    } else {
        Units::default()
    };
    Ok((to(masses)?, to(velocities)?, units))
}

/// Two values as typed (`M1,M2`, `V1,V2`, `F1,F2`): numbers with optional units, or `?`.
#[derive(Clone, Debug, PartialEq)]
pub struct Pair(pub [Given<Quantity>; 2]);

/// Why a text is not a pair of quantities.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PairError {
    #[error(transparent)]
    Fields(#[from] FieldsError),
    /// A bad value, named by its dimension when the message starts with it (`mass 'abc' ...`).
    #[error("{}", value_message(*.dimension, .error))]
    Value {
        dimension: Dimension,
        error: QuantityError,
    },
}

fn value_message(dimension: Dimension, e: &QuantityError) -> String {
    let e = e.to_string();
    if e.starts_with('\'') {
        format!("{} {e}", dimension.name())
    } else {
        e
    }
}

/// Parses `a,b` where each is `?` or a number with an optional unit; `what` names them.
pub fn parse_pair(text: &str, dimension: Dimension, what: &str) -> Result<Pair, PairError> {
    let [a, b] = split_fields::<2>(text, what)?;
    let one = |t: &str| {
        let parsed = if dimension == Dimension::Mass {
            Given::parse_mass(t, |t| parse(t, dimension))
        } else {
            Given::parse(t, |t| parse(t, dimension))
        };
        parsed.map_err(|error| PairError::Value { dimension, error })
    };
    Ok(Pair([one(a)?, one(b)?]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parsing_quantities() {
        let q = parse("4 t", Dimension::Mass).unwrap();
        assert_eq!((q.number.value(), q.unit.map(Unit::name)), (4.0, Some("t")));
        let q = parse("60mph", Dimension::Velocity).unwrap();
        assert_eq!(
            (q.number.value(), q.unit.map(Unit::name)),
            (60.0, Some("mph"))
        );
        let q = parse("72 km/h", Dimension::Velocity).unwrap();
        assert_eq!(q.unit.map(Unit::name), Some("km/h"));
        let q = parse("2/3 m/s", Dimension::Velocity).unwrap();
        assert_eq!(q.number.value(), 2.0 / 3.0);
        let q = parse("1e3kg", Dimension::Mass).unwrap();
        assert_eq!(q.number.value(), 1000.0);
        assert_eq!(parse("4", Dimension::Mass).unwrap().unit, None);
        assert_eq!(
            parse("1 long ton", Dimension::Mass)
                .unwrap()
                .unit
                .map(Unit::name),
            Some("long ton")
        );
    }

    #[test]
    fn slides_are_heights_of_mu_d() {
        // 'slide 5 cm mu 0.62': v^2 = 2 mu g d = 2 g (0.62 0.05), the height 0.031 m, signed.
        let h = |t: &str| parse(t, Dimension::Velocity).map(|q| (q.number.exact(), q.height));
        let q = |s: &str| s.parse::<Number>().unwrap().exact();
        assert_eq!(h("slide 5 cm mu 0.62"), Ok((q("0.031"), true)));
        assert_eq!(h("-slide 2 ft mu 1/2"), Ok((q("-0.3048"), true)));
        for bad in [
            "slide 5 cm",
            "slide 5 cm mu 0",
            "slide -5 cm mu 1",
            "slide 5 kg mu 1",
        ] {
            assert!(h(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn unknown_and_ambiguous_units_say_what_to_write() {
        let e = parse("60 mhp", Dimension::Velocity)
            .unwrap_err()
            .to_string();
        assert!(e.contains("did you mean 'mph'"), "{e}");
        let e = parse("4 T", Dimension::Mass).unwrap_err().to_string();
        assert!(
            e.contains("ambiguous") && e.contains("'t'") && e.contains("'ton'"),
            "{e}"
        );
        let e = parse("4 mph", Dimension::Mass).unwrap_err().to_string();
        assert!(e.contains("unit of velocity, not of mass"), "{e}");
        let e = parse("abc", Dimension::Mass).unwrap_err().to_string();
        assert!(e.contains("'abc' is not a number"), "{e}");
    }

    #[test]
    fn resolution_keeps_shared_units_and_converts_mixed_ones() {
        let q = |s: &str, d| Given::Known(parse(s, d).unwrap());
        use Dimension::*;
        let (m, v, u) = resolve(
            &[q("4 ton", Mass), q("1 ton", Mass)],
            &[q("60 mph", Velocity), q("10 mph", Velocity)],
            false,
        )
        .unwrap();
        assert_eq!(m[0].known().unwrap().value(), 4.0);
        assert_eq!(v[1].known().unwrap().value(), 10.0);
        assert_eq!(u.energy(), "ton mph^2");
        // Mixed: 1500 kg and 1 t -> 1500 and 1000 kg; 72 km/h -> 20 m/s exactly.
        let (m, v, u) = resolve(
            &[q("1500 kg", Mass), q("1 t", Mass)],
            &[q("72 km/h", Velocity), q("0 km/h", Velocity)],
            false,
        )
        .unwrap();
        assert_eq!(
            (m[0].known().unwrap().value(), m[1].known().unwrap().value()),
            (1500.0, 1000.0)
        );
        assert_eq!(v[0].known().unwrap().value(), 20.0);
        assert_eq!(u.energy(), "J");
        // --si: 60 mph = 26.8224 m/s exactly.
        let (_, v, _) = resolve(
            &[q("4 t", Mass), q("1 t", Mass)],
            &[q("60 mph", Velocity), q("10 mph", Velocity)],
            true,
        )
        .unwrap();
        assert_eq!(
            v[0].known().unwrap().exact(),
            "26.8224".parse::<Number>().unwrap().exact()
        );
        let e = resolve(
            &[q("4 t", Mass), q("1", Mass)],
            &[q("1", Velocity), q("2", Velocity)],
            false,
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("every mass or for none"), "{e}");
        // A bare 0 takes any unit.
        let (_, v, u) = resolve(
            &[q("1500 kg", Mass), q("900 kg", Mass)],
            &[q("72 km/h", Velocity), q("0", Velocity)],
            false,
        )
        .unwrap();
        assert_eq!(
            (v[1].known().unwrap().value(), u.energy()),
            (0.0, "kg (km/h)^2".to_string())
        );
        let (_, _, u) = resolve(
            &[q("4", Mass), q("1", Mass)],
            &[q("1", Velocity), q("2", Velocity)],
            false,
        )
        .unwrap();
        assert_eq!(u.energy(), "mass unit x velocity unit^2");
    }
}
