//! Builds stickslip-fixtures' sources and tests for rapier3d 0.35.0-glamx0.2.
fn main() {
    println!("cargo::rustc-cfg=rapier_035");
}
