#!/usr/bin/env bash
# Packages every crate a user adds and builds each one from its .crate file alone:
# `bash scripts/package.sh` from the repository root (.ci/run runs it).
#
# `cargo package` makes each package's .crate under $CARGO_TARGET_DIR/package-verify/package,
# unpacks it there and builds it, taking the other stickslip crates from the packages it has
# just made (a local registry) and everything else from crates.io. So a published crate that
# depends on an unpublished one, a path dependency without a version, or a source file outside
# its package fails here. stickslip-rapier2d, stickslip-rapier-035 and stickslip-scenario-035
# share their sources with stickslip-rapier and stickslip-scenario through a `src` link, which
# `cargo package` follows and copies in (the way rapier publishes rapier2d and rapier3d from
# one source). Internal crates stay unpublished (`publish = false`) and out of this:
# stickslip-fixtures, stickslip-fixtures-035 and stickslip-fixtures2d (the reference scenes and
# the rapier tests, on rapier 0.36, 0.35 and rapier2d) and stickslip-benches; nothing published depends on them (a path-only
# dev-dependency is dropped from the package).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/cargo_selection.sh

# The workspace's profiles for the verification builds too (dependencies unoptimized and
# without debug info, the physics crates at opt-level 2): a package built on its own has no
# workspace and would otherwise build every dependency once more with full debug info.
profiles=$(mktemp --suffix .toml)
trap 'rm -f "$profiles"' EXIT
sed -n '/^\[profile\./,$p' Cargo.toml > "$profiles"

# The packages build in a target dir of their own beside the workspace's, kept between runs
# for their dependencies. cargo takes a crate from a registry to be immutable: it never
# unpacks a name and version again that its registry cache (a directory named for the local
# registry under $CARGO_HOME/registry/src) already has, and never rebuilds one whose artifacts
# it has. Both would make a second run verify the first run's sources, so both go.
target="$CARGO_TARGET_DIR/package-verify"
cargo_home="${CARGO_HOME:-$HOME/.cargo}"
for d in "$cargo_home"/registry/src/-*/; do
    rm -rf "$d"stickslip*
done
rm -rf "$target"/package "$target"/debug/.fingerprint/stickslip* "$target"/debug/build/stickslip* \
    "$target"/debug/deps/*stickslip*

# --allow-dirty: a local run packages the working tree as it is (CI packages a clean clone).
# (The profiles name dependencies of every crate; each package warns about the others'.)
cargo package --workspace --exclude stickslip-fixtures --exclude stickslip-fixtures-035 --exclude stickslip-fixtures2d \
    --exclude stickslip-benches \
    --allow-dirty --config "$profiles" --target-dir "$target" 2>&1 |
    grep -v "^warning: profile package spec"
ls -l "$target"/package/*.crate
