//! The page's inputs as it holds them: text, as typed, in the command line's words, read by the
//! command line's own parsers when a panel solves them. Below the panels (`two_body`, `plane`,
//! `stack`) and the command lines and scenes built from them (`shell`), which all read them.

use serde::{Deserialize, Serialize};

/// The default restitution of an input: `collide solve`'s (no `-e`).
fn elastic() -> String {
    "elastic".into()
}

/// The default frame of an input.
fn lab() -> String {
    "lab".into()
}

/// A case as the page's inputs hold it: text, parsed by the command line's own parsers.
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct CaseInput {
    #[serde(default)]
    pub m1: String,
    #[serde(default)]
    pub m2: String,
    /// A general tensor `M11,M12;M21,M22` instead of the masses.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inertia: Option<String>,
    pub v1: String,
    pub v2: String,
    #[serde(default = "elastic")]
    pub e: String,
    #[serde(default = "lab")]
    pub frame: String,
    #[serde(default)]
    pub reverse: bool,
    /// Exact arithmetic (`--exact`): the report's numbers as fractions (the picture stays in
    /// binary64). The page does not send it; the Python module does.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub exact: bool,
}

/// Two pucks as the page's inputs hold them: text, read by the command line's own parsers.
/// The line of impact is `normal` (`30deg`, `(1,1)`, `N30E`), or the disks' radii `r1`, `r2`
/// with the impact parameter `b`, or neither (then only `e = 0`, the pucks stick, fixes FIN).
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PlaneInput {
    pub m1: String,
    pub m2: String,
    pub v1: String,
    pub v2: String,
    #[serde(default = "elastic")]
    pub e: String,
    #[serde(default)]
    pub normal: String,
    #[serde(default)]
    pub r1: String,
    #[serde(default)]
    pub r2: String,
    #[serde(default)]
    pub b: String,
    #[serde(default = "lab")]
    pub frame: String,
    #[serde(default)]
    pub reverse: bool,
    #[serde(default)]
    pub exact: bool,
    /// The page's choice of line of impact (`normal`, `disks` or `none`), when it sends one:
    /// a chosen line left empty is named as missing.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub line: String,
}

/// A layout as the page's inputs hold it, in `collide track`'s words; an empty text is a flag
/// not given.
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TrackInput {
    pub masses: String,
    pub positions: String,
    pub velocities: String,
    #[serde(default)]
    pub sizes: String,
    #[serde(default)]
    pub left_wall: String,
    #[serde(default)]
    pub right_wall: String,
    #[serde(default = "elastic")]
    pub e: String,
    #[serde(default)]
    pub e_wall: String,
    #[serde(default)]
    pub gravity: String,
    /// The end of the animation; empty: eight times the first collision's time.
    #[serde(default)]
    pub until: String,
}

/// The field whose typed numbers are the largest or smallest in size (the likeliest cause of a
/// result beyond binary64), by the exponent of each number in it.
pub fn largest_field(fields: &[(&'static str, &String)]) -> &'static str {
    let size = |text: &str| -> f64 {
        text.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == 'e' || c == 'E' || c == '-'))
            .filter_map(|w| w.trim_matches('-').parse::<f64>().ok())
            .filter(|x| *x != 0.0)
            .map(|x| x.abs().log10().abs())
            .fold(0.0, f64::max)
    };
    fields
        .iter()
        .map(|(f, text)| (*f, size(text)))
        .fold(("m1", -1.0), |best, x| if x.1 > best.1 { x } else { best })
        .0
}

/// A rigid impact as the page's inputs hold it, in `collide solve`'s words for the homework
/// shapes (docs/rigid.md): the ball (body 1) and the body it hits, `m2` a mass or `wall`,
/// `floor`, `ceiling`; an empty text is a flag not given.
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RigidInput {
    pub m1: String,
    pub m2: String,
    /// The ball's velocity: a number (along +x) or a vector `(vx,vy)`.
    pub v1: String,
    /// The target's velocity (free targets only), empty for at rest (`0`).
    #[serde(default)]
    pub v2: String,
    /// `--target`: `rod 2`, `door 0.9 m`, `disk 1`, ...
    #[serde(default)]
    pub target: String,
    /// `--pivot`: `end`, `centre`, `(x,y)`.
    #[serde(default)]
    pub pivot: String,
    /// `--hit-at`: the distance along the target, or `end`.
    #[serde(default)]
    pub hit_at: String,
    /// `--ball`: `sphere 1`, `shell 3 cm`.
    #[serde(default)]
    pub ball: String,
    /// `--spin`: `W1` or `W1,W2`.
    #[serde(default)]
    pub spin: String,
    #[serde(default = "elastic")]
    pub e: String,
    /// `--friction`: Coulomb's mu.
    #[serde(default)]
    pub friction: String,
    /// `--tangential-restitution`: Garwin's beta.
    #[serde(default)]
    pub beta: String,
    /// `--law`: `newton`, `poisson`, `stronge`.
    #[serde(default)]
    pub law: String,
}

/// Two to five pucks in the plane as the page's inputs hold them, one text per puck and list
/// (`collide solve`'s `-m`, `-v`, `--fin`, `--positions`, `--radii`, a puck's value each), and
/// how they meet (`mode`): `stick` (`-e 0`: one body after), `explode` (`--fin`, a `?` for the
/// velocity momentum gives) or `contacts` (touching balls: `--positions` and `--radii`, Newton's
/// law at every contact at once, with `e`).
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct NBodyInput {
    pub mode: String,
    pub masses: Vec<String>,
    pub velocities: Vec<String>,
    /// `explode`: the final velocities, `?` for unknown ones.
    #[serde(default)]
    pub fin: Vec<String>,
    /// `contacts`: each ball's centre `(x,y)` and radius, in one length unit.
    #[serde(default)]
    pub positions: Vec<String>,
    #[serde(default)]
    pub radii: Vec<String>,
    /// `contacts`: the restitution at every contact.
    #[serde(default = "elastic")]
    pub e: String,
}
