//! Builds stickslip-rapier's sources for rapier2d 0.35.0-glamx0.2 (2D, and the 0.35 API).
fn main() {
    println!("cargo::rustc-cfg=dim2");
    println!("cargo::rustc-cfg=rapier_035");
}
