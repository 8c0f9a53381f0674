//! Every README example is real: each ```console block's `$ collide ...` commands are run and
//! their output (stdout, then stderr) must match the block exactly. To refresh the README after
//! a deliberate change of output: `UPDATE_README=1 cargo test --release --test suite readme`.

use crate::common;

use common::collide;

/// Splits a command line on spaces, keeping '...' quoted words whole and expanding a
/// `dir/*.ext` glob (sorted), as a shell would for the README's commands.
fn words(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut word = String::new();
    let mut quoted = false;
    for ch in line.chars() {
        match ch {
            '\'' => quoted = !quoted,
            ' ' if !quoted => {
                if !word.is_empty() {
                    out.push(std::mem::take(&mut word));
                }
            }
            c => word.push(c),
        }
    }
    if !word.is_empty() {
        out.push(word);
    }
    out.into_iter()
        .flat_map(|w| match w.split_once("/*") {
            Some((dir, ext)) => {
                let mut paths: Vec<String> = std::fs::read_dir(dir)
                    .unwrap()
                    .map(|e| e.unwrap().path().display().to_string())
                    .filter(|p| p.ends_with(ext))
                    .collect();
                paths.sort();
                paths
            }
            None => vec![w],
        })
        .collect()
}

fn run(command: &str) -> String {
    let args = words(
        command
            .strip_prefix("collide ")
            .expect("README commands start with collide"),
    );
    let out = collide().args(&args).output().unwrap();
    let mut text = String::from_utf8(out.stdout).unwrap();
    text.push_str(&String::from_utf8(out.stderr).unwrap());
    text.trim_end().to_string()
}

#[test]
fn readme_examples_print_what_they_show() {
    let readme = std::fs::read_to_string("README.md").unwrap();
    let mut updated = Vec::new();
    let mut failures = Vec::new();
    let mut commands = 0;
    let mut lines = readme.lines().peekable();
    while let Some(line) = lines.next() {
        updated.push(line.to_string());
        if line != "```console" {
            continue;
        }
        // A console block: `$ command` lines, each followed by its output, up to the fence.
        let mut block = Vec::new();
        for l in lines.by_ref() {
            if l == "```" {
                break;
            }
            block.push(l);
        }
        let mut i = 0;
        while i < block.len() {
            let command = block[i]
                .strip_prefix("$ ")
                .expect("a console block starts with '$ '");
            let end = (i + 1..block.len())
                .find(|&j| block[j].starts_with("$ "))
                .unwrap_or(block.len());
            let shown = block[i + 1..end].join("\n");
            let actual = run(command);
            commands += 1;
            if actual != shown {
                failures.push(format!(
                    "$ {command}\n--- README shows:\n{shown}\n--- the program prints:\n{actual}\n"
                ));
            }
            updated.push(block[i].to_string());
            updated.extend(actual.lines().map(String::from));
            i = end;
        }
        updated.push("```".to_string());
    }
    assert!(commands >= 12, "only {commands} README commands found");
    if std::env::var_os("UPDATE_README").is_some() {
        std::fs::write("README.md", updated.join("\n") + "\n").unwrap();
        return;
    }
    assert!(
        failures.is_empty(),
        "README examples out of date (UPDATE_README=1 refreshes):\n{}",
        failures.join("\n")
    );
}
