//! Rolling resistance on a ramp, logged to rerun: three lanes of a ball and a cylinder on a
//! slope of tan θ = 0.05 — without rolling resistance (plain rapier's rolling), with μ_r = 0.08
//! (above the slope: they hold) and with μ_r = 0.02 (below it: they roll, slower). The
//! recording shows the bodies, their contacts and the resisting torques
//! (`world/contacts/rolling`, and per pair `series/contacts/{pair}/rolling_torque`); the
//! example prints how far each roller went beside the closed form
//! ½ k g (sin θ − μ_r cos θ) t² (k = 5/7 for a ball, 2/3 for a cylinder).
//!
//! `cargo run --release -p stickslip-rerun --example rolling_ramp` writes `rolling_ramp.rrd`
//! (open it with `rerun rolling_ramp.rrd`); `-- --connect` streams to a running viewer
//! instead (`-- --connect HOST:PORT` for another address).
use stickslip_rapier::core::law::Law;
use stickslip_rapier::core::sliding_curve::Curve;
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, ReadBack, StickSlip};
use stickslip_rerun::{LogOptions, RerunLogger, Sink};

const TAN: f32 = 0.05;
const R: f32 = 0.1;
const SECONDS: f32 = 4.0;
const G: f32 = 9.81;

/// An elasto-plastic law with a sharp band at `mu` (break-away and sliding level).
fn sharp(mu: f64) -> Result<Law, Box<dyn std::error::Error>> {
    Ok(Law::elasto_plastic(1e4, mu, mu, Curve::constant(mu)?)?)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let sink = match std::env::args().skip_while(|a| a != "--connect").nth(1) {
        Some(addr) => Sink::Grpc(Some(addr)),
        None if std::env::args().any(|a| a == "--connect") => Sink::Grpc(None),
        None => Sink::File("rolling_ramp.rrd".into()),
    };
    let mut world = PhysicsWorld::default();
    let theta = TAN.atan();
    // The ramp: gravity tilted, so the floor (a half-space, on which a cylinder's line
    // contact keeps its end points) runs downhill along +x.
    world.gravity = Vector::new(theta.sin(), -theta.cos(), 0.0) * G;
    let floor = world.insert_collider(
        ColliderBuilder::new(SharedShape::halfspace(Vector::Y)),
        None,
    );
    let mut friction =
        StickSlip::new(FrictionMaterial::new(sharp(0.5)?)).with_read_back(ReadBack::Contacts);
    friction.attach(&mut world.colliders, floor, None);
    // (lane name, μ_r): none is plain rapier's rolling.
    let lanes = [
        ("plain", None),
        ("held", Some(0.08)),
        ("rolling", Some(0.02)),
    ];
    let (rec, _) = stickslip_rerun::open("rolling_ramp", &sink)?;
    let mut logger = RerunLogger::new(rec, LogOptions::default());
    let mut rollers = Vec::new();
    for (lane, (name, mu_r)) in lanes.into_iter().enumerate() {
        let z = lane as f32 * 0.6;
        let material = match mu_r {
            Some(mu_r) => FrictionMaterial::new(sharp(0.5)?)
                .with_rolling(sharp(mu_r)?)
                .with_spinning(sharp(mu_r)?),
            None => FrictionMaterial::new(sharp(0.5)?),
        };
        // A solid ball, and a cylinder of length 2R lying on its side (its axis along z).
        let shapes = [
            ("ball", ColliderBuilder::ball(R), 5.0 / 7.0),
            (
                "cylinder",
                ColliderBuilder::cylinder(R, R).rotation(Vector::new(
                    std::f32::consts::FRAC_PI_2,
                    0.0,
                    0.0,
                )),
                2.0 / 3.0,
            ),
        ];
        for (k, (shape, collider, roll)) in shapes.into_iter().enumerate() {
            let (body, c) = world.insert(
                RigidBodyBuilder::dynamic()
                    .translation(Vector::new(0.0, R, z + 0.3 * k as f32 - 0.15))
                    .can_sleep(false),
                collider.density(1000.0),
            );
            friction.attach(&mut world.colliders, c, Some(material.clone()));
            logger.set_body_name(body, format!("{name}_{shape}"));
            rollers.push((format!("{name} {shape}"), body, mu_r.unwrap_or(0.0), roll));
        }
    }
    // From rest, touching the floor.
    let dt = world.integration_parameters.dt;
    let start: Vec<f32> = rollers
        .iter()
        .map(|(_, b, _, _)| world.bodies[*b].translation().x)
        .collect();
    let steps = (SECONDS / dt).round() as u64;
    for step in 1..=steps {
        friction.step(&mut world);
        logger.log_step(step, &world, &friction)?;
    }
    logger.flush()?;
    let t = steps as f32 * dt;
    for ((name, body, mu_r, roll), x0) in rollers.iter().zip(start) {
        let moved = world.bodies[*body].translation().x - x0;
        let a = roll * G * (theta.sin() - *mu_r as f32 * theta.cos());
        let expected = 0.5 * a.max(0.0) * t * t;
        println!("{name:>16}: {moved:8.4} m in {t} s (closed form {expected:.4} m)");
    }
    match sink {
        Sink::File(path) => println!("wrote {}", path.display()),
        _ => println!("streamed to the viewer"),
    }
    Ok(())
}
