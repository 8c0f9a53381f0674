//! The flags of several contacts at once (`collide solve`, docs/plane.md): touching balls by
//! their positions and radii, or contacts named as pairs with their lines of impact.

use clap::Args;

/// Several contacts at once: balls that touch (docs/plane.md).
#[derive(Args, Debug, Clone, Default)]
pub struct BallsArgs {
    /// Centres of touching balls, one per body, e.g. '(0,0),(1.732,1),(1.732,-1)' (with
    /// --radii, one per ball): pairs within 0.1% of touching are contacts, solved at once
    #[arg(long, value_name = "(X,Y),...", allow_hyphen_values = true,
          help_heading = "Several contacts", conflicts_with_all = ["normal", "impact_parameter"])]
    pub positions: Option<String>,

    /// Contacts named as pairs with their lines of impact (from the first body to the
    /// second), e.g. '1-2 @ 30deg,1-3 @ -30deg' or '1-2 @ (1,0)'
    #[arg(long, value_name = "A-B @ N,...", allow_hyphen_values = true,
          help_heading = "Several contacts",
          conflicts_with_all = ["positions", "radii", "normal", "impact_parameter"])]
    pub contacts: Option<String>,

    /// Also show the sequential answer: the pairs collide one at a time, in the order of the
    /// contacts, until none approaches
    #[arg(long, help_heading = "Several contacts")]
    pub sequential: bool,
}

impl BallsArgs {
    /// Whether the case is one of several contacts.
    pub fn active(&self) -> bool {
        self.positions.is_some() || self.contacts.is_some() || self.sequential
    }
}
