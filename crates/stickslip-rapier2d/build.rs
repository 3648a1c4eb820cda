//! Builds stickslip-rapier's sources for rapier2d 0.36.1 (see its `tangent.rs`: a contact
//! has one tangent).
fn main() {
    println!("cargo::rustc-cfg=dim2");
}
