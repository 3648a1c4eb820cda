//! Vibration: a plate that vibrates elliptically at 20 kHz (normal and tangential, a quarter
//! period apart) drives a sled on it with no force pushing it (Popov's vibration-driven
//! transport). The source is averaged: rapier steps at 60 Hz, far below the vibration, and
//! the contact gets Popov's averaged friction and drive velocity.
//!
//! `cargo run --release -p stickslip-rapier --example vibration`
use stickslip_rapier::core::law::{EpParams, Law};
use stickslip_rapier::core::sliding_curve::Curve;
use stickslip_rapier::core::waveform::Waveform;
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{
    Amplitude, FrictionMaterial, StickSlip, VibrationComponent, VibrationDirection, VibrationMode,
    VibrationSource,
};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut world = PhysicsWorld::default();
    let plate = world.insert_collider(ColliderBuilder::cuboid(5.0, 0.1, 1.0), None);
    let (sled, part) = world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.2, 0.0)),
        ColliderBuilder::cuboid(0.1, 0.1, 0.1),
    );
    let law = Law::try_from(EpParams {
        stiffness: 1e4,
        static_coefficient: 0.5,
        peak_coefficient: 0.5,
        sliding: Curve::constant(0.5)?,
    })?;
    let mut friction = StickSlip::new(FrictionMaterial::new(law));
    friction.attach(&mut world.colliders, plate, None);
    friction.attach(&mut world.colliders, part, None);

    // The normal force oscillates by ±60 % of its mean and the plate along x by 0.75 μ0 F̄/k_t
    // (k_t = c F̄, the contact's tangential stiffness), a quarter period later: an ellipse.
    let normal = VibrationComponent::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(0.6),
        Waveform::Sine,
        0.0,
    )?;
    let along_x = VibrationComponent::new(
        VibrationDirection::Tangential {
            axis: [1.0, 0.0, 0.0],
        },
        Amplitude::Ratio(0.75),
        Waveform::Sine,
        0.25,
    )?;
    let source =
        VibrationSource::superimposed(&[normal, along_x], 20_000.0, VibrationMode::Averaged)?;
    friction.set_vibration(plate, source);

    for step in 1..=120 {
        friction.step(&mut world);
        if step % 20 == 0 {
            let v = world.bodies[sled].linvel().x;
            let t = step as f64 / 60.0;
            println!("t = {t:.2} s: the sled moves at {:+.1} mm/s", v * 1e3);
        }
    }
    Ok(())
}
