//! Pictures: the SVG parses as XML, its elements have the right geometry in the data-to-screen
//! map that the axis ticks state (each grid line is labelled with its value; the map recorded on
//! the root element must agree with it, so a wrong scale fails), everything drawn lies inside
//! the picture, the world lines of the space-time pictures have the bodies' velocities as
//! slopes, and case A's picture is pinned byte for byte (it is the README's picture,
//! `examples/case-a.svg`; `UPDATE_SNAPSHOTS=1` refreshes it).

use crate::common;

use common::collide;

fn svg(args: &[&str]) -> String {
    let out = collide().arg("plot").args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// A linear axis `screen = origin + scale * value`.
#[derive(Clone, Copy, Debug)]
struct Axis {
    origin: f64,
    scale: f64,
}

impl Axis {
    /// The axis through labelled grid lines `(screen, value)`: from the outermost two, and every
    /// other one must lie on it (to the two decimals of the screen coordinates).
    fn through(ticks: &[(f64, f64)]) -> Axis {
        assert!(
            ticks.len() >= 2,
            "an axis needs two labelled ticks: {ticks:?}"
        );
        let ((p0, v0), (p1, v1)) = (ticks[0], ticks[ticks.len() - 1]);
        let scale = (p1 - p0) / (v1 - v0);
        let axis = Axis {
            origin: p0 - scale * v0,
            scale,
        };
        for &(p, v) in ticks {
            assert!(
                (axis.at(v) - p).abs() < 0.011,
                "tick {v} at {p}, not on {axis:?}"
            );
        }
        axis
    }
    fn at(&self, v: f64) -> f64 {
        self.origin + self.scale * v
    }
    fn value(&self, p: f64) -> f64 {
        (p - self.origin) / self.scale
    }
}

/// The screen map `X = ox + s x`, `Y = oy - s y` and a way to read elements by id.
struct Picture {
    doc: String,
}

impl Picture {
    fn new(text: String) -> Picture {
        roxmltree::Document::parse(&text).expect("the SVG is well-formed XML");
        Picture { doc: text }
    }
    fn with<T>(&self, f: impl FnOnce(&roxmltree::Document) -> T) -> T {
        f(&roxmltree::Document::parse(&self.doc).unwrap())
    }
    /// The axes the grid states: each grid line (`stroke="#f3f4f6"`) followed by its label,
    /// vertical lines across, horizontal ones up.
    fn axes(&self) -> (Axis, Axis) {
        self.with(|d| {
            let nodes: Vec<roxmltree::Node> = d
                .root_element()
                .children()
                .filter(|n| n.is_element())
                .collect();
            let (mut across, mut up) = (Vec::new(), Vec::new());
            for w in nodes.windows(2) {
                if w[0].tag_name().name() != "line"
                    || w[0].attribute("stroke") != Some("#f3f4f6")
                    || w[1].tag_name().name() != "text"
                {
                    continue;
                }
                let g = |k: &str| w[0].attribute(k).unwrap().parse::<f64>().unwrap();
                let value: f64 = w[1].text().unwrap().parse().unwrap();
                if g("x1") == g("x2") {
                    across.push((g("x1"), value));
                } else if g("y1") == g("y2") {
                    up.push((g("y1"), value));
                }
            }
            (Axis::through(&across), Axis::through(&up))
        })
    }
    /// The velocity plane's map, from its ticks: equal scales on both axes (a 45-degree line
    /// looks like one), and the same as the map recorded on the root element.
    fn map(&self) -> (f64, f64, f64) {
        let (x, y) = self.axes();
        let s = x.scale;
        assert!(
            (y.scale + s).abs() < 1e-4 * s,
            "unequal scales: {x:?} {y:?}"
        );
        let recorded = self.with(|d| {
            let r = d.root_element();
            let g = |k: &str| r.attribute(k).unwrap().parse::<f64>().unwrap();
            (g("data-origin-x"), g("data-origin-y"), g("data-scale"))
        });
        assert!(
            (recorded.0 - x.origin).abs() < 0.02
                && (recorded.1 - y.origin).abs() < 0.02
                && (recorded.2 - s).abs() < 1e-4 * s,
            "recorded map {recorded:?}, ticks say ({}, {}, {s})",
            x.origin,
            y.origin
        );
        recorded
    }
    fn attr(&self, id: &str, name: &str) -> f64 {
        self.with(|d| {
            let n = d
                .descendants()
                .find(|n| n.attribute("id") == Some(id))
                .unwrap_or_else(|| panic!("no #{id}"));
            n.attribute(name).unwrap().parse().unwrap()
        })
    }
    fn has(&self, id: &str) -> bool {
        self.with(|d| d.descendants().any(|n| n.attribute("id") == Some(id)))
    }
    /// Screen position of a data point.
    fn at(&self, (x, y): (f64, f64)) -> (f64, f64) {
        let (ox, oy, s) = self.map();
        (ox + s * x, oy - s * y)
    }
    /// The points of polyline `id`.
    fn polyline(&self, id: &str) -> Vec<(f64, f64)> {
        self.with(|d| {
            let n = d
                .descendants()
                .find(|n| n.attribute("id") == Some(id))
                .unwrap_or_else(|| panic!("no #{id}"));
            n.attribute("points")
                .unwrap()
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
    }
    /// Every position drawn: circle centres (widened by their radius), line ends, polyline
    /// points and text anchors, with the element's name.
    fn drawn(&self) -> Vec<(String, f64, f64, f64)> {
        self.with(|d| {
            let mut out = Vec::new();
            for n in d.descendants().filter(|n| n.is_element()) {
                let g = |k: &str| n.attribute(k).and_then(|v| v.parse::<f64>().ok());
                let name = format!(
                    "{} {}",
                    n.tag_name().name(),
                    n.attribute("id").unwrap_or("")
                );
                match n.tag_name().name() {
                    "circle" => {
                        out.push((name, g("cx").unwrap(), g("cy").unwrap(), g("r").unwrap()))
                    }
                    "line" => {
                        out.push((name.clone(), g("x1").unwrap(), g("y1").unwrap(), 0.0));
                        out.push((name, g("x2").unwrap(), g("y2").unwrap(), 0.0));
                    }
                    "text" => out.push((name, g("x").unwrap(), g("y").unwrap(), 0.0)),
                    "polyline" => {
                        for (x, y) in self.polyline(n.attribute("id").unwrap()) {
                            out.push((name.clone(), x, y, 0.0));
                        }
                    }
                    _ => {}
                }
            }
            out
        })
    }
    /// The viewBox `(x, y, width, height)`.
    fn view_box(&self) -> [f64; 4] {
        self.with(|d| {
            let v: Vec<f64> = d
                .root_element()
                .attribute("viewBox")
                .unwrap()
                .split_whitespace()
                .map(|x| x.parse().unwrap())
                .collect();
            [v[0], v[1], v[2], v[3]]
        })
    }
}

/// Screen coordinates are written with two decimals.
const PX: f64 = 0.006;

#[test]
fn case_a_geometry() {
    let p = Picture::new(svg(&["-m", "4,1", "-v", "60,10"]));
    // IN, COM and FIN where the lecture puts them: (60, 10), (50, 50), (40, 90).
    for (id, v) in [
        ("point-in", (60.0, 10.0)),
        ("point-com", (50.0, 50.0)),
        ("point-fin", (40.0, 90.0)),
    ] {
        let (x, y) = p.at(v);
        assert!(
            (p.attr(id, "cx") - x).abs() < PX && (p.attr(id, "cy") - y).abs() < PX,
            "{id}"
        );
    }
    // The momentum line 4 V1 + V2 = 250 passes through all three.
    let (x1, y1, x2, y2) = (
        p.attr("momentum-line", "x1"),
        p.attr("momentum-line", "y1"),
        p.attr("momentum-line", "x2"),
        p.attr("momentum-line", "y2"),
    );
    for id in ["point-in", "point-com", "point-fin"] {
        let (x, y) = (p.attr(id, "cx"), p.attr(id, "cy"));
        let cross = (x2 - x1) * (y - y1) - (y2 - y1) * (x - x1);
        let dist = cross.abs() / (x2 - x1).hypot(y2 - y1);
        assert!(dist < 0.02, "{id} is {dist} px off the momentum line");
    }
    // Ellipse radii sqrt(2 KE / M_i) in the picture's scale: IN a = sqrt(14500/4), b = sqrt(14500);
    // COM a = sqrt(12500/4), b = sqrt(12500) (lecture: 60.21, 120.42; 55.90, 111.80).
    let (_, _, s) = p.map();
    for (id, a, b) in [
        ("ellipse-in", 14500f64 / 4.0, 14500f64),
        ("ellipse-com", 12500f64 / 4.0, 12500f64),
    ] {
        assert!((p.attr(id, "rx") - a.sqrt() * s).abs() < PX, "{id} rx");
        assert!((p.attr(id, "ry") - b.sqrt() * s).abs() < PX, "{id} ry");
        assert!(
            (p.attr(id, "cx") - p.at((0.0, 0.0)).0).abs() < PX,
            "{id} centred at the origin"
        );
    }
    // Elastic: no separate FIN ellipse (it is the IN ellipse).
    assert!(!p.has("ellipse-fin"));
    // Equal scales: the 45-degree line rises as much as it runs.
    let (dx, dy) = (
        p.attr("diagonal", "x2") - p.attr("diagonal", "x1"),
        p.attr("diagonal", "y1") - p.attr("diagonal", "y2"),
    );
    assert!((dx - dy).abs() < 0.02, "45 degrees looks like 45 degrees");
}

#[test]
fn ka_whump_draws_a_fin_ellipse_and_stuck_bodies_share_a_point() {
    let p = Picture::new(svg(&["-m", "6,1", "-v", "3,-4", "-e", "2/3"]));
    let (_, _, s) = p.map();
    // KE_FIN = 70/3: radii sqrt(2 KE / 6) and sqrt(2 KE / 1).
    assert!((p.attr("ellipse-fin", "rx") - (140.0f64 / 3.0 / 6.0).sqrt() * s).abs() < PX);
    assert!((p.attr("ellipse-fin", "ry") - (140.0f64 / 3.0).sqrt() * s).abs() < PX);
    let p = Picture::new(svg(&["-m", "6,1", "-v", "3,-4", "-e", "0"]));
    assert!(
        !p.has("point-fin") && p.has("point-com"),
        "FIN is COM when the bodies stick"
    );
}

#[test]
fn a_general_tensor_gives_turned_ellipses() {
    let text = svg(&["--inertia", "4,0.5;0.5,1", "-v", "60,10"]);
    let p = Picture::new(text.clone());
    assert!(
        text.contains("id=\"ellipse-in\"") && text.contains("transform=\"rotate("),
        "turned"
    );
    let (_, _, s) = p.map();
    // Radii along the eigenvectors: lambda = (5 -+ sqrt 10)/2, KE_IN = 7550.
    let (l1, l2) = ((5.0 - 10f64.sqrt()) / 2.0, (5.0 + 10f64.sqrt()) / 2.0);
    assert!((p.attr("ellipse-in", "rx") - (2.0 * 7550.0 / l1).sqrt() * s).abs() < PX);
    assert!((p.attr("ellipse-in", "ry") - (2.0 * 7550.0 / l2).sqrt() * s).abs() < PX);
}

/// Every circle, line end, polyline point and label lies inside the viewBox, for pictures of
/// ordinary, extreme and degenerate cases, of every kind.
#[test]
fn everything_drawn_lies_inside_the_picture() {
    for args in [
        &["-m", "4,1", "-v", "60,10"][..],
        &["-m", "6,1", "-v", "3,-4", "-e", "2/3", "--frames"],
        &["-m", "6,1", "-v", "3,-4", "--frame", "rest-fin:2"],
        &["--inertia", "4,0.5;0.5,1", "-v", "60,10"],
        &["-m", "1e-20,1e20", "-v", "1e-5,-3e7"],
        &["-m", "1,1", "-v", "5,5"],
        &["-m", "1,1", "-v", "0,0"],
        &["-m", "6,1", "-v", "3,-4", "--kind", "newton"],
        &["-m", "6,1", "-v", "3,-4", "--kind", "minkowski"],
        &[
            "-m", "1,1e6", "-v", "-250,0.5", "--kind", "newton", "-e", "0",
        ],
    ] {
        let p = Picture::new(svg(args));
        let [x0, y0, w, h] = p.view_box();
        for (what, x, y, r) in p.drawn() {
            assert!(
                x - r >= x0 && x + r <= x0 + w && y - r >= y0 && y + r <= y0 + h,
                "{args:?}: {what} at ({x}, {y}) r {r} is outside the viewBox {w} x {h}"
            );
        }
    }
}

/// The world lines of the space-time pictures, read through the axes their ticks state: each
/// body's line passes through the collision event (0, 0) and has the body's velocity as its
/// slope, V_IN before and V_FIN after (case B: (3, -4) -> (1, 8); ka-runch: both 2).
#[test]
fn world_lines_have_the_velocities_as_slopes() {
    for (e, fin) in [("1", [1.0f64, 8.0]), ("0", [2.0, 2.0])] {
        for kind in ["newton", "minkowski"] {
            let p = Picture::new(svg(&["-m", "6,1", "-v", "3,-4", "-e", e, "--kind", kind]));
            let (across, up) = p.axes();
            // Newton: time across, position up; Minkowski: position across, time up.
            let tx = |(a, u): (f64, f64)| {
                let (a, u) = (across.value(a), up.value(u));
                if kind == "newton" { (a, u) } else { (u, a) }
            };
            // Half a hundredth of a pixel, in data units, on each axis.
            let (dt, dx) = if kind == "newton" {
                (0.006 / across.scale.abs(), 0.006 / up.scale.abs())
            } else {
                (0.006 / up.scale.abs(), 0.006 / across.scale.abs())
            };
            let event = tx((p.attr("event", "cx"), p.attr("event", "cy")));
            assert!(
                event.0.abs() < dt && event.1.abs() < dx,
                "{kind}: event at {event:?}"
            );
            for (i, (v_in, v_fin)) in [(3.0, fin[0]), (-4.0, fin[1])].into_iter().enumerate() {
                let pts: Vec<(f64, f64)> = p
                    .polyline(&format!("world-line-{}", i + 1))
                    .into_iter()
                    .map(tx)
                    .collect();
                assert_eq!(pts.len(), 3, "{kind}");
                assert!(
                    pts[1].0.abs() < dt && pts[1].1.abs() < dx,
                    "{kind}: bend at {:?}",
                    pts[1]
                );
                for (a, b, v) in [(pts[0], pts[1], v_in), (pts[1], pts[2], v_fin)] {
                    let slope = (b.1 - a.1) / (b.0 - a.0);
                    // The slope's error from rounding both ends to 0.01 px, over one unit of time.
                    let tol = 2.0 * dx / (b.0 - a.0).abs() + 2.0 * dt * v.abs();
                    assert!(
                        (slope - v).abs() <= tol,
                        "{kind} e = {e}: body {} slope {slope} against {v} (tol {tol:e})",
                        i + 1
                    );
                }
            }
        }
    }
}

#[test]
fn frames_and_spacetime_pictures() {
    let p = Picture::new(svg(&["-m", "6,1", "-v", "3,-4", "--frames"]));
    assert!(
        p.has("frame-0") && p.has("frame-4"),
        "five other standard frames"
    );
    // In the COM frame COM is at the origin.
    let p = Picture::new(svg(&["-m", "6,1", "-v", "3,-4", "--frame", "com"]));
    let (x, y) = p.at((0.0, 0.0));
    assert!(
        (p.attr("point-com", "cx") - x).abs() < PX && (p.attr("point-com", "cy") - y).abs() < PX
    );
    for kind in ["newton", "minkowski"] {
        let p = Picture::new(svg(&["-m", "6,1", "-v", "3,-4", "--kind", kind]));
        assert!(
            p.has("world-line-1") && p.has("world-line-2") && p.has("event"),
            "{kind}"
        );
    }
}

#[test]
fn the_picture_is_deterministic_and_pinned() {
    let a = svg(&["-m", "4,1", "-v", "60,10"]);
    assert_eq!(
        a,
        svg(&["-m", "4,1", "-v", "60,10"]),
        "same input, same bytes"
    );
    let pinned = "examples/case-a.svg";
    if std::env::var_os("UPDATE_SNAPSHOTS").is_some() {
        std::fs::write(pinned, &a).unwrap();
    }
    assert_eq!(
        a,
        std::fs::read_to_string(pinned).unwrap(),
        "case A's picture changed (UPDATE_SNAPSHOTS=1 refreshes {pinned})"
    );
}

#[test]
fn terminal_plot_fits_the_width() {
    let out = collide()
        .args(["plot", "-m", "4,1", "-v", "60,10", "--term"])
        .env("COLUMNS", "60")
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("I = IN (60, 10)   C = COM (50, 50)   F = FIN (40, 90)"),
        "{text}"
    );
    let canvas: Vec<&str> = text
        .lines()
        .filter(|l| l.chars().any(|c| ('\u{2800}'..='\u{28ff}').contains(&c)))
        .collect();
    assert!(canvas.len() > 10);
    assert!(
        canvas.iter().all(|l| l.chars().count() <= 60),
        "fits 60 columns"
    );
    // solve --plot term prints the report, then the picture.
    let out = collide()
        .args(["solve", "-m", "4,1", "-v", "60,10", "--plot", "term"])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("Quadratic forms") && text.contains("I = IN (60, 10)"));
}

#[test]
fn solve_and_scenes_write_svg_files() {
    let dir = std::env::temp_dir().join(format!("collide-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("a.svg");
    collide()
        .args([
            "solve",
            "-m",
            "4,1",
            "-v",
            "60,10",
            "--plot",
            file.to_str().unwrap(),
        ])
        .assert()
        .success();
    Picture::new(std::fs::read_to_string(&file).unwrap());
    let scene = dir.join("s.toml");
    let out = dir.join("s.svg");
    // Beside the scene (an absolute path is refused).
    std::fs::write(&scene, "masses = [4, 1]\nvelocities = [60, 10]\n[plot]\noutput = \"s.svg\"\nkind = \"minkowski\"\n").unwrap();
    collide()
        .args(["scene", scene.to_str().unwrap()])
        .assert()
        .success();
    assert!(
        std::fs::read_to_string(&out)
            .unwrap()
            .contains("world-line-1")
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn hostile_pictures_never_draw_nan_or_inf() {
    // No motion at all: a unit box, not a zero-size one.
    for kind in ["velocity", "newton", "minkowski"] {
        let text = svg(&["-m", "1,1", "-v", "0,0", "--kind", kind]);
        Picture::new(text.clone());
        assert!(!text.contains("NaN") && !text.contains("inf"), "{kind}");
    }
    // Energies beyond binary64 are refused by name, not drawn.
    let out = collide()
        .args(["plot", "-m", "1,1", "-v", "1e200,-1e200"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("energy.in is not representable"));
}
