//! Issue 13's regressions fixed so far, each as the command: labels from the exact
//! values, the same inputs in both modes, JSON that stays JSON, failed consistency checks,
//! exact expectations, and two-value arrays.

use crate::common;

use common::run;

pub(crate) fn scratch(name: &str, text: &str) -> std::path::PathBuf {
    let path = std::env::temp_dir().join(format!("collide-hostile-{}-{name}", std::process::id()));
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_restitution_above_1_as_typed_is_superelastic_in_both_modes() {
    // Issue 13 asked that binary64 and --exact accept the same inputs and label them from the
    // typed value; issue 15 made e > 1 superelastic rather than refused. 1.0000000000000001
    // rounds to 1 in binary64, but it releases (e^2 - 1) crunch = (2e-16 + 1e-32) 21
    // = 4.2e-15 + 2.1e-31 (binary64: the exact factor rounded once, times 21).
    for (exact, released) in [
        (false, "4.2e-15"),
        (true, "0.00000000000000420000000000000021"),
    ] {
        let mut args = vec![
            "solve",
            "-m",
            "6,1",
            "-v",
            "3,-4",
            "-e",
            "1.0000000000000001",
            "--show",
            "energy",
        ];
        if exact {
            args.push("--exact");
        }
        let (code, out, err) = run(&args);
        assert_eq!(code, 0, "exact = {exact}: {err}");
        assert!(out.contains("(superelastic: energy released)"), "{out}");
        assert!(!out.contains("conserved") && !out.contains("lost"), "{out}");
        let line = out.lines().find(|l| l.contains("released =")).unwrap();
        assert!(line.contains(&format!(" {released} ")), "{line}");
    }
    // Just below 0 as typed, though it rounds to -0.
    let (code, _, err) = run(&["solve", "-m", "6,1", "-v", "3,-4", "-e", "-1e-400"]);
    assert_eq!(code, 2, "{err}");
}

#[test]
fn labels_follow_the_exact_values() {
    let (code, out, _) = run(&[
        "solve",
        "-m",
        "6,1",
        "-v",
        "3,-4",
        "-e",
        "0.99999999999999999999999",
        "--exact",
        "--show",
        "energy",
    ]);
    assert_eq!(code, 0);
    assert!(
        !out.contains("elastic") && !out.contains("conserved"),
        "{out}"
    );
    // lost = (1 - e^2) crunch = (2e-23 - 1e-46) 21, shown to 20 digits.
    assert!(
        out.contains("lost = (1 - e^2) crunch") && out.contains("4.1999999999999999999e-22"),
        "{out}"
    );
    // Exactly 1 is elastic, in either spelling.
    for e in ["1", "1.000", "elastic", "3/3"] {
        let (_, out, _) = run(&[
            "solve", "-m", "6,1", "-v", "3,-4", "-e", e, "--exact", "--show", "energy",
        ]);
        assert!(out.contains("elastic: energy is conserved"), "{e}: {out}");
    }
}

#[test]
fn json_with_a_terminal_plot_is_refused() {
    let (code, out, err) = run(&[
        "solve", "-m", "4,1", "-v", "60,10", "--format", "json", "--plot", "term",
    ]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(
        err.contains("--plot term") && err.contains("--plot FILE.svg"),
        "{err}"
    );
}

#[test]
fn a_failed_consistency_check_exits_1() {
    let (code, out, _) = run(&[
        "solve", "-m", "4,1", "-v", "60,10", "--fin", "40,90", "-e", "0.5",
    ]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("restitution does NOT hold"));
    let (code, out, _) = run(&[
        "solve", "-m", "4,1", "-v", "60,10", "--fin", "40,90", "-e", "1",
    ]);
    assert_eq!(code, 0, "{out}");
    // In a scene as well.
    let scene = scratch(
        "inconsistent.toml",
        "masses = [4, 1]\nvelocities = [60, 10]\nfin = [40, 90]\nrestitution = 0.5\n",
    );
    let (code, out, _) = run(&["scene", scene.to_str().unwrap()]);
    assert_eq!(code, 1, "{out}");
    std::fs::remove_file(scene).unwrap();
}

#[test]
fn exact_scenes_compare_exact_values_as_fractions() {
    let base = std::fs::read_to_string("scenarios/fig-2-3-ka-whump-exact.toml").unwrap();
    assert!(base.contains("\n\"energy.lost\" = \"35/3\"\n"));
    for (expectation, pass) in [
        ("{ value = \"11.6666666666666666\", rel = 0 }", false),
        ("{ value = \"35/3\", rel = 0 }", true),
        ("{ value = \"11.6666666666666666\", rel = 1e-17 }", true),
        ("{ value = \"70/6\", abs = 0 }", true),
    ] {
        let text = base.replace(
            "\n\"energy.lost\" = \"35/3\"\n",
            &format!("\n\"energy.lost\" = {expectation}\n"),
        );
        let scene = scratch("exact.toml", &text);
        let (code, out, err) = run(&["scene", scene.to_str().unwrap()]);
        assert_eq!(code, if pass { 0 } else { 1 }, "{expectation}: {out}{err}");
        std::fs::remove_file(scene).unwrap();
    }
}

#[test]
fn two_value_arrays_take_exactly_two() {
    for (text, at) in [
        (
            "masses = [4, 1]\nvelocities = [60, 10, 99, \"garbage\"]\n",
            ":2:14: invalid length 4",
        ),
        (
            "masses = [4]\nvelocities = [60, 10]\n",
            ":1:10: invalid length 1",
        ),
        (
            "masses = [4, 1]\nvelocities = [60, 10]\nfin = [1, 2, 3]\n",
            ":3:7: invalid length 3",
        ),
        (
            "inertia = [[4, 0.5, 1], [0.5, 1]]\nvelocities = [60, 10]\n",
            "invalid length 3",
        ),
    ] {
        let scene = scratch("two.toml", text);
        let (code, out, err) = run(&["scene", scene.to_str().unwrap()]);
        assert_eq!(code, 2, "{text}");
        assert!(out.is_empty());
        assert!(
            err.contains(at) && err.contains("expected exactly 2 values"),
            "{err}"
        );
        std::fs::remove_file(scene).unwrap();
    }
}

#[test]
fn a_closed_stderr_is_no_panic() {
    // The command: bad rows reported to a stderr whose reader has gone.
    let bin = assert_cmd::cargo::cargo_bin("collide");
    let script = format!(
        "{} batch scenarios/cases.csv --skip-bad -o /dev/null 2>&1 | head -c 0; echo \"${{PIPESTATUS[0]}}\"",
        bin.display()
    );
    let out = std::process::Command::new("bash")
        .args(["-c", &script])
        .output()
        .unwrap();
    let status = String::from_utf8_lossy(&out.stdout);
    assert!(
        status.trim() == "0" || status.trim() == "141",
        "exit {status}"
    );
}

#[test]
fn long_arguments_give_short_messages_at_once() {
    let long = format!("4,{}x", "1".repeat(100_000));
    let start = std::time::Instant::now();
    let (code, out, err) = run(&["solve", "-m", &long, "-v", "1,2"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(
        err.len() < 3000 && err.contains("characters cut"),
        "{} bytes",
        err.len()
    );
    // Refused by its length (over 10,000 characters) before it is parsed.
    assert!(err.contains("100001 characters"), "{err}");
    // Not a timing assertion on the machine: a quadratic parse took over a minute here.
    assert!(start.elapsed().as_secs() < 30);
}

#[test]
fn write_errors_name_the_path() {
    // Linux has /dev/full (every write fails with ENOSPC); a machine without it cannot run this
    // test, which must then fail, not pass unchecked.
    assert!(
        std::path::Path::new("/dev/full").exists(),
        "/dev/full is missing: this test needs it"
    );
    let (code, _, err) = run(&[
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "e=0:1:11",
        "-o",
        "/dev/full",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("cannot write /dev/full: "), "{err}");
}

#[test]
fn frames_are_for_the_velocity_diagram() {
    for kind in ["newton", "minkowski"] {
        let (code, out, err) = run(&[
            "plot", "-m", "4,1", "-v", "60,10", "--kind", kind, "--frames",
        ]);
        assert_eq!(code, 2, "{kind}");
        assert!(out.is_empty());
        assert!(err.contains("--frames overlays"), "{err}");
    }
}

#[test]
fn scene_titles_cannot_send_escape_sequences() {
    let scene = scratch(
        "title.toml",
        "title = \"a\\u001b[31mred\"\nmasses = [4, 1]\nvelocities = [60, 10]\n",
    );
    let (code, out, _) = run(&["scene", scene.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(
        !out.contains('\u{1b}') && out.starts_with("a\\u{1b}[31mred"),
        "{out}"
    );
    std::fs::remove_file(scene).unwrap();
}

#[test]
fn scene_files_are_read_with_a_size_cap() {
    assert!(
        std::path::Path::new("/dev/zero").exists(),
        "/dev/zero is missing: this test needs it"
    );
    let (code, out, err) = run(&["scene", "/dev/zero"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(
        err.contains("/dev/zero: the scene file is larger than 1048576 bytes"),
        "{err}"
    );
    let binary = scratch("binary.toml", "");
    std::fs::write(&binary, b"title = \"\xff\"\n").unwrap();
    let (code, _, err) = run(&["scene", binary.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("not UTF-8"), "{err}");
    std::fs::remove_file(binary).unwrap();
}

#[test]
fn dash_o_dash_is_stdout() {
    let (code, out, _) = run(&[
        "sweep", "-m", "4,1", "-v", "60,10", "--vary", "e=0:1:3", "-o", "-",
    ]);
    assert_eq!(code, 0);
    assert_eq!(out.lines().count(), 4, "{out}");
    assert!(!std::path::Path::new("-").exists());
}

#[test]
fn one_bad_scene_among_several_does_not_stop_the_others() {
    let bad = scratch("bad-among.toml", "masses = [4]\nvelocities = [60, 10]\n");
    let bad = bad.to_str().unwrap();
    let (code, out, err) = run(&[
        "scene",
        "scenarios/fig-1-3-elastic.toml",
        bad,
        "scenarios/superball-2.toml",
    ]);
    assert_eq!(code, 2, "the worst status");
    assert!(
        out.contains("2 scenes: 2 pass, 0 fail")
            && out.contains("1 scene file could not be solved"),
        "{out}"
    );
    assert!(
        err.contains(&format!("{bad}:1:10: invalid length 1")),
        "{err}"
    );
    let (code, out, _) = run(&["scene", bad, bad]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    std::fs::remove_file(bad).unwrap();
}

#[test]
fn a_sweep_too_large_is_refused_before_anything_is_computed() {
    let start = std::time::Instant::now();
    let (code, out, err) = run(&[
        "sweep",
        "-m",
        "4,1",
        "-v",
        "60,10",
        "--vary",
        "v1=1e-30:1e30:4000000",
        "--max-rows",
        "1",
    ]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(
        err.contains("4.000e6 rows, more than --max-rows 1"),
        "{err}"
    );
    // Generous: it took over 60 s when the 4 M values were computed first.
    assert!(start.elapsed().as_secs() < 20);
}

#[test]
fn a_jsonl_line_that_is_not_utf8_is_one_bad_row() {
    let input = scratch("bad.jsonl", "");
    std::fs::write(
        &input,
        b"\xff\xfe{\"m1\":1}\n{\"m1\":4,\"m2\":1,\"v1\":60,\"v2\":10}\r\n\n{\"m1\":6,\"m2\":1,\"v1\":3,\"v2\":-4}\n",
    )
    .unwrap();
    let path = input.to_str().unwrap();
    let (code, out, err) = run(&[
        "batch",
        path,
        "--input-format",
        "jsonl",
        "--skip-bad",
        "--columns",
        "fin1,fin2",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, "fin1,fin2\n40.0,90.0\n1.0,8.0\n");
    assert!(
        err.contains("skipped line 1: cannot read: the line is not valid UTF-8"),
        "{err}"
    );
    assert!(err.contains("2 rows written, 1 bad rows skipped"), "{err}");
    // Without --skip-bad the bad line stops the run.
    let (code, _, err) = run(&["batch", path, "--input-format", "jsonl"]);
    assert_eq!(code, 2, "{err}");
    std::fs::remove_file(input).unwrap();
}

#[test]
fn log_steps_from_the_subnormal_range_do_not_overflow() {
    // 1e-310 to 1e300 in 7 log steps: 10^(-310 + 610 i / 6), all representable. Expected to 15
    // digits: 10^(2/3) = 4.64158883361278, 10^(1/3) = 2.15443469003188.
    let (code, out, err) = run(&[
        "sweep",
        "-m",
        "1,1",
        "-v",
        "1,1e-300",
        "--vary",
        "v2=1e-310:1e300:7:log",
        "--skip-bad",
        "--columns",
        "v2",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("skipped"), "{err}");
    assert_eq!(
        out,
        "v2\n1e-310\n4.64158883361278e-209\n2.15443469003188e-107\n0.00001\n\
         4.64158883361278e96\n2.15443469003188e198\n1e300\n"
    );
}

#[test]
fn dash_o_treats_files_as_the_shell_does() {
    use std::os::unix::fs::PermissionsExt;
    let dir = std::env::temp_dir().join(format!("collide-hostile-o-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let sweep = |out: &std::path::Path| {
        let (code, _, err) = run(&[
            "sweep",
            "-m",
            "4,1",
            "-v",
            "60,10",
            "--vary",
            "e=0:1:3",
            "-o",
            out.to_str().unwrap(),
        ]);
        assert_eq!(code, 0, "{err}");
    };
    // A dangling symlink: its target is created, the link stays a link.
    let link = dir.join("link.csv");
    std::os::unix::fs::symlink("real.csv", &link).unwrap();
    sweep(&link);
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("real.csv"))
            .unwrap()
            .lines()
            .count(),
        4
    );
    // An existing file keeps its permission bits.
    let kept = dir.join("kept.csv");
    std::fs::write(&kept, "old\n").unwrap();
    std::fs::set_permissions(&kept, std::fs::Permissions::from_mode(0o640)).unwrap();
    sweep(&kept);
    assert_eq!(
        std::fs::metadata(&kept).unwrap().permissions().mode() & 0o777,
        0o640
    );
    // A legal 254-byte name (the temporary file's name must fit too).
    let long = dir.join(format!("{}.csv", "a".repeat(250)));
    sweep(&long);
    assert!(long.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn long_numbers_within_the_limits_work_and_beyond_are_refused_at_once() {
    // m1 from momentum with a 9,000-digit V1 = 60.333...: m1 = 80 / (V1 - 40) = 240/61 to
    // thousands of digits (it was refused as "too large for binary64", with a 40 KB message).
    let v1 = format!("60.{}", "3".repeat(9000));
    let (code, out, err) = run(&[
        "solve",
        "-m",
        "?,1",
        "-v",
        &format!("{v1},10"),
        "--fin",
        "40,90",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{}", &err[..err.len().min(300)]);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let m1 = j["solved"]["m1"].as_f64().unwrap();
    assert!((m1 - 240.0 / 61.0).abs() <= 4.0 * f64::EPSILON * m1, "{m1}");
    // A fraction is judged by its value: 1e9999/1e10000 is 0.1.
    let (code, out, _) = run(&[
        "solve",
        "-m",
        "1,1",
        "-v",
        "1e9999/1e10000,0",
        "--show",
        "vectors",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(j["in"][0], 0.1);
    // Past 10,000 characters a number is refused by its length, with a short message.
    let long = "1".repeat(10_001);
    let (code, out, err) = run(&["solve", "-m", &format!("{long},1"), "-v", "1,0"]);
    assert_eq!(code, 2);
    // clap quotes the value; the message is cut to about 2,000 characters.
    assert!(
        out.is_empty() && err.contains("10001 characters") && err.len() < 2100,
        "{err}"
    );
    // A 2 M-digit batch field: one bad row, at once.
    let csv = scratch(
        "long.csv",
        &format!("m1,m2,v1,v2\n{},1,1,0\n4,1,60,10\n", "1".repeat(2_000_000)),
    );
    let (code, out, err) = run(&[
        "batch",
        csv.to_str().unwrap(),
        "--skip-bad",
        "--columns",
        "fin1",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, "fin1\n40.0\n");
    assert!(err.contains("2000000 characters"), "{err}");
    // --exact reads up to 1,000 characters per typed number.
    let ok = format!("3.{}", "1".repeat(998));
    let (code, _, err) = run(&["solve", "-m", &format!("{ok},1"), "-v", "1,0", "--exact"]);
    assert_eq!(code, 0, "{err}");
    let over = format!("3.{}", "1".repeat(999));
    for cmd in ["solve", "frames"] {
        let (code, out, err) = run(&[cmd, "-m", &format!("{over},1"), "-v", "1,0", "--exact"]);
        assert_eq!(code, 2, "{cmd}");
        assert!(out.is_empty() && err.contains("at most 1000"), "{err}");
    }
}

#[test]
fn a_thousand_character_exact_case_is_exact() {
    // The lecture's Fig. 1.3 (m = 4, 1; V = 60, 10; elastic; FIN = 40, 90) seen by an observer
    // moving at -x, x a 997-digit decimal: every velocity gains x (Galilean invariance), so
    // FIN = (40 + x, 90 + x) exactly and the crunch is still 1000. x's last digit is 7, so each
    // velocity's fraction N / 10^997 is already in lowest terms and its digits are known.
    let mut digits: String = (0..996u32)
        .map(|i| char::from_digit(i * i % 7 + i % 3, 10).unwrap())
        .collect();
    digits.push('7');
    let v = format!("60.{digits},10.{digits}");
    assert_eq!(
        v.split(',').next().unwrap().len(),
        1000,
        "the --exact limit"
    );
    let (code, out, err) = run(&[
        "solve", "-m", "4,1", "-v", &v, "-e", "1", "--exact", "--format", "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    let den = format!("1{}", "0".repeat(997));
    let at = |int: &str| format!("{int}{digits}/{den}");
    assert_eq!(json["fin"][0], at("40"));
    assert_eq!(json["fin"][1], at("90"));
    assert_eq!(json["v_com"], at("50"));
    assert_eq!(json["energy"]["crunch"], "1000");
    assert_eq!(json["energy"]["lost"], "0");
}

#[test]
fn a_scene_draws_only_beside_itself_and_replaces_only_svg() {
    let dir = std::env::temp_dir().join(format!("collide-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = |name: &str, output: &str| {
        let p = dir.join(name);
        std::fs::write(
            &p,
            format!("masses = [4, 1]\nvelocities = [60, 10]\n[plot]\noutput = \"{output}\"\n"),
        )
        .unwrap();
        p
    };
    // Relative to the scene's folder, not the working directory.
    let p = scene("ok.toml", "ok.svg");
    let (code, out, err) = run(&["scene", p.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains(&format!("wrote {}", dir.join("ok.svg").display())),
        "{out}"
    );
    assert!(
        std::fs::read_to_string(dir.join("ok.svg"))
            .unwrap()
            .starts_with("<svg")
    );
    // Running it again replaces its own picture.
    assert_eq!(run(&["scene", p.to_str().unwrap()]).0, 0);
    // Not an .svg name; an existing file that is not a picture: refused, untouched.
    std::fs::write(dir.join("notes.svg"), "my notes").unwrap();
    for (name, output) in [("txt.toml", "victim.txt"), ("notes.toml", "notes.svg")] {
        let p = scene(name, output);
        let (code, out, err) = run(&["scene", p.to_str().unwrap()]);
        assert_eq!(code, 2, "{output}: {out}");
        assert!(err.contains("[plot]") && err.contains(output), "{err}");
    }
    assert_eq!(
        std::fs::read_to_string(dir.join("notes.svg")).unwrap(),
        "my notes"
    );
    assert!(!dir.join("victim.txt").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn toml_numbers_follow_the_command_line_rule() {
    // `1e-400` in a scene was read as 0; the command line refuses it. Same rule, with the line.
    let p = scratch("tiny.toml", "masses = [4, 1e-400]\nvelocities = [60, 10]\n");
    let (code, out, err) = run(&["scene", p.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        out.is_empty() && err.contains("tiny.toml:1:14") && err.contains("too small"),
        "{err}"
    );
    let (code, _, err) = run(&["solve", "-m", "4,1e-400", "-v", "60,10"]);
    assert_eq!(code, 2);
    assert!(err.contains("too small"), "{err}");
    // In a comment or a string, or with TOML's digit separators, nothing is refused.
    let p = scratch(
        "fine.toml",
        "# 1e-400\ntitle = \"1e-400\"\nmasses = [4, 1_0]\nvelocities = [60, 10]\n[expect]\nin = [60, 10]\n",
    );
    let (code, _, err) = run(&["scene", p.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
}
