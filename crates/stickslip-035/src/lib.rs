//! The `stickslip` facade over rapier3d 0.35.0-glamx0.2 (the rapier bevy_rapier3d 0.36 pins):
//! [`core`] and [`rapier`] as in the workspace's `stickslip` crate, so that its rapier test
//! files run against that rapier unchanged (see this package's `Cargo.toml`).

pub use stickslip_core as core;
pub use stickslip_rapier_035 as rapier;
