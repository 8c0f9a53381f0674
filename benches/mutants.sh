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
#   MUTANTS_PER_FILE=2 benches/mutants.sh rigid   # 2 of each file's mutants, spread over its
#                                            # listing (results in target/mutants/rigid-each2)
#   MUTANTS_FILES="src/space/balls.rs src/space/typed.rs" MUTANTS_PER_FILE=2 \
#       benches/mutants.sh space             # those files instead of the area's (its tests)
#   MUTANTS_BASELINE=skip ...                # no unmutated run first (the tree passed before)
#
# rigid and impact skip the page's Chromium tests (view_rigid::browser_*: they run the committed
# module, not the mutant). view skips the tests of the committed WebAssembly module against its sources (the SHA-256 of
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
    [rigid]="src/rigid/*.rs src/rigid/slip/*.rs"
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
    [rigid]="rigid homework fin_known:: --skip browser_"
    [impact]="rigid --skip browser_"
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
# A unified diff that replaces each line named by the mutants read from stdin
# ("src/x.rs:LINE:COL: ...") by itself: the lines for --in-diff.
lines_diff() {
    cut -d: -f1,2 | sort -t: -k1,1 -k2,2n -u |
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
    out="$out${MUTANTS_PER_FILE:+-each$MUTANTS_PER_FILE}"
    mkdir -p "$out"
    # The files to mutate (globs, not expanded by the shell).
    read -ra globs <<< "${MUTANTS_FILES:-${FILES[$area]}}"
    files=()
    for glob in "${globs[@]}"; do files+=(--file "$glob"); done
    extra=(--baseline "${MUTANTS_BASELINE:-run}")
    # (MUTANTS_SHARD with MUTANTS_AGAIN names the earlier run's folder only: no shard of the few.)
    [ -n "${MUTANTS_SHARD:-}" ] && [ -z "${MUTANTS_AGAIN:-}" ] &&
        extra+=(--shard "$MUTANTS_SHARD" --sharding "${MUTANTS_SHARDING:-slice}")
    [ -n "${MUTANTS_ITERATE:-}" ] && extra+=(--iterate)
    # Again only what an earlier run (its mutants.out folder) missed or timed out on, by name.
    if [ -n "${MUTANTS_AGAIN:-}" ]; then
        [[ $MUTANTS_AGAIN = /* ]] || MUTANTS_AGAIN=$here/$MUTANTS_AGAIN
        out="$out-again"
        mkdir -p "$out"
        cat "$MUTANTS_AGAIN/missed.txt" "$MUTANTS_AGAIN/timeout.txt" > "$out/chosen.txt"
    elif [ -n "${MUTANTS_PER_FILE:-}" ]; then
        # Of each file's c mutants in the listing's order, the middle one of each of N equal
        # parts: numbers 1 + floor((2i + 1) c / 2N), i < N (N = 1: the middle one).
        cargo mutants --list "${files[@]}" | awk -F: -v n="$MUTANTS_PER_FILE" '
            !($1 in c) { order[++files] = $1 }
            { m[$1, ++c[$1]] = $0 }
            END { for (j = 1; j <= files; j++) { f = order[j]
                for (i = 0; i < n && i < c[f]; i++)
                    print m[f, 1 + int((2 * i + 1) * c[f] / (2 * n))] } }' \
            > "$out/chosen.txt"
    fi
    if [ -n "${MUTANTS_AGAIN:-}${MUTANTS_PER_FILE:-}" ]; then
        # Nothing chosen (no --re would mean every mutant).
        [ -s "$out/chosen.txt" ] || { echo "$area: no mutant chosen"; continue; }
        while IFS= read -r name; do
            extra+=(--re "^$(printf '%s' "$name" | sed 's/[][\\.*^$()+?{}|]/\\&/g')\$")
        done < "$out/chosen.txt"
        # cargo-mutants 27's --re does not filter its "delete field ... from struct ...
        # expression" mutants (a --list with a --re that matches nothing still lists them all):
        # a diff that touches only the named lines (each line replaced by itself), given as
        # --in-diff, leaves the named mutants and what else is on their lines.
        lines_diff < "$out/chosen.txt" > "$out/chosen.diff"
        extra+=(--in-diff "$out/chosen.diff")
    fi
    # shellcheck disable=SC2086
    cargo mutants --in-place --no-shuffle --profile "${MUTANTS_PROFILE:-mutation}" "${extra[@]}" \
        "${files[@]}" --output "$out" --timeout "${MUTANTS_TIMEOUT:-20}" \
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
