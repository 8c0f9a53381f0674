//! The restitution laws of an impact with friction (physics.md section 7; Stronge, *Impact
//! Mechanics*, ch. 4): how the normal impulse ends once the bodies have stopped approaching. They
//! agree without friction and for central impacts; with friction and an off-centre contact
//! Newton's law can create energy (Kane's paradox; Stronge 1991, J. Appl. Mech. 58:1049), which
//! collide detects and says rather than prints as physics.

use crate::values::rational::Q;

/// A restitution law.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
#[serde(rename_all = "kebab-case")]
pub enum Law {
    /// Kinematic (Newton): the normal velocity after is -e times the one before
    Newton,
    /// Kinetic (Poisson): the restitution impulse is e times the compression impulse
    #[default]
    Poisson,
    /// Energetic (Stronge): e^2 = -(work of the normal force in restitution) / (work in
    /// compression); never creates energy
    Stronge,
}

impl Law {
    pub fn name(self) -> &'static str {
        match self {
            Law::Newton => "newton",
            Law::Poisson => "poisson",
            Law::Stronge => "stronge",
        }
    }

    /// The law as a formula, for the header.
    pub fn formula(self) -> &'static str {
        match self {
            Law::Newton => "v_n' = -e v_n",
            Law::Poisson => "P_n = (1 + e) P_c",
            Law::Stronge => "e^2 = -W_restitution / W_compression",
        }
    }
}

/// The law of the tangential impulse.
#[derive(Clone, Debug, PartialEq)]
pub enum Tangential {
    /// No friction: the impulse is normal.
    Smooth,
    /// Coulomb friction: `|P_t| <= mu P_n`, slip opposed.
    Coulomb(Q),
    /// Garwin's rough contact (Am. J. Phys. 37, 88, 1969): the slip velocity at the contact
    /// reverses to `-beta` times itself (`beta = 1`: the ideal superball), `v_n' = -e v_n`,
    /// within a friction limit `mu` when one is given.
    Rough { beta: Q, mu: Option<Q> },
    /// The bodies join (physics.md section 8): the striking particle lodges at the contact
    /// point and moves with the body it hit, so the relative velocity of the contact points
    /// after is zero, `w' = 0` (normal and tangential: `e = 0` and no slip), and
    /// `P = K^-1 w`. Linear momentum (free) and angular momentum about the pivot (pivoted)
    /// are kept by construction; it is the rail's `e = 0` along a normal through the centres.
    Join,
}

/// How the contact slid during the impact.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Mode {
    /// No friction: the impulse is along the normal.
    Smooth,
    /// Slip stopped and the contact stuck (or it never slipped).
    Stick,
    /// It slipped throughout, one way.
    Slip,
    /// Slip stopped and resumed the other way (in space: in another direction).
    Reverse,
    /// The bodies joined: one rigid body after (`--join`).
    Joined,
}

impl Mode {
    pub fn name(self) -> &'static str {
        match self {
            Mode::Smooth => "smooth",
            Mode::Stick => "stick",
            Mode::Slip => "slip",
            Mode::Reverse => "reverse",
            Mode::Joined => "joined",
        }
    }

    pub fn describe(self) -> &'static str {
        match self {
            Mode::Smooth => "no friction: the impulse is normal",
            Mode::Stick => "the slip stopped and the contact held",
            Mode::Slip => "it slid throughout, one way",
            Mode::Reverse => "the slip stopped, then reversed",
            Mode::Joined => "one rigid body after: w' = 0",
        }
    }
}
