//! Builds the 3D add-on's sources for 2D.
fn main() {
    println!("cargo::rustc-cfg=dim2");
}
