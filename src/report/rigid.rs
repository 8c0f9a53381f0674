//! The report of a rigid impact (`rigid::outcome`): the impulse at the contact and how the
//! contact slid, the 1D-equivalent collision along the normal in the lecture's notation (IN, COM,
//! FIN, crunch with the effective masses), velocities and spins before and after, momentum and
//! angular momentum about a stated point, the explicit inertia tensor with the Jacobian rows and
//! the collision matrix, energies split into translation and rotation, and the ODE's error
//! estimate and run time in space; as text (fitting the terminal: `crate::values::terminal`) and as JSON.
//!
//! Values are exact and rounded once here (`--exact`: fractions, `≈` for 40-digit values).
//! Energy created is never printed as physics: the report says why it is not (Kane's paradox).

use std::fmt::Write;

use crate::rigid::algebra::Mat;
use crate::rigid::body::{Body, Mobility};
use crate::rigid::join::Joined;
use crate::rigid::laws::{Mode, Tangential};
use crate::rigid::outcome::{Energy, Outcome};
use crate::rigid::units::rpm;
use crate::values::number::num;
use crate::values::rational::{Q, to_f64};
use crate::values::units::Units;

use super::space::{Overflow, Style, vector};
use super::text::{Block, wrap};
use super::{Section, Sections};

pub mod after;
mod json;
pub mod solved;

pub use json::{KEYS, json};

/// Text lines fit the terminal: 80 columns, or `COLUMNS`, or no limit with `--wide`.
fn width() -> usize {
    crate::values::terminal::width()
}

/// The sections a rigid report shows by default (the impulse, the contact and the collision
/// along the normal are always shown).
pub const DEFAULT: [Section; 2] = [Section::Vectors, Section::Energy];

/// The sections that mean something for rigid bodies (`forms`: the inertia tensor, the Jacobian
/// rows and the collision matrix).
pub const SECTIONS: [Section; 7] = [
    Section::Vectors,
    Section::Momentum,
    Section::Forms,
    Section::Energy,
    Section::Swing,
    Section::Rolling,
    Section::All,
];

/// The case's units: SI when any value had a unit (then `units` has kg and m/s, and maybe an
/// energy unit), else the numbers as typed.
#[derive(Clone, Debug, PartialEq)]
pub struct RigidUnits {
    pub si: bool,
    pub units: Units,
}

impl RigidUnits {
    /// SI (kg, m/s) when `si`, else the numbers as typed; no energy unit.
    pub fn new(si: bool) -> RigidUnits {
        let units = if si {
            Units {
                mass: Some("kg"),
                velocity: Some("m/s"),
                energy_as: None,
            }
        } else {
            Units::default()
        };
        RigidUnits { si, units }
    }

    fn suffix(&self, unit: &str) -> String {
        if self.si {
            format!(" {unit}")
        } else {
            String::new()
        }
    }
}

/// What is said, in place of a report, of bodies that do not approach at the contact (`n.w =
/// along`, `w` the relative velocity of the contact points): `collide solve` and the page.
pub fn not_approaching(along: &impl std::fmt::Display) -> String {
    format!(
        "Note: the bodies do not approach at the contact: n.w = {along} <= 0 (w the relative \
         velocity of the contact points), so they do not collide (no FIN)."
    )
}

/// The text of a body's kind: "a point particle", "rod 1.2 m on a pivot at (0, -0.6)".
fn describe_body(b: &Body, style: &Style, approx: bool, u: &RigidUnits) -> String {
    let m = u.suffix("m");
    let shape = b
        .shape
        .as_ref()
        .map(|s| {
            let sizes: Vec<String> = s.sizes.iter().map(|x| style.show(x, approx)).collect();
            if sizes.len() == 1 {
                format!("a {} {}{m}", s.kind.name(), sizes[0])
            } else {
                format!("a {} ({}){m}", s.kind.name(), sizes.join(", "))
            }
        })
        .unwrap_or_else(|| match b.inertia() {
            Some(_) => "a rigid body".into(),
            None => "a point particle".into(),
        });
    match &b.mobility {
        Mobility::Immovable { word } => format!("a {word} (immovable)"),
        Mobility::Pivoted { pivot, .. } => {
            format!("{shape} on a pivot at {}{m}", vector(style, pivot, approx))
        }
        Mobility::Free { .. } => shape,
    }
}

/// A matrix as rows `[a, b; c, d]`.
fn matrix(style: &Style, m: &Mat, approx: bool) -> String {
    let rows: Vec<String> = m
        .iter()
        .map(|r| {
            r.iter()
                .map(|x| style.show(x, approx))
                .collect::<Vec<_>>()
                .join(", ")
        })
        .collect();
    format!("[{}]", rows.join("; "))
}

/// The header: bodies, contact, laws, units.
pub fn header(o: &Outcome, style: &Style, u: &RigidUnits) -> String {
    let a = o.approx();
    let p = &o.problem;
    let mut out = format!(
        "Rigid impact {}: 2 bodies\n",
        if o.dim() == 2 {
            "in the plane"
        } else {
            "in space"
        }
    );
    for (i, b) in o.bodies().iter().enumerate() {
        let mass = match &b.mass {
            Some(m) => format!("m{} = {}{}, ", i + 1, style.show(m, a), u.suffix("kg")),
            None => String::new(),
        };
        let inertia = match (&b.mobility, b.inertia()) {
            (Mobility::Pivoted { about_pivot, .. }, _) => format!(
                ", I_p = {}{}",
                matrix_or_scalar(style, about_pivot, a),
                u.suffix("kg m^2")
            ),
            (_, Some(i)) => format!(
                ", I_cm = {}{}",
                matrix_or_scalar(style, i, a),
                u.suffix("kg m^2")
            ),
            _ => String::new(),
        };
        out.push_str(&wrap(
            &format!(
                "Body {}: {mass}{}{inertia}, centre at {}{}",
                i + 1,
                describe_body(b, style, a, u),
                vector(style, &b.position, a),
                u.suffix("m")
            ),
            width(),
            "  ",
        ));
    }
    let c = &p.pair.contact;
    out.push_str(&wrap(
        &format!(
            "Contact at {}{}, normal n = {} (from body 1 to body 2)",
            vector(style, &c.point, a),
            u.suffix("m"),
            vector(style, &c.normal, false)
        ),
        width(),
        "  ",
    ));
    let e = style.show(&p.e, a);
    let kind = if p.e == Q::ONE {
        " (elastic)"
    } else if p.e.is_zero() {
        " (totally inelastic)"
    } else {
        ""
    };
    let laws = match &p.tangential {
        Tangential::Smooth => format!("e = {e}{kind}, no friction"),
        Tangential::Coulomb(mu) if mu.is_zero() => format!("e = {e}{kind}, no friction"),
        Tangential::Coulomb(mu) => format!(
            "e = {e}{kind}, friction mu = {}, law {} ({})",
            style.show(mu, a),
            p.law.name(),
            p.law.formula()
        ),
        Tangential::Rough { beta, mu } => format!(
            "Garwin's rough contact: e = {e}, beta = {} (v_n' = -e v_n, v_t' = -beta v_t){}",
            style.show(beta, a),
            mu.as_ref()
                .map(|m| format!(", friction limit mu = {}", style.show(m, a)))
                .unwrap_or_default()
        ),
        Tangential::Join => {
            "The bodies join: the ball stays at the contact point (e = 0, no slip: w' = 0)".into()
        }
    };
    out.push_str(&wrap(&laws, width(), "  "));
    if u.si {
        out.push_str(&wrap(
            &format!(
                "Units: SI (kg, m, m/s, rad/s, kg m^2), impulses in N s, energies in {}",
                u.units.energy()
            ),
            width(),
            "  ",
        ));
    }
    out
}

fn matrix_or_scalar(style: &Style, m: &Mat, approx: bool) -> String {
    if m.len() == 1 {
        style.show(&m[0][0], approx)
    } else {
        matrix(style, m, approx)
    }
}

/// A spin for people: the number (a vector in space), and in rpm when in rad/s.
fn spin(style: &Style, omega: &[Q], approx: bool, u: &RigidUnits) -> (String, String) {
    let value = format!("{}{}", vector(style, omega, approx), u.suffix("rad/s"));
    let note = if u.si && omega.len() == 1 && !omega[0].is_zero() {
        // Turns carry pi: in exact arithmetic an approximation.
        let mark = if style.exact { "≈" } else { "" };
        format!(
            "{mark}{} rpm",
            num(to_f64(&rpm(&omega[0])).unwrap_or(f64::NAN))
        )
    } else {
        String::new()
    };
    (value, note)
}

/// The report's sections as text.
pub fn text(
    o: &Outcome,
    show: &Sections,
    style: &Style,
    u: &RigidUnits,
) -> Result<String, Overflow> {
    let a = o.approx();
    let mut out = String::new();
    if let Some(why) = o.paradox() {
        out.push('\n');
        out.push_str(&wrap(&format!("NOT PHYSICAL: {why}."), width(), "  "));
    }
    impulse_block(o, style, u).render(&mut out);
    along_block(o, style, u).render(&mut out);
    if let Some(j) = Joined::of(o) {
        joined_block(o, &j, style, u).render(&mut out);
    }
    if show.contains(Section::Vectors) {
        let mut b = Block::new("Velocities and spins (IN, then FIN)");
        for (fin, ms) in [(false, o.v_in()), (true, &o.fin)] {
            let tick = if fin { "'" } else { "" };
            for (i, (body, m)) in o.bodies().iter().zip(ms).enumerate() {
                if body.immovable().is_some() {
                    continue;
                }
                b.row(
                    format!("v{}{tick}", i + 1),
                    format!("{}{}", vector(style, &m.v, a), u.suffix("m/s")),
                    "",
                );
                if body.inertia().is_some() || body.pivot().is_some() {
                    let (value, note) = spin(style, &m.omega, a, u);
                    b.row(format!("omega{}{tick}", i + 1), value, note);
                }
            }
        }
        b.render(&mut out);
    }
    if show.contains(Section::Momentum) {
        momentum_block(o, style, u).render(&mut out);
    }
    if show.contains(Section::Forms) {
        forms_block(o, style).render(&mut out);
    }
    if show.contains(Section::Energy) {
        energy_block(o, style, u).render(&mut out);
    }
    if let Some(s) = after::swing(o, show) {
        after::swing_block(o, &s, show, style, u).render(&mut out);
    }
    if let Some(r) = after::rolling(o, show) {
        after::rolling_block(o, &r, style, u).render(&mut out);
    }
    if let Some(ode) = &o.impact.ode {
        let _ = write!(
            out,
            "\n{}",
            wrap(
                &format!(
                    "ODE in the normal impulse (slip turning in the tangent plane): tsit45 at \
                     rtol {} (checked at {}), {} steps{}; error estimate {} (relative, of the \
                     impulse); run time {}",
                    sci(ode.rtol),
                    sci(ode.rtol * 100.0),
                    ode.steps,
                    ode.run
                        .stick
                        .map(|s| format!(", the slip stopped at P_n = {}", num(s)))
                        .unwrap_or_default(),
                    sci(ode.error),
                    duration(ode.seconds)
                ),
                width(),
                "  ",
            )
        );
    }
    style.checked(out)
}

fn sci(x: f64) -> String {
    format!("{x:.1e}")
}

fn duration(s: f64) -> String {
    if s < 1e-3 {
        format!("{:.0} us", s * 1e6)
    } else {
        format!("{:.2} ms", s * 1e3)
    }
}

fn impulse_block(o: &Outcome, style: &Style, u: &RigidUnits) -> Block {
    let a = o.approx() || !o.normal_length().1;
    let ns = u.suffix("N s");
    let mut b = Block::new("Impulse at the contact (P on body 2, -P on body 1)");
    b.row(
        "P",
        format!("{}{ns}", vector(style, &o.impact.impulse, o.approx())),
        "",
    );
    b.row(
        "P_n",
        format!("{}{ns}", style.show(&o.normal_impulse(), a)),
        "normal part",
    );
    if o.impact.mode != Mode::Smooth || o.dim() == 3 {
        let t = o.tangential_impulse();
        b.row(
            "P_t",
            format!("{}{ns}", vector(style, &t, a)),
            if o.dim() == 2 {
                "along t = (-n_y, n_x)/|n|"
            } else {
                "tangential part"
            },
        );
    }
    if !matches!(
        o.problem.tangential,
        Tangential::Rough { .. } | Tangential::Join
    ) {
        b.row(
            "P_c",
            format!("{}{ns}", style.show(&o.compression_impulse(), a)),
            "at the end of compression",
        );
    }
    b.row("contact", o.impact.mode.name(), o.impact.mode.describe());
    if let Some(m) = o.effective_mass() {
        b.row(
            "m_eff = 1/K_nn",
            format!("{}{}", style.show(&m, o.approx()), u.suffix("kg")),
            "effective mass along n",
        );
    }
    for (i, pivot) in o.pivot_impulses().iter().enumerate() {
        if let Some(p) = pivot {
            let zero = crate::rigid::algebra::is_zero(p);
            b.row(
                format!("pivot {}", i + 1),
                format!("{}{ns}", vector(style, p, o.approx())),
                if zero {
                    "none: the centre of percussion"
                } else {
                    "from the pivot: m (v' - v) - P"
                },
            );
        }
    }
    if let Some(note) = &o.impact.note {
        b.row("note", "", note.clone());
    }
    b
}

fn along_block(o: &Outcome, style: &Style, u: &RigidUnits) -> Block {
    let n = o.along_normal();
    let a = o.approx() || !n.exact;
    let vs = u.suffix("m/s");
    let mut b =
        Block::new("Along the normal: the 1D collision of the contact points (effective masses)");
    // A wall, or a body its pivot holds along n, is immovable there (an infinite mass).
    let mass = |m: &Option<Q>| match m {
        Some(m) => format!("{}{}", style.show(m, o.approx()), u.suffix("kg")),
        None => "immovable".into(),
    };
    b.row(
        "masses",
        format!("{}, {}", mass(&n.masses[0]), mass(&n.masses[1])),
        "1/(n^T K_i n), n of unit length",
    );
    b.row(
        "IN",
        format!("{}{vs}", vector(style, &n.v_in, a)),
        "(v1n, v2n) of the contact points",
    );
    b.row(
        "COM",
        format!(
            "{}{vs}",
            vector(style, &[n.v_com.clone(), n.v_com.clone()], a)
        ),
        "",
    );
    b.row("FIN", format!("{}{vs}", vector(style, &n.fin, a)), "");
    let e = style.energy(&n.crunch);
    b.row(
        "crunch",
        format!("{}{}", style.show(&e, o.approx()), energy_unit(u)),
        "1/2 m_eff (v1n - v2n)^2",
    );
    if !matches!(o.impact.mode, Mode::Smooth | Mode::Joined) {
        b.row(
            "e along n",
            style.show(&o.restitution_along(), a),
            "-(v1n' - v2n') / (v1n - v2n)",
        );
    }
    b
}

/// The one body two joined bodies make, and the energy the joining took.
fn joined_block(o: &Outcome, j: &Joined, style: &Style, u: &RigidUnits) -> Block {
    let a = o.approx();
    let mut b = Block::new("The joined body (one rigid body after the impact)");
    b.row(
        "M",
        format!("{}{}", style.show(&j.mass, a), u.suffix("kg")),
        "m1 + m2",
    );
    b.row(
        "centre",
        format!("{}{}", vector(style, &j.centre, a), u.suffix("m")),
        "(m1 x1 + m2 x2)/M",
    );
    let (name, about) = match &j.pivot {
        Some(p) => ("I_p", format!("about the pivot {}", vector(style, p, a))),
        None => ("I_cm", "about the new centre".to_string()),
    };
    b.row(
        name,
        format!(
            "{}{}",
            matrix_or_scalar(style, &j.inertia, a),
            u.suffix("kg m^2")
        ),
        about,
    );
    b.row(
        "v_cm",
        format!("{}{}", vector(style, &j.v, a), u.suffix("m/s")),
        "P_FIN / M",
    );
    let (value, note) = spin(style, &j.omega, a, u);
    b.row("omega", value, note);
    let lost = match o.energy() {
        Energy::Lost(q) => q,
        _ => Q::ZERO,
    };
    b.row(
        "lost",
        format!("{}{}", style.show(&style.energy(&lost), a), energy_unit(u)),
        "KE_IN - KE_FIN",
    );
    b
}

fn energy_unit(u: &RigidUnits) -> String {
    if u.si {
        format!(" {}", u.units.energy())
    } else {
        String::new()
    }
}

fn momentum_block(o: &Outcome, style: &Style, u: &RigidUnits) -> Block {
    let a = o.approx();
    let mut b = Block::new("Momentum");
    let about = o.about();
    let rows = [
        (
            "P",
            [o.momentum(o.v_in()), o.momentum(&o.fin)],
            u.suffix("kg m/s"),
            String::new(),
            "changed by the impulse of a pivot or a wall",
        ),
        (
            "L",
            [
                o.angular(o.v_in(), &about.point),
                o.angular(&o.fin, &about.point),
            ],
            u.suffix("kg m^2/s"),
            format!("about {} {}", about.name, vector(style, &about.point, a)),
            "changed: impulses act away from this point",
        ),
    ];
    for (name, [before, after], unit, note, changed) in rows {
        b.row(
            format!("{name}_IN"),
            format!("{}{unit}", vector(style, &before, a)),
            note,
        );
        b.row(
            format!("{name}_FIN"),
            format!("{}{unit}", vector(style, &after, a)),
            if before == after { "the same" } else { changed },
        );
    }
    b
}

fn forms_block(o: &Outcome, style: &Style) -> Block {
    let a = o.approx();
    let pair = &o.problem.pair;
    let mut b = Block::new("The inertia tensor, the Jacobian rows and the collision matrix");
    let names: Vec<String> = o
        .bodies()
        .iter()
        .enumerate()
        .flat_map(|(i, body)| body.coordinate_names(i + 1))
        .collect();
    b.row(
        "u",
        format!("({})", names.join(", ")),
        "generalized velocity",
    );
    let blocks: Vec<String> = o
        .bodies()
        .iter()
        .filter(|body| body.coordinates() > 0)
        .map(|body| block_text(style, body, a))
        .collect();
    b.row("M", format!("diag({})", blocks.join(", ")), "");
    b.row(
        "J_n",
        vector(style, &pair.row(&pair.contact.normal), false),
        "n^T [J1, -J2]",
    );
    if o.dim() == 2 {
        b.row(
            "J_t",
            vector(style, &pair.row(&pair.tangent()), false),
            "t = (-n_y, n_x)",
        );
    }
    b.row(
        "K",
        matrix(style, &pair.collision_matrix(), a),
        "J M^-1 J^T, world axes",
    );
    b
}

/// A body's block of `M`: `m I, I` (free), `m I` (particle), `I_p` (pivoted).
fn block_text(style: &Style, body: &Body, a: bool) -> String {
    let m = body.mass.clone().unwrap_or_default();
    match &body.mobility {
        Mobility::Free { inertia } => {
            let mi = format!("{} I{}", style.show(&m, a), body.dim());
            match inertia {
                Some(i) => format!("{mi}, {}", matrix_or_scalar(style, i, a)),
                None => mi,
            }
        }
        Mobility::Pivoted { about_pivot, .. } => matrix_or_scalar(style, about_pivot, a),
        Mobility::Immovable { .. } => String::new(),
    }
}

fn energy_block(o: &Outcome, style: &Style, u: &RigidUnits) -> Block {
    let a = o.approx();
    let show = |q: &Q| style.show(&style.energy(q), a);
    let mut b = Block::new(format!(
        "Energy (translation + rotation{})",
        if u.si {
            format!(", in {}", u.units.energy())
        } else {
            String::new()
        }
    ));
    for (label, ms) in [("IN", o.v_in()), ("FIN", &o.fin)] {
        let parts = o.energies(ms);
        for (i, (t, r)) in parts.iter().enumerate() {
            if o.bodies()[i].immovable().is_some() {
                continue;
            }
            b.row(
                format!("KE{}_{label}", i + 1),
                show(&(t + r)),
                format!("= {} + {}", show(t), show(r)),
            );
        }
        b.row(format!("KE_{label}"), show(&o.kinetic(ms)), "");
    }
    match o.energy() {
        Energy::Lost(q) => b.row("lost", show(&q), "KE_IN - KE_FIN"),
        Energy::Kept => b.row("lost", show(&Q::ZERO), "energy kept"),
        Energy::Gained(q) => b.row("GAINED", show(&q), "not physical (see above)"),
    }
    b
}
