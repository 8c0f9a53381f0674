//! Pictures: the SVG parses as XML, its elements have the right geometry in the picture's own
//! data-to-screen map (recorded on the root element), and case A's picture is pinned byte for
//! byte (it is the README's picture, `examples/case-a.svg`; `UPDATE_SNAPSHOTS=1` refreshes it).

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
    fn map(&self) -> (f64, f64, f64) {
        self.with(|d| {
            let r = d.root_element();
            let g = |k: &str| r.attribute(k).unwrap().parse::<f64>().unwrap();
            (g("data-origin-x"), g("data-origin-y"), g("data-scale"))
        })
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
