//! Log a rapier world with stickslip to rerun: bodies, contacts coloured by regime, friction
//! series. Writes `log_world.rrd` (open it with `rerun log_world.rrd`).
//!
//! `cargo run --release -p stickslip-rerun --example log_world`
use stickslip_rapier::core::law::{EpParams, Law};
use stickslip_rapier::core::sliding_curve::Curve;
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, ReadBack, StickSlip};
use stickslip_rerun::{RerunLogger, Sink};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // A box on a slope of tan θ = 0.6, above its break-away coefficient 0.5: it slides.
    let mut world = PhysicsWorld::default();
    let theta = 0.6f32.atan();
    world.gravity = Vector::new(theta.sin(), -theta.cos(), 0.0) * 9.81;
    let floor = world.insert_collider(ColliderBuilder::cuboid(50.0, 0.1, 2.0), None);
    let (block, part) = world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.3, 0.0)),
        ColliderBuilder::cuboid(0.2, 0.2, 0.2),
    );
    let law = Law::try_from(EpParams {
        stiffness: 1e4,
        static_coefficient: 0.5,
        peak_coefficient: 0.55,
        sliding: Curve::constant(0.4)?,
    })?;
    // The logger reads the contacts back from the modifier.
    let mut friction =
        StickSlip::new(FrictionMaterial::new(law)).with_read_back(ReadBack::Contacts);
    friction.attach(&mut world.colliders, floor, None);
    friction.attach(&mut world.colliders, part, None);

    let (rec, _) = stickslip_rerun::open("log_world", &Sink::File("log_world.rrd".into()))?;
    let mut logger = RerunLogger::new(rec, Default::default());
    logger.set_body_name(block, "block");
    for step in 1..=120 {
        friction.step(&mut world);
        logger.log_step(step, &world, &friction)?;
    }
    logger.flush()?;
    println!("wrote log_world.rrd");
    Ok(())
}
