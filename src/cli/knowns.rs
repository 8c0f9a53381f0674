//! The flags of what a homework problem gives beyond masses, velocities and restitution, and
//! what it asks beyond the report's sections (`collide solve`, docs/homework.md).

use clap::Args;

/// What a homework problem gives beyond masses, velocities and restitution (docs/homework.md).
#[derive(Args, Debug, Clone, Default)]
pub struct KnownArgs {
    /// One body passes through the other (a bullet through a block): only momentum holds, the
    /// energy lost in the two bodies is reported, and e is no law
    #[arg(long, conflicts_with = "restitution", help_heading = "Homework knowns")]
    pub pass_through: bool,

    /// The impulse on body 2 (signed; on body 1 it is -J), e.g. 12, '12 N s', '2.4 kg m/s':
    /// a known that replaces one unknown (e is unknown unless given)
    #[arg(long, value_name = "J", allow_hyphen_values = true, help_heading = "Homework knowns",
          value_parser = |s: &str| collide::values::derived::parse(s, collide::values::derived::Kind::Impulse))]
    pub impulse: Option<collide::values::derived::Derived>,

    /// The energy released when bodies that start together are pushed apart (an explosion),
    /// e.g. '48 J', '7.11e8 J', or plain in the case's units: with --fin '?,?' (or no --fin)
    /// both ways the pieces can part are printed
    #[arg(long, value_name = "E", help_heading = "Homework knowns", allow_hyphen_values = true,
          conflicts_with_all = ["pass_through", "impulse", "restitution"],
          value_parser = |s: &str| collide::values::derived::parse(s, collide::values::derived::Kind::Energy))]
    pub released: Option<collide::values::derived::Derived>,

    /// A spring between the bodies, e.g. '1120 N/m' (N/m, kN/m, N/cm, lbf/in; plain: N/m):
    /// reports the maximum compression sqrt(2 crunch / k) and the contact time pi sqrt(mu / k)
    #[arg(long, value_name = "K", help_heading = "Homework knowns", allow_hyphen_values = true,
          value_parser = |s: &str| collide::values::derived::parse(s, collide::values::derived::Kind::Stiffness))]
    pub spring: Option<collide::values::derived::Derived>,

    /// The string of a pendulum, e.g. '5 m' or '80 cm' (plain: metres): the swing of each body
    /// at rest when hit (both when neither or both were), its angle acos(1 - h/L) and
    /// horizontal displacement L sin(theta), with h = f^2 / 2g
    #[arg(long, value_name = "L", help_heading = "Homework knowns", allow_hyphen_values = true,
          value_parser = |s: &str| collide::values::derived::length(s, "--length"))]
    pub length: Option<(collide::values::rational::Q, String)>,

    /// The total mass m1 + m2 with one mass given as '?', e.g. '12 kg' (in the masses' units):
    /// fixes that mass
    #[arg(long, value_name = "M", help_heading = "Homework knowns",
          value_parser = |s: &str| collide::values::units::parse(s, collide::values::units::Dimension::Mass))]
    pub total_mass: Option<collide::values::units::Quantity>,

    /// The relative speed of separation |f1 - f2|, e.g. '1.5 m/s' (in the velocities' units):
    /// e = |S| / |v1 - v2| (a separation from rest has no e)
    #[arg(long, value_name = "S", help_heading = "Homework knowns", allow_hyphen_values = true,
          conflicts_with = "restitution",
          value_parser = |s: &str| collide::values::units::parse_plain(s, collide::values::units::Dimension::Velocity))]
    pub separation_speed: Option<collide::values::units::Quantity>,
}

impl KnownArgs {
    /// What the report is asked beyond its sections, for a case in `units`.
    pub fn asked(
        &self,
        units: &collide::values::units::Units,
        g: &collide::values::rational::Q,
    ) -> collide::report::asked::Asked {
        let mut asked = collide::report::asked::Asked::in_units(units);
        asked.length = self.length.clone();
        asked.g = g.clone();
        asked.spring = self.spring.as_ref().map(|k| {
            let unit = if k.unit_si.is_none() { " N/m" } else { "" };
            (k.si(), format!("{}{unit}", k.text))
        });
        asked
    }

    /// The flag of the first output asked for (`--spring`, `--length`), for refusals; `apart`:
    /// of those a separation or pass-through cannot answer (a spring between bodies that
    /// do not collide).
    pub fn first_asked(&self, apart: bool) -> Option<&'static str> {
        let length = (!apart && self.length.is_some()).then_some("--length");
        self.spring.as_ref().map(|k| k.kind.flag()).or(length)
    }

    /// The knowns as the library takes them.
    pub fn knowns(&self) -> collide::line::problem::Knowns {
        collide::line::problem::Knowns {
            pass_through: self.pass_through,
            impulse: self.impulse.clone(),
            released: self.released.clone(),
            total_mass: self.total_mass.clone(),
            separation_speed: self.separation_speed.clone(),
        }
    }
}
