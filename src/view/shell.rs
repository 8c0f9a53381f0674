//! Back to the shell: the `collide` command line and the scene file of what the page shows, so
//! that a case found by playing becomes a command that reproduces it. Values go out as they were
//! typed (`2/3` stays `2/3`), so the command computes from the same exact numbers.

use super::input::{CaseInput, NBodyInput, PlaneInput, RigidInput, TrackInput};

/// `text` as one shell word: as it is when no shell treats any of its characters specially,
/// else in single quotes (a quote inside written `'\''`).
pub fn word(text: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_,.:/+=@%-".contains(c);
    if !text.is_empty() && text.chars().all(plain) {
        text.to_string()
    } else {
        format!("'{}'", text.replace('\'', r"'\''"))
    }
}

/// `text` as a TOML value that a scene reads back as the same typed value: bare when TOML reads
/// it as a number with the same digits (an integer within i64, or a decimal written as Rust
/// writes the binary64 it rounds to), else a string.
pub fn toml_value(text: &str) -> String {
    let t = text.trim();
    let digits = t.strip_prefix('-').unwrap_or(t);
    let integer = !digits.is_empty()
        && digits.bytes().all(|b| b.is_ascii_digit())
        && (digits == "0" || !digits.starts_with('0'))
        && t.parse::<i64>().is_ok();
    let decimal = t.contains('.') && t.parse::<f64>().is_ok_and(|v| format!("{v:?}") == t);
    if integer || decimal {
        t.to_string()
    } else {
        toml_string(t)
    }
}

/// A TOML basic string.
fn toml_string(t: &str) -> String {
    let mut out = String::from("\"");
    for c in t.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => out.push_str(&format!("\\u{:04X}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A comma-separated list as typed, trimmed field by field.
fn fields(text: &str) -> Vec<&str> {
    text.split(',').map(str::trim).collect()
}

fn toml_list(text: &str) -> String {
    let values: Vec<String> = fields(text).into_iter().map(toml_value).collect();
    format!("[{}]", values.join(", "))
}

/// Whether the restitution is the command line's default.
fn is_elastic(e: &str) -> bool {
    e.trim() == "elastic"
}

/// The `collide solve` command line of a case.
pub fn solve_command(c: &CaseInput) -> String {
    let mut out = String::from("collide solve");
    match &c.inertia {
        Some(t) => out.push_str(&format!(" --inertia {}", word(t.trim()))),
        None => out.push_str(&format!(
            " -m {}",
            word(&format!("{},{}", c.m1.trim(), c.m2.trim()))
        )),
    }
    out.push_str(&format!(
        " -v {}",
        word(&format!("{},{}", c.v1.trim(), c.v2.trim()))
    ));
    out.push_str(&rules(&c.e, &c.frame, c.reverse));
    if c.exact {
        out.push_str(" --exact");
    }
    out
}

/// The flags after the bodies: `-e` unless elastic, `--frame` unless the lab, `--reverse`.
fn rules(e: &str, frame: &str, reverse: bool) -> String {
    let mut out = String::new();
    if !is_elastic(e) {
        out.push_str(&format!(" -e {}", word(e.trim())));
    }
    if frame.trim() != "lab" {
        out.push_str(&format!(" --frame {}", word(frame.trim())));
    }
    if reverse {
        out.push_str(" --reverse");
    }
    out
}

/// The scene file of a case (`collide scene FILE.toml`).
pub fn solve_scene(c: &CaseInput) -> String {
    let mut out = String::from("# From collide view; run with: collide scene FILE.toml\n");
    match &c.inertia {
        Some(t) => {
            let rows: Vec<String> = t.split(';').map(toml_list).collect();
            out.push_str(&format!("inertia = [{}]\n", rows.join(", ")));
        }
        None => out.push_str(&format!(
            "masses = [{}, {}]\n",
            toml_value(&c.m1),
            toml_value(&c.m2)
        )),
    }
    out.push_str(&format!(
        "velocities = [{}, {}]\n",
        toml_value(&c.v1),
        toml_value(&c.v2)
    ));
    out.push_str(&format!("restitution = {}\n", toml_value(&c.e)));
    if c.frame.trim() != "lab" {
        out.push_str(&format!("frame = {}\n", toml_value(&c.frame)));
    }
    if c.reverse {
        out.push_str("# The time reverse (--reverse) has no scene key: see the command line.\n");
    }
    if c.exact {
        out.push_str("exact = true\n");
    }
    out
}

/// The `collide solve` command line of two pucks in the plane.
pub fn plane_command(p: &PlaneInput) -> String {
    let mut out = format!(
        "collide solve -m {} -v {}",
        word(&format!("{},{}", p.m1.trim(), p.m2.trim())),
        word(&format!("{},{}", p.v1.trim(), p.v2.trim()))
    );
    if !p.normal.trim().is_empty() {
        out.push_str(&format!(" --normal {}", word(p.normal.trim())));
    } else if !p.r1.trim().is_empty() || !p.r2.trim().is_empty() || !p.b.trim().is_empty() {
        out.push_str(&format!(
            " --radii {} --impact-parameter {}",
            word(&format!("{},{}", p.r1.trim(), p.r2.trim())),
            word(p.b.trim())
        ));
    }
    out.push_str(&rules(&p.e, &p.frame, p.reverse));
    if p.exact {
        out.push_str(" --exact");
    }
    out
}

/// A list of the page's per-body texts as one flag's value (`1,2 kg,3`), trimmed.
fn joined(list: &[String]) -> String {
    word(&list.iter().map(|s| s.trim()).collect::<Vec<_>>().join(","))
}

/// The `collide solve` command line of N pucks (`view::nbody`): `-e 0` where they stick,
/// `--fin` where they explode, `--positions` and `--radii` (and `-e`) where they touch.
pub fn nbody_command(p: &NBodyInput) -> String {
    let mut out = format!(
        "collide solve -m {} -v {}",
        joined(&p.masses),
        joined(&p.velocities)
    );
    match p.mode.trim() {
        "stick" => out.push_str(" -e 0"),
        "explode" => out.push_str(&format!(" --fin {}", joined(&p.fin))),
        _ => {
            out.push_str(&format!(
                " --positions {} --radii {}",
                joined(&p.positions),
                joined(&p.radii)
            ));
            out.push_str(&rules(&p.e, "lab", false));
        }
    }
    out
}

/// The `collide solve` command line of a rigid impact (docs/rigid.md): each field given as its
/// flag, as typed.
pub fn rigid_command(r: &RigidInput) -> String {
    let v2 = Some(r.v2.trim()).filter(|t| !t.is_empty()).unwrap_or("0");
    let v = format!("{},{v2}", r.v1.trim());
    let mut out = format!(
        "collide solve -m {} -v {}",
        word(&format!("{},{}", r.m1.trim(), r.m2.trim())),
        word(&v)
    );
    for (flag, text) in [
        ("--target", &r.target),
        ("--pivot", &r.pivot),
        ("--hit-at", &r.hit_at),
        ("--ball", &r.ball),
        ("--spin", &r.spin),
        ("-e", &r.e),
        ("--friction", &r.friction),
        ("--tangential-restitution", &r.beta),
        ("--law", &r.law),
    ] {
        let t = text.trim();
        if !(t.is_empty() || flag == "-e" && is_elastic(t)) {
            out.push_str(&format!(" {flag} {}", word(t)));
        }
    }
    out
}

/// A vector as a scene writes it: `[4, 0]` when it is components the scene reads back as typed,
/// else the command line's text as a string (`"6 m/s @ 30deg"`, `"(4,0) m/s"`) or number.
fn toml_vector(text: &str) -> String {
    let t = text.trim();
    if let Some(inside) = t.strip_prefix('(').and_then(|r| r.strip_suffix(')')) {
        let parts: Vec<String> = fields(inside).into_iter().map(toml_value).collect();
        if parts.iter().all(|v| !v.starts_with('"')) {
            return format!("[{}]", parts.join(", "));
        }
    }
    toml_value(t)
}

/// The scene file of two pucks in the plane (`collide scene FILE.toml`).
pub fn plane_scene(p: &PlaneInput) -> String {
    let mut out = String::from("# From collide view; run with: collide scene FILE.toml\n");
    out.push_str(&format!(
        "masses = [{}, {}]\n",
        toml_value(&p.m1),
        toml_value(&p.m2)
    ));
    out.push_str(&format!(
        "velocities = [{}, {}]\n",
        toml_vector(&p.v1),
        toml_vector(&p.v2)
    ));
    if !p.normal.trim().is_empty() {
        out.push_str(&format!("normal = {}\n", toml_vector(&p.normal)));
    } else if !p.r1.trim().is_empty() || !p.r2.trim().is_empty() || !p.b.trim().is_empty() {
        out.push_str(&format!(
            "radii = [{}, {}]\nimpact_parameter = {}\n",
            toml_value(&p.r1),
            toml_value(&p.r2),
            toml_value(&p.b)
        ));
    }
    if !is_elastic(&p.e) {
        out.push_str(&format!("restitution = {}\n", toml_value(&p.e)));
    }
    if p.frame.trim() != "lab" {
        out.push_str(&format!("frame = {}\n", toml_value(&p.frame)));
    }
    if p.reverse {
        out.push_str("reverse = true\n");
    }
    if p.exact {
        out.push_str("exact = true\n");
    }
    out
}

/// The flags of a layout as `(flag, TOML key, typed text)`, in the order of `collide track
/// --help`; empty texts are flags not given.
fn track_flags(t: &TrackInput) -> [(&'static str, &'static str, &str); 9] {
    [
        ("-m", "masses", &t.masses),
        ("-x", "positions", &t.positions),
        ("-v", "velocities", &t.velocities),
        ("--sizes", "sizes", &t.sizes),
        ("--left-wall", "left_wall", &t.left_wall),
        ("--right-wall", "right_wall", &t.right_wall),
        ("-e", "restitution", &t.e),
        ("--wall-restitution", "wall_restitution", &t.e_wall),
        ("--gravity", "gravity", &t.gravity),
    ]
}

/// Whether a flag's text is given (and not the default restitution).
fn given(key: &str, text: &str) -> bool {
    !text.trim().is_empty() && (key != "restitution" || !is_elastic(text))
}

/// The `collide track` command line of a layout, run to `until`.
pub fn track_command(t: &TrackInput, until: f64) -> String {
    let mut out = String::from("collide track");
    for (flag, key, text) in track_flags(t) {
        if given(key, text) {
            out.push_str(&format!(" {flag} {}", word(&fields(text).join(","))));
        }
    }
    out.push_str(&format!(" --until {}", until_text(t, until)));
    out
}

/// The scene file of a layout (`[track]`), run to `until`.
pub fn track_scene(t: &TrackInput, until: f64) -> String {
    let mut out = String::from("# From collide view; run with: collide scene FILE.toml\n[track]\n");
    for (_, key, text) in track_flags(t) {
        if !given(key, text) {
            continue;
        }
        let value = if matches!(key, "masses" | "positions" | "velocities" | "sizes") {
            toml_list(text)
        } else {
            toml_value(text)
        };
        out.push_str(&format!("{key} = {value}\n"));
    }
    out.push_str(&format!("until = {}\n", toml_value(&until_text(t, until))));
    out
}

/// `until` as typed, or the chosen one as Rust writes it (shortest, reads back the same).
fn until_text(t: &TrackInput, until: f64) -> String {
    match t.until.trim() {
        "" => format!("{until:?}"),
        typed => typed.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_are_quoted_only_when_a_shell_would_change_them() {
        assert_eq!(word("4,1"), "4,1");
        assert_eq!(word("3,-4"), "3,-4");
        assert_eq!(word("2/3"), "2/3");
        assert_eq!(word("4 ton,1 ton"), "'4 ton,1 ton'");
        assert_eq!(word("4,0.5;0.5,1"), "'4,0.5;0.5,1'");
        assert_eq!(word("it's"), r"'it'\''s'");
        assert_eq!(word("?"), "'?'");
        assert_eq!(word(""), "''");
    }

    #[test]
    fn toml_values_read_back_as_typed() {
        for bare in ["4", "-4", "0", "60.0", "0.01", "9.81", "-0.5"] {
            assert_eq!(toml_value(bare), bare);
        }
        // Not TOML numbers, or numbers TOML would read back with other digits.
        assert_eq!(toml_value("2/3"), "\"2/3\"");
        assert_eq!(toml_value("1e3"), "\"1e3\"");
        assert_eq!(toml_value("007"), "\"007\"");
        assert_eq!(toml_value(".5"), "\".5\"");
        assert_eq!(
            toml_value("0.10000000000000000001"),
            "\"0.10000000000000000001\""
        );
        assert_eq!(
            toml_value("100000000000000000000"),
            "\"100000000000000000000\""
        );
        assert_eq!(toml_value("elastic"), "\"elastic\"");
        assert_eq!(toml_value("4 \"t\""), "\"4 \\\"t\\\"\"");
    }
}
