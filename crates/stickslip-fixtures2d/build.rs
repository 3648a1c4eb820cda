//! Builds stickslip-fixtures' sources and tests for rapier2d 0.36.1 (cfg `dim2`).
fn main() {
    println!("cargo::rustc-cfg=dim2");
}
