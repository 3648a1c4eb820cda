# stickslip-bevy in CI: what `.ci/run` should run (after `bash scripts/test.sh`, which already
# runs the crate's headless tests as part of the workspace). `.ci/run` now calls
# scripts/bevy_screenshot.sh, which covers the Xvfb part with a weaker blank check (raw
# filtered bytes); this is the full set and can replace that line. Assumes the script's
# `set -euo pipefail`, the repository root as working directory and CARGO_TARGET_DIR exported.
#
# Cost: the window feature set compiles bevy's renderer, a second bevy build beside the
# headless one (see docs/bevy/README-notes.md for measured times); the run itself renders
# 120 frames on the CPU (llvmpipe) in well under a minute.

# The debug gizmos (feature `debug`, headless) and lints of the windowed example.
cargo test -p stickslip-bevy --features debug --test debug_gizmos
cargo clippy -p stickslip-bevy --all-targets --features window -- -D warnings

# A real window without a display: Xvfb and Mesa's software Vulkan driver (lavapipe), and the
# X11 client libraries winit opens. Installed only when missing.
if ! command -v xvfb-run >/dev/null || ! ls /usr/share/vulkan/icd.d/lvp_icd.*.json >/dev/null 2>&1; then
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends xvfb xauth mesa-vulkan-drivers libvulkan1 \
        libx11-6 libxcursor1 libxrandr2 libxi6 libxkbcommon-x11-0 >/dev/null
fi

# Build the example, render 120 frames (1/30 s of simulated time each: 4 s), save the window,
# exit; then check that the picture is not blank (standard-library Python, no extra tools).
cargo build -p stickslip-bevy --features window --example vibrating_conveyor
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
chmod 700 "$XDG_RUNTIME_DIR"
shot="$CARGO_TARGET_DIR/vibrating_conveyor.png"
rm -f "$shot"
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" \
    "$CARGO_TARGET_DIR/debug/examples/vibrating_conveyor" --screenshot "$shot" --frames 120
python3 docs/bevy/check_screenshot.py "$shot" 1280 720
