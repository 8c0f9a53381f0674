//! Scenes of stages (issue 27 §4): a chain of two-body collisions and bounces off walls, as in
//! the A-level problems solved in three steps by hand (A hits B; B rebounds from a wall; do they
//! meet again?). Each `[[stage]]` is a two-body scene of its own (masses, velocities, restitution,
//! units, `?` unknowns, `[stage.expect]`) and may take a velocity from an earlier stage's result:
//!
//! ```toml
//! exact = true
//! [[stage]]
//! masses = [2, 1]
//! velocities = [3, 0]
//! restitution = "1/2"
//! [stage.expect]
//! fin = ["3/2", 3]
//! [[stage]]
//! masses = [1, "wall"]
//! velocities = ["stage1.fin2", 0]
//! restitution = "1/3"
//! [expect]
//! collide_again = true
//! ```
//!
//! A reference is `NAME.fin1` or `NAME.fin2` (a stage's name, or `stageN` for the N-th), checked
//! when the file is read: the stage must come earlier (so no chain can loop), the value be a
//! body's (not a wall's), and the body's latest (one that collided since has a newer velocity).
//! Identity follows the references: a velocity taken from an earlier stage is the body that left
//! it; a typed velocity starts a new body. Solving carries each FIN into the stages that take it,
//! exactly (`exact = true`: fractions, never rounded) or as the binary64 value printed. Whether
//! each stage happens, whether the bodies keep their order ([`crate::line::chain`]) and whether
//! they meet again are decided in exact arithmetic in either mode.

mod joint;
mod linear;
mod range;
mod read;
mod solve;
mod system;

use std::path::Path;

use super::{About, SceneError};
use crate::expect::Expectation;
use crate::line::chain::{Meeting, Object};
use crate::line::problem::{Posed, Problem};
use crate::report::stages::Fixed;
use crate::report::{Section, Sections};
use crate::values::rational::Q;

pub use range::{Asked, SolvedRange};

/// Sections a stage prints unless `show` says otherwise: the vectors and the energies.
pub const STAGE_SHOW: [Section; 2] = [Section::Vectors, Section::Energy];

/// The most stages a scene holds (each is solved twice in binary64 mode, and a chain's exact
/// fractions grow with its length).
pub const MAX_STAGES: usize = 100;

/// Top-level keys of a chain's report (`[expect]` at the top addresses them).
pub const STAGES_KEYS: [&str; 7] = [
    "collide_again",
    "next",
    "after",
    "stages",
    "units",
    "system",
    "range",
];

/// A velocity taken from an earlier stage's result (`"stage1.fin2"`).
#[derive(Clone, Debug)]
pub struct Taken {
    /// The earlier stage (0-based) and which of its two it takes (0 or 1).
    pub stage: usize,
    pub body: usize,
    /// As written (`stage1.fin2`).
    pub text: String,
}

/// A stage, read and checked.
#[derive(Clone, Debug)]
pub struct Stage {
    /// As given, or `stageN`.
    pub name: String,
    /// 1-based line of the stage in its file.
    pub line: usize,
    /// Body 1 (on the left) and body 2: bodies or a wall.
    pub objects: [Object; 2],
    /// The velocities taken from earlier stages, by body.
    pub takes: [Option<Taken>; 2],
    /// The stage's problem; a taken velocity is `?` until the stage it comes from is solved.
    problem: Problem,
    show: Vec<Section>,
    contact_time: Option<Q>,
    pub expect: Vec<Expectation>,
}

/// A scene of `[[stage]]` tables, read and checked.
#[derive(Clone, Debug)]
pub struct StagesScene {
    /// The top-level `[expect]` addresses the chain's report (`collide_again`, `next`, ...).
    pub about: About,
    pub exact: bool,
    pub stages: Vec<Stage>,
    /// Each body's name (`A`, `B`, ... unless `bodies` names them), by its number.
    pub bodies: Vec<String>,
    /// The range asked (`condition`, one stage's `restitution = "?"`), when asked.
    pub range: Option<Asked>,
}

/// A stage solved in one arithmetic.
#[derive(Clone, Debug)]
pub struct StageRun {
    pub posed: Posed,
    /// FIN in this arithmetic, as an exact value (binary64: the printed value, exactly); a
    /// wall's entry is its own velocity.
    pub fin: [Q; 2],
    /// The sections to print, with the contact time and heights of the stage.
    pub show: Sections,
}

/// A chain solved: each stage in the scene's arithmetic, and what comes next.
#[derive(Clone, Debug)]
pub struct SolvedStages {
    pub runs: Vec<StageRun>,
    /// Each body's velocity after the last stage (in the scene's arithmetic) and the stage
    /// (0-based) it comes from, by body number.
    pub after: Vec<(Q, usize)>,
    /// Neighbours that approach after the last stage, decided exactly.
    pub meetings: Vec<Meeting>,
    /// Every pair of neighbours after the last stage, with `v_left - v_right` (of any sign).
    pub pairs: Vec<Meeting>,
    /// The velocity unit of every stage, when they have one.
    pub velocity_unit: Option<&'static str>,
    /// The taken velocities a later stage fixed (the chain solved as one system), exactly.
    pub fixed: Vec<Fixed>,
}

impl StagesScene {
    /// Whether scene text is of this kind: it has a `[[stage]]` table.
    pub fn is_stages(text: &str) -> bool {
        text.lines()
            .any(|l| l.trim_start().starts_with("[[stage]]"))
    }

    /// Reads a scene of stages; `path` names it in errors.
    pub fn parse(path: &Path, text: &str) -> Result<StagesScene, SceneError> {
        read::parse(path, text)
    }
}

impl Stage {
    /// Sections to compute for a collision: those shown and those the expectations read.
    pub fn sections_needed(&self, show: &Sections) -> Sections {
        super::needed(show, &self.expect)
    }
}

#[cfg(test)]
mod tests {
    use super::read::reference;
    use super::*;
    use crate::line::chain::Side;

    fn parse(text: &str) -> Result<StagesScene, SceneError> {
        StagesScene::parse(Path::new("s.toml"), text)
    }

    const FIRST: &str = "[[stage]]\nmasses = [2, 1]\nvelocities = [3, 0]\nrestitution = \"1/2\"\n";

    #[test]
    fn references_name_earlier_bodies_and_bodies_get_letters() {
        let s = parse(&format!(
            "{FIRST}[[stage]]\nname = \"wall\"\nmasses = [1, \"wall\"]\nvelocities = \
             [\"stage1.fin2\", 0]\n[[stage]]\nmasses = [2, 1]\nvelocities = [\"stage1.fin1\", \
             \"wall.fin1\"]\n"
        ))
        .unwrap();
        assert_eq!(s.bodies, ["A", "B"]);
        assert_eq!(s.stages[1].name, "wall");
        assert_eq!(s.stages[1].line, 5);
        assert_eq!(
            s.stages[1].objects,
            [Object::Body(1), Object::Wall(Side::Right)]
        );
        assert_eq!(s.stages[2].objects, [Object::Body(0), Object::Body(1)]);
        let t = s.stages[2].takes[1].as_ref().unwrap();
        assert_eq!((t.stage, t.body, t.text.as_str()), (1, 0, "wall.fin1"));
        // The chain carries 3 into the wall, which sends B back at -3 (elastic, the default);
        // A (3/2) catches it: momentum 2 (3/2) - 3 = 0, so V_COM = 0 and the elastic FIN is
        // 2 V_COM - IN = (-3/2, 3). Then B moves toward the wall (closing at 3), away from A.
        let solved = s.solve().unwrap();
        let q = |n: i64, d: i64| crate::values::rational::int(n) / crate::values::rational::int(d);
        assert_eq!(solved.after, [(q(-3, 2), 2), (q(3, 1), 2)]);
        assert_eq!(
            solved.meetings,
            [Meeting {
                left: Object::Body(1),
                right: Object::Wall(Side::Right),
                closing: q(3, 1)
            }]
        );
    }

    #[test]
    fn a_reference_is_a_name_a_dot_and_a_word() {
        assert_eq!(reference("stage1.fin2"), Some(("stage1", "fin2")));
        assert_eq!(reference(" wall.fin1 "), Some(("wall", "fin1")));
        for not in [
            "1.5",
            ".5",
            "4 m/s",
            "?",
            "height 2 m",
            "stage1.",
            "a.b.c",
            "1e3",
        ] {
            assert_eq!(reference(not), None, "{not}");
        }
    }

    #[test]
    fn bad_names_are_located() {
        let e = parse(&format!(
            "{FIRST}[[stage]]\nname = \"stage7\"\nmasses = [1, 1]\nvelocities = [1, 0]\n"
        ))
        .unwrap_err();
        assert!(
            e.message.contains("names another stage") && e.at.unwrap().0 == 6,
            "{e}"
        );
        let named = FIRST.replace("[[stage]]\n", "[[stage]]\nbodies = [\"A\", \"B\"]\n");
        let e = parse(&format!(
            "{named}[[stage]]\nbodies = [\"A\", \"C\"]\nmasses = [1, 1]\nvelocities = [1, 0]\n"
        ))
        .unwrap_err();
        assert!(e.message.contains("'A' already names a body"), "{e}");
        let e = parse(&format!("{named}[[stage]]\nbodies = [\"B\", \"floor\"]\nmasses = [1, \"wall\"]\nvelocities = [\"stage1.fin2\", 0]\n")).unwrap_err();
        assert!(e.message.contains("name it \"wall\""), "{e}");
        let e = parse("[[stage]]\nbodies = [\"A\", \"A\"]\nmasses = [1, 1]\nvelocities = [1, 0]\n")
            .unwrap_err();
        assert!(
            e.message.contains("'A' names both bodies of this stage"),
            "{e}"
        );
        let e = parse("title = \"no stages\"\nstage = []\n").unwrap_err();
        assert!(e.message.contains("no [[stage]]"), "{e}");
    }
}
