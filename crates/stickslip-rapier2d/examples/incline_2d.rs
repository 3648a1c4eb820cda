//! A side view of three ramps at tan θ = 0.45, streamed to rerun: parts coloured by friction
//! regime (green sticking, orange stick-slip, red sliding; grey: plain rapier2d).
//!
//! - Top lane: plain rapier2d, Coulomb μ = 0.4. Without static friction above kinetic the
//!   part slides off at once (a = g (sin θ − 0.4 cos θ)).
//! - Middle lane: stickslip's elasto-plastic law, μ_s = 0.5 (break-away), μ_k = 0.4. The part
//!   put down at rest sticks: 0.45 is below its static coefficient.
//! - Bottom lane: the same law; the part is kicked at t = 2 s. It breaks away and, since
//!   0.45 is above its kinetic coefficient, keeps sliding: static above kinetic friction.
//!
//! ```text
//! cargo run --release -p stickslip-rapier2d --example incline_2d              # incline_2d.rrd
//! cargo run --release -p stickslip-rapier2d --example incline_2d -- --connect # live viewer
//! ```

use clap::Parser;
use std::path::PathBuf;
use stickslip_rapier2d::core::law::{Law, Regime};
use stickslip_rapier2d::core::sliding_curve::Curve;
use stickslip_rapier2d::rapier::prelude::*;
use stickslip_rapier2d::{FrictionMaterial, ReadBack, StickSlip};
use stickslip_rerun::Sink;

#[derive(Parser)]
#[command(about = "Three parts on 2D ramps, plain rapier2d beside stickslip, in rerun")]
struct Args {
    /// Write the recording to this .rrd file (the default, as incline_2d.rrd).
    #[arg(long, conflicts_with = "connect")]
    save: Option<PathBuf>,
    /// Stream to a rerun viewer instead: the local one, or HOST:PORT.
    #[arg(long, num_args = 0..=1, default_missing_value = "")]
    connect: Option<String>,
    /// Simulated seconds.
    #[arg(long, default_value_t = 6.0)]
    seconds: f64,
}

const TAN: f32 = 0.45;
const HALF: f32 = 0.15;
const RAMP_HALF: f32 = 4.0;
const GREY: [u8; 3] = [150, 150, 150];

/// One lane: a ramp, a part on it, and whether stickslip runs it.
struct Lane {
    name: &'static str,
    /// Its entity path segment.
    path: &'static str,
    ramp: ColliderHandle,
    body: RigidBodyHandle,
    part: ColliderHandle,
    start: Vector,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = Args::parse();
    let sink = match args.connect {
        Some(addr) => Sink::Grpc((!addr.is_empty()).then_some(addr)),
        None => Sink::File(args.save.unwrap_or_else(|| "incline_2d.rrd".into())),
    };
    let (rec, _) = stickslip_rerun::open("stickslip_incline_2d", &sink)?;

    let theta = TAN.atan();
    let down = Vector::new(theta.cos(), -theta.sin());
    let normal = Vector::new(theta.sin(), theta.cos());
    let mut world = PhysicsWorld::default();
    let law = Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(0.4)?)?;
    let mut friction =
        StickSlip::new(FrictionMaterial::new(law)).with_read_back(ReadBack::Contacts);
    let mut lanes = Vec::new();
    for (i, (name, path)) in [
        ("plain rapier2d", "plain"),
        ("stickslip EP", "ep"),
        ("stickslip EP, kicked", "ep_kicked"),
    ]
    .into_iter()
    .enumerate()
    {
        let centre = Vector::new(0.0, -1.5 * i as f32);
        let ramp = world.insert_collider(
            ColliderBuilder::cuboid(RAMP_HALF, 0.05)
                .translation(centre)
                .rotation(-theta)
                .friction(0.4),
            None,
        );
        // Put down at rest on the ramp's upper third, its faces flush with the surface.
        let start = centre - down * (RAMP_HALF * 0.6) + normal * (0.05 + HALF);
        let (body, part) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(start)
                .rotation(-theta)
                .can_sleep(false),
            ColliderBuilder::cuboid(HALF, HALF)
                .density(1000.0)
                .friction(0.4),
        );
        if i > 0 {
            friction.attach(&mut world.colliders, ramp, None);
            friction.attach(&mut world.colliders, part, None);
        }
        lanes.push(Lane {
            name,
            path,
            ramp,
            body,
            part,
            start,
        });
    }

    let steps = (args.seconds * 60.0).round() as usize;
    for step in 0..steps {
        let t = step as f64 / 60.0;
        if step == 120 {
            // The kick: 0.5 m/s down the ramp.
            let b = &mut world.bodies[lanes[2].body];
            b.set_linvel(down * 0.5, true);
        }
        friction.step(&mut world);
        rec.set_duration_secs("sim_time", t + 1.0 / 60.0);
        let reports = friction.reports()?;
        for lane in &lanes {
            let regime = reports
                .iter()
                .find(|r| r.collider1 == lane.part || r.collider2 == lane.part)
                .map(|r| r.regime);
            let color = regime.map_or(GREY, Regime::srgb);
            let body = &world.bodies[lane.body];
            let label = format!("{}: {}", lane.name, regime.map_or("Coulomb", |r| r.name()));
            rec.log(
                format!("world/{}/part", lane.path),
                &rerun::LineStrips2D::new([outline(body.position(), HALF, HALF)])
                    .with_colors([rerun::Color::from_rgb(color[0], color[1], color[2])])
                    .with_labels([label]),
            )?;
            let moved = (body.translation() - lane.start).dot(down);
            rec.log(
                format!("series/moved_down_the_ramp/{}", lane.path),
                &rerun::Scalars::single(moved as f64),
            )?;
            if step == 0 {
                let ramp = world.colliders[lane.ramp].position();
                rec.log_static(
                    format!("world/{}/ramp", lane.path),
                    &rerun::LineStrips2D::new([outline(ramp, RAMP_HALF, 0.05)])
                        .with_colors([rerun::Color::from_rgb(90, 90, 90)]),
                )?;
            }
        }
    }
    for lane in &lanes {
        let moved = (world.bodies[lane.body].translation() - lane.start).dot(down);
        println!("{:>22}: moved {moved:8.4} m down the ramp", lane.name);
    }
    Ok(())
}

/// The closed outline of a box of half-extents (hx, hy) at `pose`, y up as in rerun's 2D
/// view once its y axis is flipped (rerun draws 2D with y down: the points are mirrored).
fn outline(pose: &Pose, hx: f32, hy: f32) -> Vec<[f32; 2]> {
    [(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy), (-hx, -hy)]
        .into_iter()
        .map(|(x, y)| {
            let p = pose * Vector::new(x, y);
            [p.x, -p.y]
        })
        .collect()
}
