//! What most users of the core name: `use stickslip_core::prelude::*;`.
pub use crate::FrictionMaterial;
pub use crate::ParamError;
pub use crate::contact::{
    Amplitude, VibrationComponent, VibrationDirection, VibrationMode, VibrationSource,
};
pub use crate::law::{Coulomb, ElastoPlastic, EpParams, FrictionLaw, Law, Physical, Regime};
pub use crate::sliding_curve::{Curve, StribeckDecay};
pub use crate::waveform::Waveform;
