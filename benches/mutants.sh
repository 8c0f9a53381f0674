#!/usr/bin/env bash
# Mutation testing (issue 31): cargo-mutants injects small bugs (a `<` for a `<=`, a `+` for a
# `-`, a function that returns a default) into the physics the suite is meant to guard, and
# reports every mutant that no test catches. Too slow for CI (about 1,250 mutants, 988 of them in
# contact/, each a rebuild and a test run); run it by hand after changing these files or their
# tests.
#
#   cargo install cargo-mutants --locked     # once (27.x)
#   benches/mutants.sh                       # every area below, one after the other
#   benches/mutants.sh motion columns        # some of them
#   benches/mutants.sh impact solve          # one file each: rigid/impact.rs, space/solve.rs
#                                            # (areas rigid and space: every file of the folder)
#   benches/mutants.sh view engine           # src/view/*.rs (tests view*), table/engine.rs
#   MUTANTS_SHARD=3/8 benches/mutants.sh contact   # one eighth of an area (to pause between)
#   MUTANTS_SHARD=0/12 MUTANTS_SHARDING=round-robin benches/mutants.sh contact
#                                            # every twelfth mutant: a sample of the whole area
#   MUTANTS_ITERATE=1 benches/mutants.sh motion    # only what the last run did not catch
#   MUTANTS_TIMEOUT=90 benches/mutants.sh space    # seconds a test run may take (default 20;
#                                            # the baseline too: space's took 20 s on loaded cores)
#   MUTANTS_AGAIN=target/mutants/contact-0/mutants.out MUTANTS_SHARD=0/16 benches/mutants.sh contact
#                                            # again what that run missed (after new tests)
#
# view skips the tests of the committed WebAssembly module against its sources (the SHA-256 of
# each, and the ignored rebuild): they fail on every mutant of the files the module is built
# from, whatever the mutant does.
# Each area mutates its files and builds and runs only the tests that guard them (the lib's unit
# tests and the suite's modules, selected by name; `--cargo-arg`, so that the build step does not
# compile the examples too), so a mutant costs its rebuild and seconds of tests. The
# `mutation` profile (dev's opt-level 1 without debug info) with incremental builds: a contact
# mutant rebuilds the lib, its unit tests and the suite in about 7 s on 2 idle cores (9.7 s with
# debug info, 45 s on loaded cores, 150 s in release; measured), and its tests take 5.5 s.
# MUTANTS_PROFILE=release to mutate what ships. One job at a time: the CI machine has 2 cores.
# The mutants are made in a copy of this tree, target included, kept between runs in
# $COLLIDE_MUTANTS_TREE (default /tmp/collide-mutants) and refreshed with `cp -a` (mtimes kept,
# so only what changed rebuilds; cargo-mutants' own copy rebuilds every dependency). Results: target/mutants/<area>/mutants.out/ (missed.txt, caught.txt, timeout.txt,
# unviable.txt, outcomes.json).
set -euo pipefail
cd "$(dirname "$0")/.."

# area -> files (cargo-mutants globs) and test-name filters.
declare -A FILES=(
    [contact]="src/contact/*.rs"
    [units]="src/values/units.rs"
    [motion]="src/track/motion.rs"
    [columns]="src/table/columns.rs"
    [rigid]="src/rigid/*.rs"
    [impact]="src/rigid/impact.rs"
    [space]="src/space/*.rs"
    [solve]="src/space/solve.rs"
    [view]="src/view/*.rs"
    [engine]="src/table/engine.rs"
)
declare -A TESTS=(
    [contact]="contact:: contact_methods:: contact_outputs:: contact_refusals::"
    [units]="units homework:: problems:: cli:: properties::hostile properties::parsers --skip view_"
    [motion]="track::"
    [columns]="tables:: table::"
    [rigid]="rigid homework"
    [impact]="rigid"
    [space]="space:: plane frames:: metamorphic:: one_answer:: knowns::"
    [solve]="space:: plane knowns:: asked::"
    [view]="view --skip browser --skip view_node --skip the_committed_module_"
    [engine]="tables:: table:: sweeps:: parquet mutants_engine::"
)
areas=("$@")
[ ${#areas[@]} -eq 0 ] && areas=(motion columns units contact)

export CARGO_INCREMENTAL=1
here=$(pwd)
tree=${COLLIDE_MUTANTS_TREE:-/tmp/collide-mutants}
mkdir -p "$tree"
[ -d "$tree/target" ] || { [ -d target ] && cp -a target "$tree/"; }
# (every workspace member and build.rs: cargo metadata reads them all)
for part in Cargo.toml Cargo.lock README.md build.rs src tests benches scenarios examples docs wasm python; do
    rm -rf "${tree:?}/$part"
    cp -a "$part" "$tree/"
done
cd "$tree"
# A run stopped half-way leaves a mutant's build behind, newer than the restored source: make
# the sources newer so that collide is rebuilt from them.
find src tests -name '*.rs' -exec touch {} +
# A unified diff that replaces each line named by the mutants of missed.txt and timeout.txt
# in folder $1 ("src/x.rs:LINE:COL: ...") by itself: the lines for --in-diff.
lines_diff() {
    cat "$1/missed.txt" "$1/timeout.txt" | cut -d: -f1,2 | sort -t: -k1,1 -k2,2n -u |
        while IFS=: read -r file line; do
            [ "$file" = "${last:-}" ] || printf -- '--- a/%s\n+++ b/%s\n' "$file" "$file"
            last=$file
            text=$(sed -n "${line}p" "$file")
            printf -- '@@ -%s,1 +%s,1 @@\n-%s\n+%s\n' "$line" "$line" "$text" "$text"
        done
}
for area in "${areas[@]}"; do
    [ -n "${FILES[$area]:-}" ] || { echo "unknown area '$area': expected ${!FILES[*]}" >&2; exit 2; }
    out="$here/target/mutants/$area${MUTANTS_SHARD:+-${MUTANTS_SHARD%/*}}"
    mkdir -p "$out"
    extra=()
    # (MUTANTS_SHARD with MUTANTS_AGAIN names the earlier run's folder only: no shard of the few.)
    [ -n "${MUTANTS_SHARD:-}" ] && [ -z "${MUTANTS_AGAIN:-}" ] &&
        extra+=(--shard "$MUTANTS_SHARD" --sharding "${MUTANTS_SHARDING:-slice}")
    [ -n "${MUTANTS_ITERATE:-}" ] && extra+=(--iterate)
    # Again only what an earlier run (its mutants.out folder) missed or timed out on, by name.
    if [ -n "${MUTANTS_AGAIN:-}" ]; then
        [[ $MUTANTS_AGAIN = /* ]] || MUTANTS_AGAIN=$here/$MUTANTS_AGAIN
        out="$out-again"
        mkdir -p "$out"
        while IFS= read -r name; do
            extra+=(--re "^$(printf '%s' "$name" | sed 's/[][\\.*^$()+?{}|]/\\&/g')\$")
        done < <(cat "$MUTANTS_AGAIN/missed.txt" "$MUTANTS_AGAIN/timeout.txt")
        # Nothing to do again (no --re would mean every mutant).
        [ ${#extra[@]} -gt 0 ] || { echo "$area: nothing missed in $MUTANTS_AGAIN"; continue; }
        # cargo-mutants 27's --re does not filter its "delete field ... from struct ...
        # expression" mutants (a --list with a --re that matches nothing still lists them all):
        # a diff that touches only the named lines (each line replaced by itself), given as
        # --in-diff, leaves the named mutants and what else is on their lines.
        lines_diff "$MUTANTS_AGAIN" > "$out/again.diff"
        extra+=(--in-diff "$out/again.diff")
    fi
    # shellcheck disable=SC2086
    cargo mutants --in-place --no-shuffle --profile "${MUTANTS_PROFILE:-mutation}" "${extra[@]}" \
        --file "${FILES[$area]}" --output "$out" --timeout "${MUTANTS_TIMEOUT:-20}" \
        --cargo-arg=--lib --cargo-arg=--test --cargo-arg=suite \
        -- -- ${TESTS[$area]} || status=$?
    # cargo-mutants exits 2 when a mutant was missed and 3 on timeouts: results, not failures.
    case ${status:-0} in
    0 | 2 | 3) ;;
    *) echo "cargo mutants failed (exit $status) on $area" >&2; exit 1 ;;
    esac
    unset status
    out="$out/mutants.out"
    printf '%-8s caught %4s  missed %4s  timeout %4s  unviable %4s\n' "$area" \
        "$(wc -l < "$out/caught.txt")" "$(wc -l < "$out/missed.txt")" \
        "$(wc -l < "$out/timeout.txt")" "$(wc -l < "$out/unviable.txt")"
done
