//! The page of `collide view`: one HTML file with its style, its script and the WebAssembly
//! module inside (zlib-compressed, base64), so it opens from disk with no network at all. The
//! answers to the first case and layout are computed here, natively, and written into the page,
//! so it shows its numbers before (and without) the module; the page recomputes them with the
//! module and reports any difference on the console. The same setup gives the same bytes.

use serde::Serialize;

use super::InputError;
use super::api::{Request, answer};
use super::input::{CaseInput, NBodyInput, PlaneInput, RigidInput, TrackInput};

const TEMPLATE: &str = include_str!("assets/page.html");
const STYLE: &str = include_str!("assets/page.css");
/// The page's script, in parts by job, run in this order inside one function (they share its
/// scope): the core and drawing helpers, the momentum and energy bars and the live regions'
/// sentences, the velocity plane and dual panel, the plane, the stack, the rigid panel, and the
/// start.
const SCRIPTS: [&str; 8] = [
    include_str!("assets/page.js"),
    include_str!("assets/bars.js"),
    include_str!("assets/two_body.js"),
    include_str!("assets/plane.js"),
    include_str!("assets/stack.js"),
    include_str!("assets/rigid.js"),
    include_str!("assets/nbody.js"),
    include_str!("assets/start.js"),
];

/// The library without its command line, compiled to `wasm32-unknown-unknown` by
/// `wasm/build.sh` and committed; `tests/suite/view.rs` checks that rebuilding it gives these
/// bytes.
pub const MODULE: &[u8] = include_bytes!("../../wasm/collide_view.wasm");

/// What the page opens with.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Setup {
    pub case: CaseInput,
    pub plane: PlaneInput,
    pub track: TrackInput,
    pub rigid: RigidInput,
    /// The N-ball panel's pucks (up to five).
    pub nbody: NBodyInput,
    /// The part shown first: `two-body`, `plane` or `stack`.
    pub focus: Focus,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Focus {
    TwoBody,
    Plane,
    Stack,
}

impl Setup {
    /// Lecture Fig. 1.3 (a 4-ton SUV at 60 rear-ends a 1-ton VW at 10, elastic), two equal
    /// disks of radius 1, one at rest, hit at the impact parameter 1 (the line of impact at
    /// asin(1/2) = 30 degrees: they leave at right angles), and the 2-ball superball stack
    /// dropped from rest 1 m above the floor; on the rigid panel, docs/rigid.md's ball of mass 1
    /// hitting the end of a free rod of mass 4 and length 2 at 3 (it stops dead: the rod's
    /// effective mass at its end is M/4).
    pub fn lecture() -> Setup {
        Setup {
            case: CaseInput {
                m1: "4".into(),
                m2: "1".into(),
                inertia: None,
                v1: "60".into(),
                v2: "10".into(),
                e: "elastic".into(),
                frame: "lab".into(),
                reverse: false,
                exact: false,
            },
            plane: PlaneInput {
                m1: "1".into(),
                m2: "1".into(),
                v1: "(1,0)".into(),
                v2: "(0,0)".into(),
                e: "elastic".into(),
                normal: String::new(),
                r1: "1".into(),
                r2: "1".into(),
                b: "1".into(),
                frame: "lab".into(),
                reverse: false,
                exact: false,
                line: String::new(),
            },
            track: TrackInput {
                masses: "1,0.01".into(),
                positions: "1.5,2.25".into(),
                velocities: "0,0".into(),
                sizes: "1,0.5".into(),
                left_wall: "0".into(),
                right_wall: String::new(),
                e: "elastic".into(),
                e_wall: String::new(),
                gravity: "9.81".into(),
                until: String::new(),
            },
            rigid: RigidInput {
                m1: "1".into(),
                m2: "4".into(),
                v1: "3".into(),
                v2: String::new(),
                target: "rod 2".into(),
                pivot: String::new(),
                hit_at: "end".into(),
                ball: String::new(),
                spin: String::new(),
                e: "elastic".into(),
                friction: String::new(),
                beta: String::new(),
                law: String::new(),
            },
            // physics.md section 8's cue ball onto two touching balls.
            nbody: NBodyInput {
                mode: "contacts".into(),
                masses: vec!["1".into(); 3],
                velocities: vec!["(3.8,0)".into(), "0".into(), "0".into()],
                fin: Vec::new(),
                positions: vec!["(0,0)".into(), "(1.732,1)".into(), "(1.732,-1)".into()],
                radii: vec!["1".into(); 3],
                e: "elastic".into(),
            },
            focus: Focus::TwoBody,
        }
    }
}

/// The page, or the first bad input (as the command line would name it).
pub fn html(setup: &Setup) -> Result<String, InputError> {
    let solved = checked(answer(&Request::Solve(setup.case.clone())))?;
    let plane = checked(answer(&Request::Plane(setup.plane.clone())))?;
    let stack = checked(answer(&Request::Track(setup.track.clone())))?;
    let rigid = checked(answer(&Request::Rigid(setup.rigid.clone())))?;
    let nbody = checked(answer(&Request::Nbody(setup.nbody.clone())))?;
    let text = |v: &serde_json::Value, key: &str| v[key].as_str().unwrap_or_default().to_string();
    let data = serde_json::json!({
        "setup": setup,
        "answers": {"solve": solved, "plane": plane, "track": stack, "rigid": rigid, "nbody": nbody},
    });
    let script = format!(
        "\"use strict\";\n(function () {{\n{}}})();\n",
        SCRIPTS.concat()
    );
    let fill = [
        ("{{STYLE}}", STYLE.to_string()),
        ("{{SCRIPT}}", script_text(&script)),
        ("{{SETUP}}", script_text(&data.to_string())),
        ("{{MODULE}}", base64(&compressed(MODULE))),
        ("{{STATE}}", escape(&text(&solved, "state"))),
        ("{{COMMAND}}", escape(&text(&solved, "command"))),
        ("{{SCENE}}", escape(&text(&solved, "scene"))),
        ("{{PLANE_STATE}}", escape(&text(&plane, "state"))),
        ("{{PLANE_COMMAND}}", escape(&text(&plane, "command"))),
        ("{{PLANE_SCENE}}", escape(&text(&plane, "scene"))),
        ("{{TRACK_STATE}}", escape(&text(&stack, "state"))),
        ("{{TRACK_COMMAND}}", escape(&text(&stack, "command"))),
        ("{{TRACK_SCENE}}", escape(&text(&stack, "scene"))),
        ("{{RIGID_STATE}}", escape(&text(&rigid, "state"))),
        ("{{RIGID_COMMAND}}", escape(&text(&rigid, "command"))),
        ("{{NBALL_STATE}}", escape(&text(&nbody, "state"))),
        ("{{NBALL_COMMAND}}", escape(&text(&nbody, "command"))),
    ];
    Ok(fill_in(TEMPLATE, &fill))
}

/// `template` with each `{{NAME}}` replaced by its value, in one pass (a value is never searched
/// for further names).
fn fill_in(template: &str, values: &[(&str, String)]) -> String {
    let mut page =
        String::with_capacity(template.len() + values.iter().map(|(_, v)| v.len()).sum::<usize>());
    let mut rest = template;
    while let Some(at) = rest.find("{{") {
        page.push_str(&rest[..at]);
        rest = &rest[at..];
        match values.iter().find(|(key, _)| rest.starts_with(key)) {
            Some((key, value)) => {
                page.push_str(value);
                rest = &rest[key.len()..];
            }
            None => {
                page.push_str("{{");
                rest = &rest[2..];
            }
        }
    }
    page.push_str(rest);
    page
}

/// The answer, or its error.
fn checked(v: serde_json::Value) -> Result<serde_json::Value, InputError> {
    if v["ok"] == true {
        return Ok(v);
    }
    let field = match v["field"].as_str() {
        Some("m1" | "m2" | "inertia") => "masses",
        Some("v1" | "v2") => "velocities",
        Some("e") => "restitution",
        Some("normal") => "normal",
        Some("r1" | "r2") => "radii",
        Some("b") => "impact-parameter",
        Some(_) | None => "input",
    };
    Err(InputError::new(
        field,
        v["error"].as_str().unwrap_or("bad input"),
    ))
}

/// Text for inside `<script>`: `</` written `<\/` and `<!--` written `<\u0021--` (the same
/// strings in JSON and JavaScript), so no value can close or confuse the element.
fn script_text(s: &str) -> String {
    s.replace("</", "<\\/").replace("<!--", "<\\u0021--")
}

/// Text for HTML content.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// `bytes` in zlib format at the highest level (the page inflates it with the browser's
/// `DecompressionStream("deflate")`).
pub fn compressed(bytes: &[u8]) -> Vec<u8> {
    miniz_oxide::deflate::compress_to_vec_zlib(bytes, 10)
}

/// Base64, standard alphabet with padding (RFC 4648, Sec. 4).
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(char::from(ALPHABET[(n >> (18 - 6 * k)) as usize & 63]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_of_the_rfc_4648_vectors() {
        // RFC 4648, Sec. 10.
        for (text, code) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(text.as_bytes()), code, "{text:?}");
        }
    }

    #[test]
    fn the_module_inflates_back_to_itself() {
        let z = compressed(MODULE);
        assert!(
            z.len() < MODULE.len() / 2,
            "{} of {}",
            z.len(),
            MODULE.len()
        );
        assert_eq!(
            miniz_oxide::inflate::decompress_to_vec_zlib(&z).unwrap(),
            MODULE
        );
    }

    #[test]
    fn script_text_cannot_close_its_element() {
        let s = script_text(r#"{"a": "</script><!--"}"#);
        assert!(!s.contains("</") && !s.contains("<!--"), "{s}");
        let back: serde_json::Value = serde_json::from_str(&s).unwrap();
        assert_eq!(back["a"], "</script><!--");
    }
}
