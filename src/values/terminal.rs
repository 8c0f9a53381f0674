//! How wide text for people may be: 80 columns, or `COLUMNS` where it is set, or no limit with
//! `--wide`; and the two ways text is made to fit that width without cutting a number: words
//! wrapped at spaces, and a wide table's columns folded into groups that each fit.
//!
//! The width is set once, by the binary, before anything is rendered (the library never reads the
//! environment); until then it is [`DEFAULT_WIDTH`].

use std::sync::atomic::{AtomicUsize, Ordering};

/// The width of text when neither `COLUMNS` nor `--wide` says otherwise: the classic terminal.
pub const DEFAULT_WIDTH: usize = 80;

/// The narrowest width honoured: a smaller `COLUMNS` is read as this (a layout narrower than a
/// number of 17 digits and its label helps nobody).
pub const MIN_WIDTH: usize = 40;

/// No limit (`--wide`): every row on one line, as wide as it is.
pub const UNLIMITED: usize = usize::MAX;

static WIDTH: AtomicUsize = AtomicUsize::new(DEFAULT_WIDTH);

/// Sets the width text is laid out for (the binary does, from [`width_for`]).
pub fn set_width(columns: usize) {
    WIDTH.store(columns, Ordering::Relaxed);
}

/// The width text is laid out for: [`DEFAULT_WIDTH`] unless set.
pub fn width() -> usize {
    WIDTH.load(Ordering::Relaxed)
}

/// The width for `--wide` and the value of `COLUMNS`: unlimited with `--wide`; else `COLUMNS`
/// when it is a whole number (at least [`MIN_WIDTH`]); else [`DEFAULT_WIDTH`].
pub fn width_for(wide: bool, columns: Option<&str>) -> usize {
    if wide {
        return UNLIMITED;
    }
    columns
        .and_then(|c| c.trim().parse::<usize>().ok())
        .filter(|&c| c > 0)
        .map_or(DEFAULT_WIDTH, |c| c.max(MIN_WIDTH))
}

/// `text` wrapped at spaces to lines of at most `width` characters (a word longer than that
/// keeps its own line: numbers are never cut), each line after the first indented by `indent`.
/// Line breaks in `text` are kept (each line is wrapped on its own); a line that fits is kept as
/// it is.
pub fn wrap(text: &str, width: usize, indent: &str) -> String {
    let mut out = String::new();
    for paragraph in text.trim_end_matches('\n').split('\n') {
        wrap_line(paragraph, width, indent, &mut out);
    }
    out
}

fn wrap_line(text: &str, width: usize, indent: &str, out: &mut String) {
    // Words with the blanks before each, as typed: blanks inside a line are kept (they may align
    // it), those at a break dropped.
    let mut line = String::new();
    let mut len = 0;
    let mut rest = text.trim_end();
    let mut first = true;
    while !rest.is_empty() {
        let blanks = rest.len() - rest.trim_start_matches(' ').len();
        let (space, after) = rest.split_at(blanks);
        let end = after.find(' ').unwrap_or(after.len());
        let (word, after) = after.split_at(end);
        rest = after;
        let (space_len, word_len) = (space.chars().count(), word.chars().count());
        if !first && len + space_len + word_len > width {
            out.push_str(line.trim_end());
            out.push('\n');
            line = format!("{indent}{word}");
            len = indent.chars().count() + word_len;
        } else {
            line.push_str(space);
            line.push_str(word);
            len += space_len + word_len;
        }
        first = false;
    }
    out.push_str(line.trim_end());
    out.push('\n');
}

/// The widest line of `text`, in characters.
pub fn widest(text: &str) -> usize {
    text.lines().map(|l| l.chars().count()).max().unwrap_or(0)
}

/// Columns of the given widths, `gap` apart, folded into groups that each fit in `limit`: each
/// group is the `key` first columns (repeated, so every group names its rows) and as many of the
/// others, in order, as fit. A column too wide to fit even beside the key gets a group of its
/// own: it is never cut. One group (every column) when the whole fits.
pub fn fold(widths: &[usize], key: usize, gap: usize, limit: usize) -> Vec<Vec<usize>> {
    let key = key.min(widths.len());
    let span = |cols: &[usize]| -> usize {
        cols.iter().map(|&c| widths[c]).sum::<usize>() + gap * cols.len().saturating_sub(1)
    };
    let all: Vec<usize> = (0..widths.len()).collect();
    if span(&all) <= limit || widths.len() <= key {
        return vec![all];
    }
    let head: Vec<usize> = (0..key).collect();
    let mut groups = Vec::new();
    let mut group = head.clone();
    for c in key..widths.len() {
        group.push(c);
        if group.len() > key + 1 && span(&group) > limit {
            group.pop();
            groups.push(std::mem::replace(&mut group, head.clone()));
            group.push(c);
        }
    }
    groups.push(group);
    groups
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wraps_at_spaces_and_never_cuts_a_word() {
        let t = wrap("aaa bbb ccc ddddddddddd e", 8, "  ");
        assert_eq!(t, "aaa bbb\n  ccc\n  ddddddddddd\n  e\n");
    }

    #[test]
    fn wraps_each_line_and_keeps_its_indent() {
        let t = wrap("ab cd\n  ef gh ij", 8, "    ");
        assert_eq!(t, "ab cd\n  ef gh\n    ij\n");
    }

    #[test]
    fn width_from_the_flag_and_the_environment() {
        assert_eq!(width_for(false, None), 80);
        assert_eq!(width_for(false, Some("120")), 120);
        assert_eq!(width_for(false, Some("10")), MIN_WIDTH);
        assert_eq!(width_for(false, Some("wide")), 80);
        assert_eq!(width_for(false, Some("0")), 80);
        assert_eq!(width_for(true, Some("100")), UNLIMITED);
    }

    #[test]
    fn folds_columns_into_groups_that_fit() {
        // 5 + 2 + 10 + 2 + 10 = 29 > 20: the key (5) with each 10-wide column.
        assert_eq!(fold(&[5, 10, 10], 1, 2, 20), vec![vec![0, 1], vec![0, 2]]);
        assert_eq!(fold(&[5, 10, 10], 1, 2, 29), vec![vec![0, 1, 2]]);
        // A column wider than the limit keeps a group of its own.
        assert_eq!(
            fold(&[5, 30, 3, 3], 1, 2, 20),
            vec![vec![0, 1], vec![0, 2, 3]]
        );
    }
}
