//! stickslip's test fixtures (unpublished): the reference scenes its tests, benches and
//! validation examples measure against analytic results (a box on an incline, on a belt,
//! dragged over a vibrating plate, the seed's Example 1, a vibratory feeder), the ordinary
//! scenes run beside plain rapier, and [`Conveyor`], a user's own hook to wrap.
//!
//! The package `stickslip-fixtures-035` compiles these same sources, and the same tests,
//! against rapier 0.35 (cfg `rapier_035`), and `stickslip-fixtures2d` for rapier2d (cfg
//! `dim2`); what has no 2D form yet is `#[cfg(not(dim2))]`.

// The figures' reference scenes: one file, which stickslip-figures compiles privately.
#[path = "../../stickslip-figures/src/scenes.rs"]
mod reference;

mod conveyor;
pub mod dim;
mod example1;
pub mod ordinary;
#[cfg(not(dim2))]
mod plate;
mod sled;

pub use conveyor::Conveyor;
pub use example1::example1;
#[cfg(not(dim2))]
pub use plate::{PlateMeasurement, VibratingPlate};
pub use reference::*;
pub use sled::Sled;

/// The contact manifolds of `world` with solver contacts (touching, not only near): the
/// contacts stickslip keeps a friction state for.
pub fn touching_manifolds(world: &stickslip_rapier::rapier::prelude::PhysicsWorld) -> usize {
    world
        .narrow_phase
        .contact_pairs()
        .flat_map(|p| p.solver_manifolds())
        .filter(|m| !m.data.solver_contacts.is_empty())
        .count()
}
