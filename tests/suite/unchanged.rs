//! Outputs that use none of issue 42's features stay byte-identical ("Done when" of issue 42):
//! `unchanged.txt` holds nine examples of the guide as it was before the issue's first change
//! (commit d43e761, taken verbatim from its README.md and docs/), on the rail, in the plane and
//! for rigid bodies, in text and JSON. Each must print exactly that. The guide's own examples
//! (`readme.rs`) are refreshed with the code when an output changes on purpose; these are not:
//! a change here is a change of an answer or its layout that nothing in issue 42 asked for.

use crate::readme::Sandbox;

#[test]
fn plain_rail_plane_and_rigid_outputs_are_as_before_issue_42() {
    let text = include_str!("unchanged.txt");
    let mut examples: Vec<(&str, Vec<&str>)> = Vec::new();
    for line in text.lines() {
        match line.strip_prefix("$ ") {
            Some(command) => examples.push((command, Vec::new())),
            None => examples.last_mut().expect("a command first").1.push(line),
        }
    }
    assert_eq!(examples.len(), 9);
    let sandbox = Sandbox::new("unchanged");
    for (command, shown) in examples {
        let run = sandbox.run(command);
        assert_eq!((run.status, run.stderr.as_str()), (0, ""), "{command}");
        assert!(
            run.stdout == shown.join("\n").trim_end(),
            "$ {command}\n--- before issue 42:\n{}\n--- now:\n{}",
            shown.join("\n"),
            run.stdout
        );
    }
}
