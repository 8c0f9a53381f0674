//! Text fits a terminal (issue 28, section 3): every line a representative command of each
//! subcommand prints, on stdout and stderr, errors and `--help` included, is at most 80 columns
//! with `COLUMNS` unset; a wider `COLUMNS` or `--wide` lets lines grow; and fitting only moves
//! words between lines, never cuts or changes one (the words printed at 80 columns are the words
//! printed with `--wide`).

use std::collections::BTreeSet;

use crate::common::collide_at_default_width;

/// One command per subcommand (and per kind of text each prints), none of them slow; quoted as
/// in a shell (`readme::CommandLine`).
const COMMANDS: &[&str] = &[
    "collide solve -m 6,1 -v 3,-4 -e 2/3",
    "collide solve -m 6,1 -v 3,-4 -e 2/3 --show all,heights --contact-time 2ms --reverse",
    "collide solve --inertia '4,0.5;0.5,1' -v 3,-4 --show all --frame com",
    "collide solve -m 6,1 -v 3,-4 -e 2/3 --exact --show all",
    "collide solve -m 4,1 -v 10,60",
    "collide solve -m 4,1 -v 10,60 --show vectors,forms",
    "collide solve -m '80.0 kg,?' -v 0,0 --fin '-0.500 m/s,10.0 m/s' --show all",
    "collide solve -m 'wall,0.5 kg' -v '0,-height 2 m' --fin '0,height 1.5 m' --show all,heights",
    "collide solve -m '4 ton,1 ton' -v '?,10 mph' --fin '40 mph,90 mph'",
    "collide solve -m 4,1 -v 60,10 --plot term",
    // Homework knowns and asks (issue 27): bodies typed in the other order, a pass-through on a
    // pendulum, an impulse, two ways pieces part, a spring, slides, an exact swing, refusals.
    "collide solve -m 1,4 -v 10,60 --show all",
    "collide solve -m '10 g,4.0 kg' -v 0,0 --fin '550 m/s,?' --show all",
    "collide solve -m '0.01 kg,2 kg' -v '500 m/s,0' --fin '?,height 0.1 m' --pass-through --length '5 m' --show all",
    "collide solve -m 3,2 -v 6,0 --impulse 12 -e 1/2",
    "collide solve -m '1200 kg,2400 kg' -v '4900 m/s,4900 m/s' --fin ?,? --released '7.11e8 J' --show all",
    "collide solve -m 2,5 -v 10,3 --spring 1120 --length 1 --show slides --friction 0.2 --exact",
    "collide solve -m 1,1 -v 5,0 --length 1 --gravity 10",
    "collide solve -m 1,1 -v 10,0 --length 1 --gravity 10",
    "collide solve -m 1,1 -v 4,0 --fin 5,? --pass-through",
    "collide frames -m 6,1 -v 3,-4 --reverse",
    "collide frames -m 4,1 -v 60,10 -e 2/3 --reverse",
    "collide scene scenarios/fig-1-3-elastic.toml",
    "collide scene scenarios/fig-1-3-elastic.toml scenarios/fig-2-3-ka-whump-exact.toml",
    "collide track -m 1,10000 -x 1,2 -v 0,-1 --left-wall 0",
    "collide track -m 1,2,3 -x 1,2,3 -v 1,0,-1 --left-wall 0 --right-wall 4 --max-collisions 10",
    "collide pi 3",
    "collide pi 20",
    "collide contact -m 1,1,1 -x 0,1,2 --sizes 1,1,1 -v 1,0,0 --law hertz",
    BACKSTOP,
    "collide accuracy --cases 2 --budget-ms 1",
    "collide sweep -m 4,1 -v 60,10 --vary e=0:1:3 --format text",
    "collide batch scenarios/cases.csv --format text --skip-bad",
    "collide plot -m 4,1 -v 60,10 --term",
    // The plane and space.
    "collide solve -m 1,1 -v (4,0),0 --normal 30deg",
    "collide solve -m 1,3 -v (1.5,2.25,3),0 --normal (1,2,2) --show all --reverse",
    "collide solve -m 1,1 -v (5,0),0 --fin '3 @ ?,?' -e 1",
    "collide frames -m 1,3 -v (1,2),0 --normal 45deg",
    "collide scene scenarios/plane-car-and-van.toml",
    // Several contacts at once (issue 42 section 4): 15-digit vectors in the tables.
    "collide solve -m 1,1,1 -v (3.8,0),0,0 --positions (0,0),(1.732,1),(1.732,-1) --radii 1,1,1 --sequential",
    "collide scene scenarios/contacts-rack.toml",
    // A chain of stages: exact, and binary64 with units (long decimals).
    "collide scene scenarios/stages-no-further.toml",
    "collide scene scenarios/stages-three-particles.toml",
    // Rigid bodies at impact (issue 26): a rod, a hinged door in SI units, a paradox, a rough
    // floor, Garwin's superball, the bodies do not approach, a scene in space (the ODE).
    "collide solve -m 1,4 -v 3,0 --target 'rod 2' --hit-at end --show all",
    DOOR,
    PARADOX,
    "collide solve -m 1,floor -v '(7,-1),0' --ball 'sphere 1' --friction 1/3 --show all",
    "collide solve -m 1,floor -v '(343,-1),0' --ball 'sphere 1' --tangential-restitution 1",
    "collide solve -m 1,4 -v -3,0 --target 'rod 2' --hit-at end",
    "collide scene scenarios/rigid-door-percussion.toml scenarios/rigid-garwin-table.toml",
    SPACE_ROLLING,
    // Errors: usage errors, bad values, long messages.
    "collide solve -m -v 60,10",
    "collide solve -m 4 1 -v 60,10",
    "collide solve -m 4,abc -v 1,2",
    "collide solve -m 1,1 -v 1e200,-1e200 --show energy",
    "collide solve -m 6,1 -v 3,-4 -e 0 --reverse",
    "collide batch scenarios/cases.csv --columns m1,m2,fin1,fin2",
    "collide track -m 1,1 -x 1 2 -v 0,0",
    "collide solve -m 1,4 -v 3,0 --target 'rod 2' --hit-at 5",
    "collide solve -m 1,4 -v 3,0 --target 'rod 2' --hit-at end --spin 2",
    // Help.
    "collide --help",
    "collide solve --help",
    "collide sweep --help",
    "collide track --help",
    "collide contact --help",
];

/// Two bodies against a stiff wall (two contacts, a wide table).
const BACKSTOP: &str = "collide contact -m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --right-wall 1.5 \
                        --damping 0.4 --wall-stiffness 1e6 --wall-zeta 1";

/// A ball hits a door hinged at its edge (SI units, exact: long fractions and a pivot's row).
const DOOR: &str = "collide solve -m '50 g,2 kg' -v '10 m/s,0' --target 'door 0.9 m' --pivot end \
                    --hit-at '0.6 m' --exact --show all";

/// Newton's law with friction creates energy (Kane's paradox): the long NOT PHYSICAL paragraph.
const PARADOX: &str = "collide solve -m 1,1 -v '(3,-1),0' --target 'box (2,4)' --hit-at -1 \
                       --friction 1/2 --law newton --exact --show all";

/// A rigid scene in space: the ODE's paragraph, with its run time.
const SPACE_ROLLING: &str = "collide scene scenarios/rigid-space-rolling.toml";

/// `collide ARGS...` as its arguments.
fn args(line: &str) -> Vec<String> {
    crate::readme::CommandLine::parse(line, std::path::Path::new("."))
        .expect("a collide command")
        .args
}

/// stdout and stderr of `args` with `COLUMNS` as given (`None`: unset).
fn run(args: &[String], columns: Option<&str>) -> (String, String) {
    let mut c = collide_at_default_width();
    if let Some(w) = columns {
        c.env("COLUMNS", w);
    }
    let out = c.args(args).output().unwrap();
    (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// The widest line of `text`, in characters, and the line.
fn widest(text: &str) -> (usize, &str) {
    text.lines()
        .map(|l| (l.chars().count(), l))
        .max()
        .unwrap_or((0, ""))
}

#[track_caller]
fn assert_fits(line: &str, columns: Option<&str>, limit: usize) {
    let (out, err) = run(&args(line), columns);
    for (stream, text) in [("stdout", &out), ("stderr", &err)] {
        let (w, widest) = widest(text);
        assert!(
            w <= limit,
            "{line}: a {stream} line of {w} > {limit} columns:\n{widest}\n\n{text}",
        );
    }
}

#[test]
fn every_subcommand_fits_80_columns_by_default() {
    // --work-precision here only: its times vary from run to run.
    let work = format!("{BACKSTOP} --work-precision --methods verlet,rk4,tsit45");
    for line in COMMANDS.iter().copied().chain([work.as_str()]) {
        assert_fits(line, None, 80);
    }
}

#[test]
fn a_wider_terminal_or_wide_lets_lines_grow_and_a_narrower_one_is_honoured() {
    let case = "collide solve -m 6,1 -v 3,-4 -e 2/3";
    let width = |line: &str, columns| widest(&run(&args(line), columns).0).0;
    let default = width(case, None);
    let wide = width(&format!("{case} --wide"), None);
    // The forms row "V_FIN.M.V_IN = V_IN.M.V_FIN  2.66...e-15  M is symmetric" is 100 wide; the
    // crunch row with its note 121.
    assert!(default <= 80, "{default}");
    let at_120 = width(case, Some("120"));
    assert!(at_120 > 80 && at_120 <= 120, "{at_120}");
    assert!(wide > 120, "{wide}");
    // --wide wins over COLUMNS; a COLUMNS that is not a number is ignored.
    assert_eq!(width(&format!("{case} --wide"), Some("60")), wide);
    assert_eq!(width(case, Some("wide")), default);
    // 60 columns are kept where the numbers allow: these reports' longest words are 20.
    assert_fits(case, Some("60"), 60);
    assert_fits("collide frames -m 6,1 -v 3,-4 --reverse", Some("60"), 60);
    // So do rigid reports: the paradox's paragraph and its exact fractions grow and shrink.
    assert!(width(PARADOX, None) <= 80);
    let rigid_at_120 = width(PARADOX, Some("120"));
    assert!(rigid_at_120 > 80 && rigid_at_120 <= 120, "{rigid_at_120}");
    assert!(width(&format!("{PARADOX} --wide"), None) > 120);
    assert_fits(PARADOX, Some("60"), 60);
    assert_fits(DOOR, Some("60"), 60);
    // Help and errors follow COLUMNS as well.
    assert!(width("collide solve --help", Some("120")) > 80);
    assert_fits("collide solve --help", Some("60"), 60);
    let error = args("collide solve -m 1,1 -v 1e200,-1e200 --show energy");
    assert!(widest(&run(&error, Some("200")).1).0 > 80);
}

/// The words of `text` (runs of non-blanks).
fn words(text: &str) -> BTreeSet<&str> {
    text.split_whitespace().collect()
}

#[test]
fn fitting_moves_words_between_lines_and_never_cuts_or_changes_one() {
    // Not the timed reports (accuracy, pi's simulation, the ODE of a rigid scene in space), whose
    // times vary, nor help, whose wrapping of `[default: ...]` is clap's, nor the braille plot,
    // whose canvas is as wide as the terminal allows.
    let timed = [
        "collide accuracy",
        "collide pi ",
        "--help",
        "term",
        SPACE_ROLLING,
    ];
    for line in COMMANDS
        .iter()
        .filter(|l| !timed.iter().any(|t| l.contains(t)))
    {
        let (out, err) = run(&args(line), None);
        let (wide_out, wide_err) = run(&args(&format!("{line} --wide")), None);
        // A folded table repeats its first column: compare the sets of words.
        assert_eq!(
            words(&out),
            words(&wide_out),
            "{line}: stdout\n{out}\n--wide:\n{wide_out}"
        );
        assert_eq!(
            words(&err),
            words(&wide_err),
            "{line}: stderr\n{err}\n--wide:\n{wide_err}"
        );
    }
}

#[test]
fn a_narrow_terminal_is_honoured_by_contact_and_scene_summaries() {
    // Issue 45 §3: at COLUMNS=60, contact's `Work:` line was 62 wide and the scene status rows
    // 65 (a long path pushed the counts out).
    assert_fits(
        "collide contact -m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --zeta 0.2",
        Some("60"),
        60,
    );
    let scenes = "collide scene scenarios/bouncing-ball.toml \
                  scenarios/fig-3-4-vw-initially-at-rest.toml scenarios/fig-1-3-elastic.toml";
    assert_fits(scenes, Some("60"), 60);
    // At 80 the rows stay aligned: each count's slash in the same column.
    let (out, _) = run(&args(scenes), None);
    let columns: BTreeSet<usize> = out
        .lines()
        .filter(|l| l.starts_with("ok "))
        .map(|l| l.rfind('/').unwrap())
        .collect();
    assert!(
        out.lines().filter(|l| l.starts_with("ok ")).count() == 3,
        "{out}"
    );
    assert_eq!(columns.len(), 1, "{out}");
}

/// Many bodies' masses wrap at the width with the report's indent (60 bodies on a line ran to
/// 317 columns, 300 to 1,500), every mass still printed once, in order.
#[test]
fn many_bodies_masses_wrap_and_keep_every_mass() {
    let masses: Vec<String> = (1..=60).map(|i| format!("{i}.5")).collect();
    let velocities: Vec<&str> = std::iter::once("2")
        .chain(std::iter::repeat_n("0", 59))
        .collect();
    let line = format!(
        "collide solve -m {} -v {} -e 0",
        masses.join(","),
        velocities.join(",")
    );
    assert_fits(&line, None, 80);
    let (out, _) = run(&args(&line), None);
    let header: String = out
        .lines()
        .take_while(|l| !l.starts_with("e = "))
        .collect::<Vec<_>>()
        .join(" ");
    let listed: Vec<&str> = header
        .split("masses ")
        .nth(1)
        .unwrap()
        .split(',')
        .map(str::trim)
        .collect();
    assert_eq!(listed, masses, "{out}");
}
