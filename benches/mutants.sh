#!/usr/bin/env bash
# Mutation testing (issue 31): cargo-mutants injects small bugs (a `<` for a `<=`, a `+` for a
# `-`, a function that returns a default) into the physics the suite is meant to guard, and
# reports every mutant that no test catches. Too slow for CI (about a thousand mutants, each a
# rebuild and a test run); run it by hand after changing these files or their tests.
#
#   cargo install cargo-mutants --locked     # once (27.x)
#   benches/mutants.sh                       # every area below, one after the other
#   benches/mutants.sh motion columns        # some of them
#   MUTANTS_SHARD=3/8 benches/mutants.sh contact   # one eighth of an area (to pause between)
#   MUTANTS_ITERATE=1 benches/mutants.sh motion    # only what the last run did not catch
#
# Each area mutates its files and runs only the tests that guard them (the lib's unit tests and
# the suite's modules, selected by name), so a mutant costs its rebuild and seconds of tests. The
# dev profile (opt-level 1) with incremental builds: a mutant rebuilds the lib and the suite in
# about 45 s on 2 loaded cores, where the release profile took 150 s (measured; the filtered
# tests run in about a second either way). MUTANTS_PROFILE=release to mutate what ships. One job at a time:
# the CI machine has 2 cores. The mutants are made in a copy of this tree, target included, kept
# between runs in $COLLIDE_MUTANTS_TREE (default /tmp/collide-mutants) and refreshed with
# `cp -a` (mtimes kept, so only what changed rebuilds; cargo-mutants' own copy rebuilds every
# dependency). Results: target/mutants/<area>/mutants.out/ (missed.txt, caught.txt, timeout.txt,
# unviable.txt, outcomes.json).
set -euo pipefail
cd "$(dirname "$0")/.."

# area -> files (cargo-mutants globs) and test-name filters.
declare -A FILES=(
    [contact]="src/contact/*.rs"
    [units]="src/values/units.rs"
    [motion]="src/track/motion.rs"
    [columns]="src/table/columns.rs"
)
declare -A TESTS=(
    [contact]="contact::"
    [units]="units homework:: problems:: cli:: properties::hostile properties::parsers"
    [motion]="track::"
    [columns]="tables:: table::"
)
areas=("$@")
[ ${#areas[@]} -eq 0 ] && areas=(motion columns units contact)

export CARGO_INCREMENTAL=1
here=$(pwd)
tree=${COLLIDE_MUTANTS_TREE:-/tmp/collide-mutants}
mkdir -p "$tree"
[ -d "$tree/target" ] || { [ -d target ] && cp -a target "$tree/"; }
for part in Cargo.toml Cargo.lock README.md src tests benches scenarios examples docs wasm; do
    rm -rf "${tree:?}/$part"
    cp -a "$part" "$tree/"
done
cd "$tree"
# A run stopped half-way leaves a mutant's build behind, newer than the restored source: make
# the sources newer so that collide is rebuilt from them.
find src tests -name '*.rs' -exec touch {} +
for area in "${areas[@]}"; do
    [ -n "${FILES[$area]:-}" ] || { echo "unknown area '$area': expected ${!FILES[*]}" >&2; exit 2; }
    out="$here/target/mutants/$area${MUTANTS_SHARD:+-${MUTANTS_SHARD%/*}}"
    mkdir -p "$out"
    extra=()
    [ -n "${MUTANTS_SHARD:-}" ] && extra+=(--shard "$MUTANTS_SHARD")
    [ -n "${MUTANTS_ITERATE:-}" ] && extra+=(--iterate)
    # shellcheck disable=SC2086
    cargo mutants --in-place --no-shuffle --profile "${MUTANTS_PROFILE:-dev}" "${extra[@]}" \
        --file "${FILES[$area]}" --output "$out" --timeout 20 \
        --cargo-test-arg=--lib --cargo-test-arg=--test --cargo-test-arg=suite \
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
