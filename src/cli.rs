//! Command-line flags (clap derive). Values are parsed and validated here, at the edge, by the
//! library types' own parsers: a bad value is a usage error (exit 2) that names it and says what
//! is expected.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

mod balls;
mod knowns;
mod runs;
mod tables;
pub use balls::BallsArgs;
pub use knowns::KnownArgs;
pub use runs::*;
pub use tables::*;

use collide::line::case::parse_inertia;
use collide::line::frame::Frame;
use collide::line::inertia::InertiaTensor;
use collide::line::restitution::Restitution;
use collide::report::Section;
use collide::space::typed::Listed;
use collide::values::number::{Given, Number};
use collide::values::units::{Dimension, Quantity};

/// The exit statuses, for `collide --help` and the man page: the same words as the guide's table
/// (docs/cli.md, "Exit status"), which `tests/suite/shell.rs` compares with both.
pub const EXIT_STATUS: &str = "Exit status:
  0    success, also when the reader of the output stops early (collide ... | head)
  1    a check failed: a scene's [expect] numbers, or given values that contradict a law that \
was checked rather than used (solve and scene then print the checks and no collision)
  2    bad input or usage: a message on stderr names the bad value and says what is expected, \
and nothing is written to stdout
  130  interrupted by Ctrl-C (SIGINT) while writing a file (-o, --log, --plot): the unfinished \
file is removed first; another catchable signal N does the same and exits with 128+N (143 for \
SIGTERM)";

/// The lecture's words, for `collide --help` (the guide's introduction says the same,
/// docs/README.md#words): `(word, meaning)`.
pub const WORDS: [(&str, &str); 3] = [
    (
        "IN, COM, FIN",
        "the velocities before the collision, of the centre of mass (both bodies at V_COM), and \
         after it",
    ),
    (
        "crunch",
        "the kinetic energy of the motion relative to the centre of mass, KE_IN - KE_COM = 1/2 mu \
         (V1 - V2)^2: the most a collision can take; e^2 crunch of it comes back",
    ),
    (
        "ka-bong",
        "an elastic collision (e = 1); ka-whump: partly inelastic (0 < e < 1); ka-runch: \
         totally inelastic (e = 0, the bodies stick)",
    ),
];

#[derive(Parser, Debug)]
#[command(
    name = "collide",
    version,
    about = "Collisions on a rail, in the plane and in space, solved and printed in the notation \
             of Harter's 'Classical Mechanics with a BANG!', Lecture 1",
    after_help = EXIT_STATUS
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,

    /// Significant digits of numbers in text (1 to 17), or 'full' for the shortest form that
    /// reads back as the same binary64 [default: 15]; JSON and tables always carry full values
    #[arg(long, global = true, value_name = "N|full", value_parser = parse_sig)]
    pub sig: Option<u8>,

    /// Text as wide as it comes, a row a line; without it text fits the terminal's width:
    /// COLUMNS, else 80
    #[arg(long, global = true)]
    pub wide: bool,
}

/// `collide pi N`: a whole number of digits after the point, 0 to 10,000.
fn parse_pi_digits(s: &str) -> Result<u32, String> {
    let t = s.trim();
    match t.parse::<u32>() {
        Ok(n) if n <= 10_000 => Ok(n),
        _ if !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit()) => {
            Err("at most 10,000 digits after the point (the count has N + 1 digits)".into())
        }
        _ => Err(
            "expected a whole number of digits after the point, 0 to 10,000 (pi 5 \
                  gives 3.14159)"
                .into(),
        ),
    }
}

/// `--sig`: 1..=17 digits, or `full` (0).
fn parse_sig(s: &str) -> Result<u8, String> {
    match s.trim() {
        "full" => Ok(0),
        t => t
            .parse::<u8>()
            .ok()
            .filter(|d| (1..=17).contains(d))
            .ok_or_else(|| format!("'{t}': expected a number of digits from 1 to 17, or 'full'")),
    }
}

/// `--fin`: final velocities, a slide whose mu is unknown (`slide 20 cm mu ?`) read as `?` (the
/// collision solves it; `commands::solve` reads the slide again from the text as typed).
fn fin_listed(s: &str) -> Result<Listed, collide::space::typed::ListedError> {
    let masked = collide::line::slide::masked(s);
    let mut listed = Listed::parse(&masked, Dimension::Velocity, "final velocities F1,F2")?;
    if masked != s {
        listed.text = s.trim().to_string();
    }
    Ok(listed)
}

#[derive(Subcommand, Debug)]
#[allow(clippy::large_enum_variant)] // parsed once per run
pub enum Command {
    /// Solve one collision given on the command line
    #[command(after_help = "Examples:
  collide solve -m 6,1 -v 3,-4 -e 2/3
  collide solve -m 6,1 -v 3,-4 -e 2/3 --exact --show vectors,energy
  collide solve -m '4 ton,1 ton' -v '?,10 mph' --fin '40 mph,90 mph'
  collide solve -m 'wall,0.5 kg' -v '0,-height 2 m' \\
      --fin '0,height 1.5 m' --show vectors,heights
  collide solve -m '0.01 kg,2 kg' -v '500 m/s,0' --fin '?,height 0.1 m' \\
      --pass-through --length '5 m'
  collide solve -m '1 kg,2 kg' -v '0,0 m/s' --fin '?,?' --released '48 J'
  collide solve -m '50 g,2 kg' -v '10 m/s,0' --target 'door 0.9 m' \\
      --pivot end --hit-at '0.6 m'")]
    Solve(SolveArgs),
    /// Solve TOML scene files and check their [expect] numbers
    #[command(after_help = "Examples:
  collide scene scenarios/fig-1-3-elastic.toml
  collide scene scenarios/*.toml --format json")]
    Scene(SceneArgs),
    /// Error against run time: each method against exact arithmetic on seeded case families
    #[command(after_help = "Examples:
  collide accuracy --cases 16
  collide accuracy --plot accuracy.svg")]
    Accuracy(AccuracyArgs),
    /// The same collision in the standard Galilean frames (lecture Figs. 2.5 and 3.4)
    #[command(
        after_help = "Examples:
  collide frames -m 6,1 -v 3,-4 --reverse
  collide frames -m 4,1 -v 60,10 -e 2/3 --exact",
        mut_args(on_a_rail)
    )]
    Frames(FramesArgs),
    /// A table of collisions over a grid of parameters (--vary), one row each
    #[command(
        after_help = "Examples:
  collide sweep -m 4,1 -v 60,10 --vary e=0:1:11 \\
      --columns e,fin1,fin2,ke_fin,lost
  collide sweep -m 1,1 -v 1,0 --vary m2=1e-3:1e3:7:log \\
      --format jsonl -o sweep.jsonl",
        mut_args(on_a_rail)
    )]
    Sweep(SweepArgs),
    /// A table of collisions read from CSV or JSON Lines, one row each
    #[command(after_help = "Examples:
  collide batch scenarios/cases.csv --columns m1,m2,e,fin1,fin2,lost \\
      --skip-bad
  collide batch scenarios/cases.csv --skip-bad \\
      --format jsonl -o cases.jsonl
  collide batch scenarios/plane-cases.csv \\
      --columns nx,ny,fin1x,fin1y,between_deg,error")]
    Batch(BatchArgs),
    /// Repeated collisions of bodies on a track between walls (pi billiards, superball stacks)
    #[command(
        override_usage = "collide track [OPTIONS] -m <M1,M2,...> -x <X1,X2,...> -v <V1,V2,...>",
        after_help = "Examples:
  collide track -m 1,10000 -x 1,2 -v 0,-1 --left-wall 0
  collide track -m 1 -x 1 -v 0 --left-wall 0 --gravity 2 -e 0.5 \\
      --format json"
    )]
    Track(TrackArgs),
    /// Collisions in time: contact forces (linear spring-dashpot, Hertz, Hunt-Crossley)
    /// integrated through each impact, with the error of each method against its run time
    #[command(
        override_usage = "collide contact [OPTIONS] -m <M1,M2,...> -x <X1,X2,...> -v <V1,V2,...>",
        after_help = "Examples:
  collide contact -m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --zeta 0.2
  collide contact -m 1,1,1 -x 0,1,2 --sizes 1,1,1 -v 1,0,0 --law hertz
  collide contact -m 1,1 -x 0,1 --sizes 1,1 -v 1,0 --right-wall 1.5 \\
      --damping 0.4 --wall-stiffness 1e10 --wall-zeta 1 \\
      --work-precision --plot wpd.svg"
    )]
    Contact(ContactArgs),
    /// Pi from collisions: the exact count for mass ratio 100^N, which spells pi to N digits
    /// after the point (collide pi 5: 314159, 3.14159), simulated as well for N <= 10
    #[command(after_help = "Examples:
  collide pi 5
  collide pi 20 --no-simulate")]
    Pi(PiArgs),
    /// Draw the collision: the velocity-velocity diagram, or Newton's or Minkowski's space-time
    #[command(
        after_help = "Examples:
  collide plot -m 4,1 -v 60,10 -o case-a.svg
  collide plot -m 4,1 -v 60,10 --kind minkowski -o world-lines.svg
  collide plot -m 4,1 -v 60,10 --term",
        mut_args(no_unknowns)
    )]
    Plot(PlotArgs),
    /// Write the lecture's simulators as one web page that opens from disk: the velocity plane
    /// and space-time diagrams of a case, two pucks in the plane, and a superball stack,
    /// computed by collide itself
    #[command(after_help = "Examples:
  collide view -o case-a.html
  collide view -m 6,1 -v 3,-4 -e 2/3 --frame com -o fig-2-3.html
  collide view -m 1,1 -v '(1,0),(0,0)' --normal 30deg -o pucks.html
  collide view scenarios/superball-3.toml -o stack.html
  collide view track -m 1,0.01 -x 1.5,2.25 -v 0,0 --sizes 1,0.5 \\
      --left-wall 0 --gravity 9.81")]
    View(ViewArgs),
    /// Print a shell completion script (bash, zsh, fish, powershell, elvish)
    #[command(after_help = "Examples:
  collide completions bash \\
      > ~/.local/share/bash-completion/completions/collide
  collide completions zsh > ~/.zfunc/_collide  # fpath+=~/.zfunc; compinit
  collide completions fish > ~/.config/fish/completions/collide.fish")]
    Completions {
        /// The shell
        #[arg(value_enum)]
        shell: clap_complete::Shell,
    },
    /// Print the man page (roff): collide man | man -l -
    #[command(after_help = "Examples:
  collide man | man -l -
  collide man > ~/.local/share/man/man1/collide.1")]
    Man,
}

/// The case flags' help for the commands that take two bodies on a rail, given (frames, sweep,
/// plot): no `?` unknowns, no vectors, no line of impact (those are for solve and scenes).
fn on_a_rail(arg: clap::Arg) -> clap::Arg {
    match arg.get_id().as_str() {
        "masses" => arg.help("Masses M1,M2 (each > 0), e.g. 4,1 or 1.5e3,2/3 or '4 ton,1 ton'"),
        "velocities" => arg.help("Initial velocities V1,V2, e.g. 60,10 or 3,-4 or '72 km/h,0'"),
        "restitution" => arg.help(
            "Coefficient of restitution e >= 0: 'elastic' (1), 'inelastic' (0), above 1 \
             superelastic (energy released) [default: elastic]",
        ),
        "normal" | "radii" | "impact_parameter" => arg.hide(true),
        _ => arg,
    }
}

/// The case flags' help for `plot`, which draws a case given: no `?` unknowns.
fn no_unknowns(arg: clap::Arg) -> clap::Arg {
    match arg.get_id().as_str() {
        "masses" => arg.help(
            "Masses M1,M2 (each > 0), e.g. 4,1 or 1.5e3,2/3 or '4 ton,1 ton'; more than two \
             bodies: M1,M2,M3,...",
        ),
        "velocities" => arg.help(
            "Initial velocities V1,V2, e.g. 60,10 or 3,-4 or '72 km/h,0'; vectors in the plane: \
             '(4,1),(-1,0.5)', '6 m/s @ 30deg,0'",
        ),
        "restitution" => on_a_rail(arg),
        _ => arg,
    }
}

#[derive(Args, Debug)]
pub struct PlotArgs {
    #[command(flatten)]
    pub case: CaseArgs,

    /// Which picture [default: velocity; for vectors in the plane, the paths and momentum
    /// triangles]
    #[arg(long, value_enum)]
    pub kind: Option<collide::plot::Kind>,

    /// The frame to draw in: lab, com, rest-in:1, ..., or an observer velocity
    #[arg(long, default_value = "lab", allow_hyphen_values = true)]
    pub frame: Frame,

    /// Overlay the standard frames as 45-degree-shifted copies (lecture Fig. 2.5)
    #[arg(long)]
    pub frames: bool,

    /// Write the SVG to FILE [default: stdout]
    #[arg(short, long, value_name = "FILE.svg", conflicts_with = "term")]
    pub output: Option<PathBuf>,

    /// Draw in the terminal (Unicode braille) instead of SVG
    #[arg(long)]
    pub term: bool,

    #[command(flatten)]
    pub rigid: RigidArgs,
}

/// `collide view`: the case as typed (the page's inputs hold text; they are checked by the same
/// parsers as `solve`'s when the page is made), a scene, or a track layout.
#[derive(Args, Debug)]
#[command(args_conflicts_with_subcommands = true)]
pub struct ViewArgs {
    #[command(subcommand)]
    pub track: Option<ViewTrack>,

    /// A scene file to open with: a two-body case, two bodies in the plane, or a [track] for
    /// the stack
    #[arg(value_name = "SCENE.toml", value_hint = clap::ValueHint::FilePath,
          conflicts_with_all = ["masses", "inertia", "velocities", "restitution", "normal",
                                "radii", "impact_parameter"])]
    pub scene: Option<PathBuf>,

    /// Masses M1,M2, as for solve [default with no case: 4,1, lecture Fig. 1.3]
    #[arg(
        short,
        long,
        value_name = "M1,M2",
        allow_hyphen_values = true,
        conflicts_with = "inertia",
        requires = "velocities"
    )]
    pub masses: Option<String>,

    /// A general symmetric positive definite inertia tensor instead of masses
    #[arg(
        long,
        value_name = "M11,M12;M21,M22",
        allow_hyphen_values = true,
        requires = "velocities"
    )]
    pub inertia: Option<String>,

    /// Initial velocities V1,V2 [default with no case: 60,10]; vectors open the plane panel:
    /// '(1,0),(0,0)', '6 @ 30deg,0'
    #[arg(short, long, value_name = "V1,V2", allow_hyphen_values = true)]
    pub velocities: Option<String>,

    /// The line of impact in the plane (from body 1 to body 2): '(1,1)', 30deg, N30E
    #[arg(
        long,
        value_name = "N",
        allow_hyphen_values = true,
        conflicts_with = "radii",
        requires = "velocities"
    )]
    pub normal: Option<String>,

    /// Radii of two smooth disks in the plane (with --impact-parameter)
    #[arg(long, value_name = "R1,R2", allow_hyphen_values = true,
          requires_all = ["impact_parameter", "velocities"])]
    pub radii: Option<String>,

    /// Distance from body 2's centre to the line of body 1's relative motion (with --radii)
    #[arg(long, value_name = "B", allow_hyphen_values = true, requires = "radii")]
    pub impact_parameter: Option<String>,

    /// Coefficient of restitution e >= 0 [default: elastic]
    #[arg(short = 'e', long, value_name = "E", allow_hyphen_values = true)]
    pub restitution: Option<String>,

    /// The frame the page opens in: lab, com, rest-in:1, ..., or an observer velocity
    #[arg(long, default_value = "lab", allow_hyphen_values = true)]
    pub frame: Frame,

    /// Also show the time-reversed collision
    #[arg(long)]
    pub reverse: bool,

    /// Write the page to FILE (atomically), or to stdout with -o - [default: stdout to a pipe;
    /// on a terminal, collide-view.html in this folder]
    #[arg(short, long, value_name = "FILE.html", global = true)]
    pub output: Option<PathBuf>,

    /// Open the page in the default browser (xdg-open, open or start; the environment variable
    /// COLLIDE_OPENER names another program): the file of -o, else collide-view.html here
    #[arg(long, global = true)]
    pub open: bool,
}

#[derive(Subcommand, Debug)]
pub enum ViewTrack {
    /// Open with this track layout for the stack (the flags of `collide track`)
    #[command(
        override_usage = concat!(
            "collide view track [OPTIONS] ",
            "-m <M1,M2,...> -x <X1,X2,...> -v <V1,V2,...>"
        ),
        after_help = "Examples:
  collide view track -m 1,100 -x 1,2 -v 0,-1 --left-wall 0 -o pi.html
  collide view track -m 1,0.01 -x 1.5,2.25 -v 0,0 --sizes 1,0.5 \\
      --left-wall 0 --gravity 9.81 --until 3 -o stack.html"
    )]
    Track(ViewTrackArgs),
}

#[derive(Args, Debug)]
pub struct ViewTrackArgs {
    #[command(flatten)]
    pub layout: LayoutArgs,

    #[command(flatten)]
    pub rules: TrackRules,

    /// How long the page runs the stack [default: 8 times the first collision's time]
    #[arg(long, value_name = "T")]
    pub until: Option<Number>,
}

#[derive(Args, Debug)]
pub struct PiArgs {
    /// Digits of pi after the point, 0 to 10,000: the mass ratio is 100^N
    #[arg(value_name = "N", value_parser = parse_pi_digits)]
    pub n: u32,

    /// Simulate the collisions too [default: when N <= 10; N = 8 takes seconds, N = 10 minutes;
    /// refused above 10]
    #[arg(long, conflicts_with = "no_simulate")]
    pub simulate: bool,

    /// Give the count only, without simulating
    #[arg(long)]
    pub no_simulate: bool,

    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

#[derive(Args, Debug)]
pub struct FramesArgs {
    #[command(flatten)]
    pub case: CaseArgs,

    /// More frames to add as rows: com, rest-in:1, rest-fin:2, ..., or an observer velocity
    #[arg(long, value_name = "FRAME", allow_hyphen_values = true)]
    pub frame: Vec<Frame>,

    /// Add a column saying whether the time-reversed collision equals the original
    #[arg(long)]
    pub reverse: bool,

    /// Exact rational arithmetic from the numbers as typed
    #[arg(long)]
    pub exact: bool,

    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

#[derive(Args, Debug)]
pub struct AccuracyArgs {
    /// Seed of the case families (the same seed gives the same cases everywhere)
    #[arg(long, default_value_t = 2026)]
    pub seed: u64,

    /// Cases per family (the lecture family always has its 5)
    #[arg(long, default_value_t = 48, value_parser = clap::value_parser!(u64).range(1..=100_000))]
    pub cases: u64,

    /// Methods to compare, comma-separated
    #[arg(
        long,
        value_enum,
        value_delimiter = ',',
        default_value = "impulse,textbook,quadratic,tensor,exact"
    )]
    pub methods: Vec<collide::accuracy::Method>,

    /// Also draw the error-vs-time scatter to FILE.svg
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,

    /// Time spent timing each method on each family, in milliseconds
    #[arg(long, default_value_t = 40, value_parser = clap::value_parser!(u64).range(1..=60_000))]
    pub budget_ms: u64,

    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

/// The case: tensor (masses or a general inertia), velocities, restitution.
#[derive(Args, Debug, Clone)]
pub struct CaseArgs {
    /// Masses M1,M2 (each > 0), e.g. 4,1 or 1.5e3,2/3 or '4 ton,1 ton'; '?' for an unknown (solve);
    /// more than two bodies: M1,M2,M3,...
    #[arg(short, long, value_name = "M1,M2", value_parser = |s: &str| Listed::parse(s, Dimension::Mass, "masses M1,M2"),
          allow_hyphen_values = true, required_unless_present = "inertia")]
    pub masses: Option<Listed>,

    /// A general symmetric positive definite inertia tensor instead of masses, e.g. '4,0.5;0.5,1'
    #[arg(long, value_name = "M11,M12;M21,M22", value_parser = parse_inertia,
          allow_hyphen_values = true, conflicts_with = "masses")]
    pub inertia: Option<InertiaTensor>,

    /// Initial velocities V1,V2, e.g. 60,10 or 3,-4 or '72 km/h,0'; '?' for an unknown (solve);
    /// vectors in the plane or in space: '(4,1),(-1,0.5)', '6 m/s @ 30deg,0', '15 m/s @ N30E,?'
    #[arg(short, long, value_name = "V1,V2", value_parser = |s: &str| Listed::parse(s, Dimension::Velocity, "velocities V1,V2"),
          allow_hyphen_values = true)]
    pub velocities: Listed,

    /// The line of impact between bodies 1 and 2 (from 1 to 2): components '(1,1)' (any
    /// length) or an angle '30deg', 'N30E'; the impulse acts along it (plane and space)
    #[arg(long, value_name = "N", allow_hyphen_values = true, conflicts_with = "radii",
          value_parser = |s: &str| s.parse::<collide::space::pose::NormalGiven>())]
    pub normal: Option<collide::space::pose::NormalGiven>,

    /// Radii of two smooth disks (with --impact-parameter): the line of impact from the
    /// geometry; numbers, or lengths with a unit ('2.5 cm,2.5 cm') like the impact parameter;
    /// with --positions, one per ball (touching balls, docs/plane.md)
    #[arg(long, value_name = "R1,R2", allow_hyphen_values = true,
          value_parser = collide::space::balls::parse_radii)]
    pub radii: Option<collide::space::balls::Radii>,

    /// Distance from body 2's centre to the line of body 1's relative motion (positive: to its
    /// left): sin(phi) = B / (R1 + R2), the line of impact at phi from the relative velocity
    #[arg(long, value_name = "B", allow_hyphen_values = true, requires = "radii",
          value_parser = |s: &str| collide::values::units::parse(s, Dimension::Length).map_err(|e| e.to_string()))]
    pub impact_parameter: Option<Quantity>,

    /// Coefficient of restitution e >= 0: 'elastic' (1), 'inelastic' (0), above 1 superelastic (energy released), or '?' (solve)
    /// [default: elastic; unknown when --fin is given]
    #[arg(short = 'e', long, value_name = "E", allow_hyphen_values = true,
          value_parser = |s: &str| Given::parse(s, str::parse::<Restitution>))]
    pub restitution: Option<Given<Restitution>>,

    /// Convert every value with a unit to kg, m/s and J
    #[arg(long)]
    pub si: bool,

    /// Print energies in this unit: J, kJ, eV, MeV, ft*lbf or cal (the masses and velocities need
    /// units)
    #[arg(long, value_name = "UNIT", value_parser = |s: &str| collide::values::units::energy_unit(s))]
    pub energy_unit: Option<&'static collide::values::units::EnergyUnit>,

    /// g in m/s^2 for velocities typed as heights ('height 2 m': the speed sqrt(2 g h) of a fall
    /// from rest through 2 m) and for --show heights [default: 9.80665, standard gravity]
    #[arg(long, value_name = "G", allow_hyphen_values = true)]
    pub gravity: Option<Number>,
}

#[derive(Args, Debug)]
pub struct SolveArgs {
    #[command(flatten)]
    pub case: CaseArgs,

    /// Print speeds in this unit on a rail: m/s, km/h, mph (mi/h), ft/s, knot... (the velocities
    /// need units; energies then in J unless --energy-unit says otherwise)
    #[arg(long, value_name = "UNIT", value_parser = |s: &str| collide::values::units::lookup(s.trim(), collide::values::units::Dimension::Velocity).map_err(|e| e.to_string()))]
    pub velocity_unit: Option<&'static collide::values::units::Unit>,

    /// Sections to print, comma-separated [default: vectors,forms,energy; in the plane, in
    /// space and for N bodies: vectors,energy,angles]
    #[arg(long, value_enum, value_delimiter = ',', value_name = "SECTIONS")]
    pub show: Vec<Section>,

    /// Exact rational arithmetic from the numbers as typed: fractions out, radii to 20 digits
    /// marked approximate
    #[arg(long)]
    pub exact: bool,

    /// The frame to see the collision from: lab, com, rest-in:1, rest-in:2, rest-fin:1,
    /// rest-fin:2, or an observer velocity
    #[arg(long, default_value = "lab", allow_hyphen_values = true)]
    pub frame: Frame,

    /// Also print the time-reversed collision (IN' = -FIN, FIN' = -IN)
    #[arg(long)]
    pub reverse: bool,

    /// How long the bodies touch, e.g. '2 ms' or 0.01 (seconds; units s, ms, us): the changes
    /// section then gives the average force dp / T on each body
    #[arg(long, value_name = "T", value_parser = |s: &str| collide::values::units::seconds(s))]
    pub contact_time: Option<collide::values::rational::Q>,

    /// Final velocities F1,F2 as given by a problem ('?' for unknown): collide solves for the
    /// unknowns (any two of m1, m2, v1, v2, f1, f2, e) and checks the rest; 'slide D mu ?'
    /// solves the floor's mu from the collision
    #[arg(long, value_name = "F1,F2", allow_hyphen_values = true, value_parser = fin_listed)]
    pub fin: Option<Listed>,

    /// Also draw the velocity diagram: to FILE.svg, or 'term' for the terminal
    #[arg(long, value_name = "FILE.svg|term")]
    pub plot: Option<PathBuf>,

    #[command(flatten)]
    pub knowns: KnownArgs,

    #[command(flatten)]
    pub balls: BallsArgs,

    #[command(flatten)]
    pub rigid: RigidArgs,

    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

/// Rigid bodies at impact (docs/rigid.md): a ball (body 1) hits a target or a floor; any of
/// these flags makes the case a rigid one.
#[derive(Args, Debug, Clone, Default)]
pub struct RigidArgs {
    /// The body hit (body 2), a rigid shape: 'rod 1.2 m', 'door 0.9 m', 'box (0.2,1) m', 'disk
    /// 10 cm', 'ring R', 'sphere R', 'shell R' (a rod or door stands along y, centre at the
    /// origin, hit on its left side by the ball moving along +x)
    #[arg(long, value_name = "SHAPE", help_heading = "Rigid bodies")]
    pub target: Option<collide::rigid::shape::ShapeTyped>,

    /// The target's fixed pivot: 'end' (its bottom end), 'centre', or '(x,y)' from its centre
    #[arg(
        long,
        value_name = "end|centre|(x,y)",
        allow_hyphen_values = true,
        help_heading = "Rigid bodies"
    )]
    pub pivot: Option<collide::rigid::homework::PivotTyped>,

    /// Where the target is hit: the distance along it from its pivot (from its centre when
    /// free; the height b on a round target), or 'end' (its top end) [default: the centre]
    #[arg(
        long,
        value_name = "D|end",
        allow_hyphen_values = true,
        help_heading = "Rigid bodies"
    )]
    pub hit_at: Option<collide::rigid::homework::HitTyped>,

    /// The ball's shape (body 1), e.g. 'sphere 3 cm' or 'shell 3 cm' [default: a point particle]
    #[arg(long, value_name = "SHAPE", help_heading = "Rigid bodies")]
    pub ball: Option<collide::rigid::shape::ShapeTyped>,

    /// Spins W1[,W2] about z, counterclockwise positive: '20 rad/s', '300 rpm', '-5 rev/s'
    /// (a ball rolling to the right spins clockwise: negative)
    #[arg(
        long,
        value_name = "W1,W2",
        allow_hyphen_values = true,
        help_heading = "Rigid bodies"
    )]
    pub spin: Option<String>,

    /// Coulomb friction coefficient mu >= 0 at the contact, or '?' (solve); with --show slides
    /// on a rail, the floor's kinetic friction, which stops each body after the collision
    #[arg(
        long,
        value_name = "MU",
        allow_hyphen_values = true,
        value_parser = |s: &str| Given::parse(s, str::parse::<Number>),
        help_heading = "Rigid bodies"
    )]
    pub friction: Option<Given<Number>>,

    /// The restitution law with friction [default: poisson]
    #[arg(long, value_enum, help_heading = "Rigid bodies")]
    pub law: Option<collide::rigid::laws::Law>,

    /// Garwin's rough contact: the slip velocity reverses to -BETA times itself (BETA in [-1,
    /// 1]; 1 is the ideal superball)
    #[arg(
        long,
        value_name = "BETA",
        allow_hyphen_values = true,
        help_heading = "Rigid bodies"
    )]
    pub tangential_restitution: Option<Number>,

    /// The bodies join: the ball lodges at the contact point and the pair moves on as one rigid
    /// body (e = 0 and no slip); prints the combined mass, centre and inertia
    #[arg(long, help_heading = "Rigid bodies")]
    pub join: bool,

    /// The floor's kinetic friction MU > 0 under a ball that leaves the impact sliding: with
    /// --show rolling, the time and distance before it rolls (with --gravity)
    #[arg(
        long,
        value_name = "MU",
        allow_hyphen_values = true,
        help_heading = "Rigid bodies"
    )]
    pub floor_friction: Option<Number>,

    /// The final spins W1,W2 about z, counterclockwise positive ('?' or empty for one not given;
    /// rad/s, rpm, rev/s, deg/s; plain: rad/s): a known that fixes a '?'
    #[arg(
        long,
        value_name = "W1,W2",
        allow_hyphen_values = true,
        help_heading = "Rigid bodies"
    )]
    pub fin_spin: Option<String>,

    /// The impulse the pivot gives the target: 0 (the centre of percussion), a known that fixes
    /// a '?' such as --hit-at ?
    #[arg(
        long,
        value_name = "0",
        allow_hyphen_values = true,
        help_heading = "Rigid bodies"
    )]
    pub pivot_impulse: Option<Number>,
}

impl RigidArgs {
    /// Whether the case is a rigid impact.
    pub fn active(&self) -> bool {
        self.friction.is_some() || self.active_beyond_friction()
    }

    /// Whether a flag other than --friction makes the case a rigid impact (with `--show slides`
    /// on a rail, --friction is the floor's).
    pub fn active_beyond_friction(&self) -> bool {
        self.target.is_some()
            || self.pivot.is_some()
            || self.hit_at.is_some()
            || self.ball.is_some()
            || self.spin.is_some()
            || self.law.is_some()
            || self.tangential_restitution.is_some()
            || self.join
            || self.floor_friction.is_some()
            || self.fin_spin.is_some()
            || self.pivot_impulse.is_some()
    }
}

#[derive(Args, Debug)]
pub struct SceneArgs {
    /// Scene files (TOML); '-' for standard input
    #[arg(required = true, value_name = "FILE.toml", value_hint = clap::ValueHint::FilePath)]
    pub files: Vec<PathBuf>,

    /// Output format of the reports [default: text] (a [sweep] scene run alone writes its table
    /// in its own format)
    #[arg(long, value_enum)]
    pub format: Option<Format>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Aligned text for people
    Text,
    /// One JSON object (stable schema: docs/json.md)
    Json,
}
