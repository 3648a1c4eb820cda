#!/usr/bin/env bash
# The bevy examples in a real window under Xvfb (software Vulkan). bevy_rapier apps with
# stickslip (crate stickslip-bevy-rapier): `vibrating_conveyor` renders FRAMES frames and saves the
# window to OUT; `view` opens scenarios/incline.toml the same way (saved beside OUT as
# *_view.png); `bevy_elliptical_drive` likewise (*_drive.png). The avian app (crate stickslip-avian):
# `avian_conveyor` after 120 frames (4 s: its vibrating trough's parts are past their start-up
# transient), saved as *_avian.png. The 2D app (crate stickslip-bevy-rapier2d): `incline_laws_2d`
# after 90 frames, saved as *_incline_2d.png. Each picture is checked not to be blank.
#   bash scripts/bevy_screenshot.sh [OUT] [FRAMES]
# Installs what it needs from Debian's packages (xvfb, Mesa's Vulkan driver) when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
# One package and feature selection for every cargo command (each dependency builds once).
source scripts/cargo_selection.sh
OUT="${1:-$CARGO_TARGET_DIR/vibrating_conveyor.png}"
FRAMES="${2:-60}"

if ! command -v xvfb-run >/dev/null || [ ! -e /usr/share/vulkan/icd.d/lvp_icd.x86_64.json ]; then
    apt-get update -qq
    apt-get install -y -qq xvfb xauth mesa-vulkan-drivers libvulkan1 libx11-6 libxcursor1 \
        libxrandr2 libxi6 libxkbcommon-x11-0 >/dev/null
fi

# In the test profile and the selection of scripts/test.sh, which has built them already.
cargo build --workspace --profile test --features "$STICKSLIP_FEATURES" \
    --example vibrating_conveyor --example view --example bevy_elliptical_drive \
    --example avian_conveyor --example incline_laws_2d
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
chmod 700 "$XDG_RUNTIME_DIR"
VIEW_OUT="${OUT%.png}_view.png"
RAPIER_OUT="${OUT%.png}_drive.png"
AVIAN_OUT="${OUT%.png}_avian.png"
INCLINE_2D_OUT="${OUT%.png}_incline_2d.png"
rm -f "$OUT" "$VIEW_OUT" "$RAPIER_OUT" "$AVIAN_OUT" "$INCLINE_2D_OUT"
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" \
    "$CARGO_TARGET_DIR/debug/examples/vibrating_conveyor" --screenshot "$OUT" --frames "$FRAMES"
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" \
    "$CARGO_TARGET_DIR/debug/examples/view" scenarios/incline.toml \
    --screenshot "$VIEW_OUT" --frames "$FRAMES"
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" \
    "$CARGO_TARGET_DIR/debug/examples/bevy_elliptical_drive" --screenshot "$RAPIER_OUT" \
    --frames "$FRAMES"
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" \
    "$CARGO_TARGET_DIR/debug/examples/avian_conveyor" --screenshot "$AVIAN_OUT" --frames 120
# The 2D one (bevy_rapier2d): three friction laws on an incline, side view.
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" \
    "$CARGO_TARGET_DIR/debug/examples/incline_laws_2d" --screenshot "$INCLINE_2D_OUT" --frames 90

# Not blank: a PNG whose pixels vary (decoded with the standard library only).
for png in "$OUT" "$VIEW_OUT" "$RAPIER_OUT" "$AVIAN_OUT" "$INCLINE_2D_OUT"; do
python3 - "$png" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
pos, idat, width, height = 8, b"", 0, 0
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b"IHDR":
        width, height = struct.unpack(">II", body[:8])
    elif kind == b"IDAT":
        idat += body
    pos += 12 + n
raw = zlib.decompress(idat)
row = len(raw) // height
# Unfiltered byte values of a sample of rows (filter type byte skipped): spread of colours.
values = [b for y in range(0, height, max(1, height // 64)) for b in raw[y * row + 1:(y + 1) * row:97]]
distinct = len(set(values))
print(f"{sys.argv[1]}: {width}x{height}, {distinct} distinct sampled byte values")
assert width >= 640 and height >= 360, "window too small"
assert distinct > 16, "the screenshot looks blank"
PY
done
