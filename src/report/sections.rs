//! The sections a report can show (`--show`, `show = [...]` in a scene), and what they need
//! beyond the case (contact time, heights, units, what a homework problem asks).

use std::collections::BTreeSet;

use serde::Deserialize;

use super::asked;
use crate::values::rational::Q;

/// A section of the report (`--show`, `show = [...]` in a scene).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Deserialize)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum Section {
    /// IN, COM and FIN vectors and V_COM
    Vectors,
    /// P = M.V at IN and FIN, P_total and the momentum line
    Momentum,
    /// The quadratic forms V.M.V
    Forms,
    /// Kinetic energies, crunch energy, energy lost
    Energy,
    /// Radii (and axes) of the IN, FIN and COM energy ellipses
    Ellipses,
    /// Plain dot product V_FIN.V_IN and outer product V_IN (x) V_FIN
    Products,
    /// Per body: dv, impulse, KE before and after; fraction of KE lost or transferred; average force (--contact-time)
    Changes,
    /// The height each IN and FIN speed corresponds to, v^2 / 2g (how high a pendulum swings or a ball rebounds)
    Heights,
    /// With --friction MU: how far each body slides after the collision before friction stops it, f^2 / (2 mu g)
    Slides,
    /// Self-check: residuals of momentum and energy conservation, and the solve's run time
    Diagnostics,
    /// In the plane or in space: the angle between the final velocities, how far each body turned
    Angles,
    /// Rigid bodies: how high a body on a pivot swings after the impact under --gravity (the
    /// angle and the rise of its centre), or that it goes over the top
    Swing,
    /// Rigid bodies: the speed a round body sliding on the floor after the impact starts to
    /// roll at; with --floor-friction the time and distance to get there
    Rolling,
    /// Every physics section (not diagnostics, whose timing varies run to run)
    All,
}

impl Section {
    pub const EVERY: [Section; 7] = [
        Section::Vectors,
        Section::Momentum,
        Section::Forms,
        Section::Energy,
        Section::Ellipses,
        Section::Products,
        Section::Changes,
    ];
    /// The design card's default: IN/COM/FIN vectors, quadratic forms and the crunch energy.
    pub const DEFAULT: [Section; 3] = [Section::Vectors, Section::Forms, Section::Energy];

    /// The JSON key this section's values live under (`vectors` are at the top level).
    pub fn json_keys(self) -> &'static [&'static str] {
        match self {
            Section::Vectors => &["in", "com", "fin", "v_com", "approaching", "left"],
            Section::Momentum => &["momentum"],
            Section::Forms => &["forms"],
            Section::Energy => &["energy"],
            Section::Ellipses => &["ellipses"],
            Section::Products => &["products"],
            Section::Changes => &["changes"],
            Section::Heights => &["heights"],
            Section::Slides => &["slides"],
            Section::Diagnostics => &["diagnostics"],
            Section::Angles => &["angle_between_deg"],
            Section::Swing => &["swing"],
            Section::Rolling => &["rolling"],
            Section::All => &[],
        }
    }

    /// The section a top-level JSON key belongs to (`None` for `inertia` and `restitution`, which
    /// are always present).
    pub fn of_json_key(key: &str) -> Option<Section> {
        Section::EVERY
            .into_iter()
            .chain([Section::Heights, Section::Slides, Section::Diagnostics])
            .find(|s| s.json_keys().contains(&key))
    }
}

/// A set of sections, with `all` expanded, and what the sections need beyond the case.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Sections {
    set: BTreeSet<Section>,
    /// The contact time in seconds, for the average forces of `changes` (`--contact-time`).
    pub contact_time: Option<Q>,
    /// `g` and the velocity unit, for `heights`.
    pub heights: Option<crate::values::units::HeightScale>,
    /// The factor from the case's energy unit to the printed one (`--energy-unit`).
    pub energy_scale: Option<Q>,
    /// The factor from the case's force unit to newtons (`Units::force_scale`).
    pub force_scale: Option<Q>,
    /// What a homework problem asks beyond these sections (`--spring`).
    pub asked: asked::Asked,
    /// `g` for a rigid body's swing and slide (`--gravity`; default: standard gravity).
    pub gravity: Option<Q>,
    /// The floor's kinetic friction under a body sliding to rolling (`--floor-friction`).
    pub floor_friction: Option<Q>,
}

impl Sections {
    pub fn new(list: impl IntoIterator<Item = Section>) -> Sections {
        let mut set = BTreeSet::new();
        for s in list {
            if s == Section::All {
                set.extend(Section::EVERY);
            } else {
                set.insert(s);
            }
        }
        Sections {
            set,
            contact_time: None,
            heights: None,
            energy_scale: None,
            force_scale: None,
            asked: asked::Asked::default(),
            gravity: None,
            floor_friction: None,
        }
    }
    pub fn contains(&self, s: Section) -> bool {
        self.set.contains(&s)
    }
    pub fn insert(&mut self, s: Section) {
        self.set.extend(Sections::new([s]).set);
    }
}
