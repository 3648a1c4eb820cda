//! What a bevy_rapier app names: `use stickslip_bevy_rapier::prelude::*;`.
pub use crate::{
    ContactReport, RegimeChanged, RollingReport, StickSlipContacts, StickSlipFriction,
    StickSlipRapier, StickSlipRapierPlugin, StickSlipVibration, SurfaceVelocity,
};
// The core's prelude without `Curve`, which bevy's prelude names too (bevy_math's `Curve`):
// name it as `core::sliding_curve::Curve`.
pub use stickslip_core::prelude::{
    Amplitude, ElastoPlastic, EpParams, FrictionLaw, FrictionMaterial, Law, ParamError, Regime,
    StribeckDecay, VibrationComponent, VibrationDirection, VibrationMode, VibrationSource,
    Waveform,
};
