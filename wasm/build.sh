#!/usr/bin/env bash
# Builds the WebAssembly module of `collide view`'s page: the collide library without its command
# line (the crate in this folder), for wasm32-unknown-unknown, into wasm/collide_view.wasm, which
# is committed and embedded in the binary by src/view/page.rs (so building collide needs only the
# host toolchain). Run it after changing the library, then commit the module.
#
#   rustup target add wasm32-unknown-unknown    # once
#   wasm/build.sh [OUT.wasm]                    # default: wasm/collide_view.wasm
#
# The same sources and toolchain give the same bytes: the profile `wasm` (Cargo.toml) builds in one
# codegen unit and strips symbols, and the checkout's folder and CARGO_HOME are remapped, so no
# local path enters the module. The rustc that built the committed module is recorded in
# wasm/rustc-version, and the sources it was built from in wasm/sources.sha256: the SHA-256 of
# every file of this checkout that cargo's dep-info names for the module, and of the manifests,
# the lock file and this script. CI checks that they are unchanged (tests/suite/view.rs, in
# milliseconds); `cargo test --release -- --ignored the_committed_module_` rebuilds the module
# and compares the bytes (about a minute).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/wasm/collide_view.wasm}
cargo_home=${CARGO_HOME:-$HOME/.cargo}
export RUSTFLAGS="--remap-path-prefix=$root=/collide --remap-path-prefix=$cargo_home=/cargo"
# Nothing from the caller's environment may change the code: no incremental compilation (it
# splits code generation differently), no wrapper, no other flags or profile settings.
export CARGO_INCREMENTAL=0
# (RUSTC_BOOTSTRAP: build scripts that probe for a nightly compiler would switch features on.)
unset CARGO_ENCODED_RUSTFLAGS CARGO_BUILD_RUSTFLAGS CARGO_TARGET_DIR CARGO_BUILD_TARGET \
    RUSTC_WRAPPER RUSTC_WORKSPACE_WRAPPER CARGO_BUILD_RUSTC_WRAPPER RUSTC_BOOTSTRAP
for v in $(env | sed -n 's/^\(CARGO_PROFILE_[A-Z0-9_]*\)=.*/\1/p'); do unset "$v"; done
cargo build --locked --quiet --manifest-path "$root/Cargo.toml" -p collide-wasm \
    --target wasm32-unknown-unknown --profile wasm --target-dir "$root/target/wasm"
cp "$root/target/wasm/wasm32-unknown-unknown/wasm/collide_wasm.wasm" "$out"
if [ "$out" = "$root/wasm/collide_view.wasm" ]; then
    rustc --version >"$root/wasm/rustc-version"
    # The dep-info line is `OUT: SRC SRC ...`, absolute paths (none with a space: see RUSTFLAGS).
    dep="$root/target/wasm/wasm32-unknown-unknown/wasm/collide_wasm.d"
    cd "$root"
    {
        sed 's/^[^:]*: //' "$dep" | tr ' ' '\n' | sed -n "s|^$root/||p"
        printf '%s\n' Cargo.toml Cargo.lock wasm/Cargo.toml wasm/build.sh
    } | LC_ALL=C sort -u | while IFS= read -r f; do sha256sum -- "$f"; done >wasm/sources.sha256
fi
