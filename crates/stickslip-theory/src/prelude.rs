//! What most users of the theory name: `use stickslip_theory::prelude::*;`.
pub use crate::block::{BeltSpring, Block, BlockRun, ForceProfile, Integrator, Tolerances};
pub use crate::feeder::VibratoryFeeder;
pub use crate::popov::{
    SpringModel, StaticFriction, mu_eff, mu_s_normal, mu_s_tangential, mu_s_transverse, psi,
};
