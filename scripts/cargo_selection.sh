# The one package and feature selection of every cargo command in scripts/ and .ci/run
# (sourced, not run): the whole workspace, with the bevy add-ons' optional parts on (contact
# gizmos, scenario files, the windowed examples).
#
# Why one selection: cargo unifies a dependency's features over the packages a command selects.
# `cargo test -p stickslip` and `cargo test --workspace` build glam, syn, bytemuck, smallvec,
# log, ... with different features, and everything above them (serde_derive, nalgebra, parry,
# rapier, bevy) again; the bevy add-ons' tests without `window` and their windowed examples
# with it built bevy twice. With one selection each dependency builds once for clippy (check
# mode) and once for the tests, examples and benches (the test profile); only the `parallel`
# pass rebuilds what rapier's multi-threaded feature changes (rapier, parry and stickslip's
# rapier crates). Every command passes `--workspace` (or `--workspace --exclude
# stickslip-fixtures-035`, which resolves the same features) and picks its targets with `--test`,
# `--example`, `--bin` or `--bench`.
#
# cargo's `resolver.feature-unification = "workspace"` would do this for `-p`, but it is
# unstable in cargo 1.95.

# Features of the default selection.
STICKSLIP_FEATURES="stickslip-bevy-rapier/window,stickslip-bevy-rapier/scenario,stickslip-bevy-rapier/debug,stickslip-avian/window,stickslip-avian/debug,stickslip-bevy-rapier2d/window,stickslip-bevy-rapier2d/debug,stickslip-avian2d/window,stickslip-avian2d/debug"
# The same with rapier's multi-threaded narrow phase and solver in the 3D and 2D adapters.
STICKSLIP_PARALLEL_FEATURES="$STICKSLIP_FEATURES,stickslip/parallel,stickslip-fixtures/parallel,stickslip-fixtures2d/parallel,stickslip-rapier2d/parallel"
export STICKSLIP_FEATURES STICKSLIP_PARALLEL_FEATURES

export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/stickslip-target}"
export CARGO_TERM_COLOR="${CARGO_TERM_COLOR:-never}"
