#!/usr/bin/env bash
# Packages every crate a user adds and checks each one from its .crate file alone:
# `bash scripts/package.sh` from the repository root (.ci/run runs it).
#
# `cargo package --no-verify` makes each package's .crate under $CARGO_TARGET_DIR/package-verify/
# package. Each is unpacked and checked there on its own (`cargo check`: its library and binaries with its
# default features; the same as `cargo package`'s own verification but without code
# generation), taking the other stickslip crates from the packages just made (a
# `[patch.crates-io]` to the unpacked ones) and everything else from crates.io. So a published
# crate that depends on an unpublished one, a path dependency without a version, a feature of a
# dependency it uses but does not enable, or a source file outside its package fails here.
# stickslip-rapier2d, stickslip-rapier-035, stickslip-rapier2d-035, stickslip-scenario-035,
# stickslip-bevy-rapier2d and stickslip-avian2d share their sources with a 3D or rapier 0.36
# crate through a `src` link, which `cargo package` follows and copies in (the way rapier
# publishes rapier2d and rapier3d from one source). Internal crates stay unpublished
# (`publish = false`) and out of this: stickslip-fixtures, stickslip-fixtures-035 and
# stickslip-fixtures2d (the reference scenes and the rapier tests, on rapier 0.36, 0.35 and
# rapier2d) and stickslip-benches; nothing published depends on them (a path-only
# dev-dependency is dropped from the package).
#
# Why check and not `cargo package`'s build: the build generated code for every dependency of
# every package once per feature set (bevy five times), 1135 s of CI's 3406 s from scratch; a
# package's missing file, dependency, version or feature fails the check the same way, and the
# workspace's own builds (tests, examples, windows) generate code from the same sources.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/cargo_selection.sh

target="$CARGO_TARGET_DIR/package-verify"
unpacked="$target/unpacked"
# The previous run's packages go (cargo would not overwrite a .crate of the same version
# otherwise; a stale unpacked crate would be checked instead of this one).
rm -rf "$target"/package "$unpacked"
mkdir -p "$unpacked"

# --allow-dirty: a local run packages the working tree as it is (CI packages a clean clone).
cargo package --workspace --exclude stickslip-fixtures --exclude stickslip-fixtures-035 \
    --exclude stickslip-fixtures2d --exclude stickslip-benches \
    --no-verify --allow-dirty --target-dir "$target"
ls -l "$target"/package/*.crate

# One cargo configuration for every check: the workspace's profiles (dependencies unoptimized;
# a package built on its own has no workspace) and the patch that takes the stickslip crates
# from the packages just made.
config="$unpacked/config.toml"
sed -n '/^\[profile\./,$p' Cargo.toml > "$config"
echo '[patch.crates-io]' >> "$config"
# Unpacked with the time of unpacking (`-m`): the archive's files carry a fixed old time, which
# cargo would take as older than the last run's check of the same path and skip it.
for crate in "$target"/package/*.crate; do
    dir=$(basename "$crate" .crate)
    tar -xzmf "$crate" -C "$unpacked"
    name=${dir%-*}
    echo "$name = { path = \"$unpacked/$dir\" }" >> "$config"
done

# Each package alone (its own lockfile and feature resolution), in one target dir kept between
# runs for the dependencies. An unused patch (a package that needs none of the others) warns.
log="$unpacked/check.log"
for dir in "$unpacked"/*/; do
    echo "=== checking $(basename "$dir") from its package"
    status=0
    (cd "$dir" && cargo check --config "$config" --target-dir "$target") >"$log" 2>&1 ||
        status=$?
    grep -v -e "^warning: profile package spec" -e "^warning: Patch \`" \
        -e "^Check that the patched package" -e "^Perhaps you misspelled" "$log" || true
    [ "$status" -eq 0 ] || { echo "$(basename "$dir") does not build from its package"; exit 1; }
done
